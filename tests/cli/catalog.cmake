# The catalog end to end (docs/catalog.md): sessions of two units, one
# analysed INVALID, one re-analysed, a damaged file → catalog index lists one
# refusal and indexes the rest; a second index reopens only the refused file; units, unit
# and lot give what the sessions hold in text, JSON and CSV, a refused delay
# never with a number; a session or a missing catalog named as --db is
# refused and left untouched. With -DDSN_FILE, the same folder is pushed to a
# throwaway PostgreSQL server twice and its rows are not doubled. A batch
# re-analysis stores new results with their audit and updates the catalog.
#   -DCLI=path -DDIR=scratch folder [-DDSN_FILE=file holding a libpq URI without a database]
set(dir ${DIR}/catalog_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/sessions)
set(s ${dir}/sessions)

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
# Fails unless ${CLI} ARGN exits with `code` and says `needle` on stderr.
function(expect_fail code needle)
  run_expect(${code} o ${ARGN})
  expect_match("${o_err}" "${needle}" "'${ARGN}'")
endfunction()

run_expect(0 o run --preset quick --speed 0 --seed 1 --out ${s}/a1.fbs --imu-serial SN-A --imu-model FOG-3 --lot L7 --bench-id B1)
run_expect(0 o run --preset quick --speed 0 --seed 2 --out ${s}/a2.fbs --imu-serial SN-A --imu-model FOG-3 --lot L7 --bench-id B1)
run_expect(0 o run --preset quick --speed 0 --seed 3 --out ${s}/b1.fbs --imu-serial SN-B --imu-model FOG-3 --lot L7 --bench-id B1)
# B's result re-analysed with its gyro stated reversed: INVALID, shown.
run_expect(0 o analyze ${s}/b1.fbs --gyro-sign x=-1,y=-1,z=-1)
expect_match("${o}" "INVALID" "analyze with reversed signs")
file(WRITE ${s}/broken.fbs "not a session")

run_expect(0 o catalog index ${s} --json)
string(JSON found GET "${o}" files_found)
string(JSON indexed GET "${o}" indexed)
string(JSON refused GET "${o}" refused)
string(JSON results GET "${o}" results_stored)
if(NOT found EQUAL 4 OR NOT indexed EQUAL 3 OR NOT refused EQUAL 1 OR NOT results EQUAL 4)
  message(FATAL_ERROR "catalog index: expected 4 files, 3 indexed, 1 refused, 4 results:\n${o}")
endif()
string(JSON why GET "${o}" refusals 0 refusal)
expect_match("${why}" "not a fogbench session" "the refusal")
if(NOT EXISTS ${s}/fogbench-catalog.sqlite)
  message(FATAL_ERROR "catalog index did not make the folder's catalog")
endif()
run_expect(0 o catalog index ${s})
expect_match("${o}" "0 indexed \\(0 results\\), 3 unchanged since last indexed, 1 refused" "a second index (the refused file read again)")
# --csv on every subcommand: index's counts with each refusal, refused's list.
run_expect(0 o catalog index ${s} --csv)
expect_match("${o}" "^catalog,files_found,indexed,unchanged,refused,results_stored,shared_catalog,shared_answered,pushed,pending,path,refusal\n\"?SQLite catalog [^\n]*fogbench-catalog.sqlite\"?,4,0,3,1,0,,,,,[^\n]*broken.fbs,[^\n]*not a fogbench session[^\n]*\n$"
             "index --csv")
run_expect(0 o catalog refused --db ${s} --csv)
expect_match("${o}" "^path,refusal\n[^\n]*broken.fbs,[^\n]*not a fogbench session[^\n]*\n$" "refused --csv")

run_expect(0 o catalog units --db ${s})
expect_match("${o}" "SN-A +FOG-3 +L7 +B1 +2 +2 " "units: SN-A")
expect_match("${o}" "SN-B +FOG-3 +L7 +B1 +1 +2 .*INVALID" "units: SN-B")
run_expect(0 o catalog units --db ${s} --csv)
string(REGEX MATCHALL "\n" lines "${o}")
list(LENGTH lines n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "catalog units --csv: expected a header and 2 rows:\n${o}")
endif()

# B's history: the first result (PASS) superseded, the shown one INVALID
# without a number.
run_expect(0 o catalog unit SN-B --db ${s} --json)
string(JSON first_shown GET "${o}" history 0 shown)
string(JSON second_shown GET "${o}" history 1 shown)
string(JSON second_verdict GET "${o}" history 1 verdict)
string(JSON first_delay GET "${o}" history 0 test_points 0 imu_delay_ms)
string(JSON second_point GET "${o}" history 1 test_points 0)
if(first_shown OR NOT second_shown OR NOT second_verdict STREQUAL "invalid" OR NOT first_delay MATCHES "^0\\.5")
  message(FATAL_ERROR "catalog unit SN-B: expected PASS superseded then INVALID shown:\n${o}")
endif()
if(second_point MATCHES "imu_delay_ms" OR NOT second_point MATCHES "\"refusal\" *: *\"INVALID")
  message(FATAL_ERROR "catalog unit SN-B: a refused delay left with its number or without why:\n${second_point}")
endif()
run_expect(0 o catalog unit SN-B --db ${s})
expect_match("${o}" "superseded" "unit text")
expect_match("${o}" "refused \\(INVALID" "unit text")
# The audit trail: when (UTC), who, the tool and command, the constants hash,
# the software and the raw stream's SHA-256 (shortened; the JSON's whole).
run_expect(0 j catalog unit SN-B --db ${s} --json)
string(JSON input GET "${j}" history 1 audit input_sha256)
string(JSON when GET "${j}" history 1 result_created_utc)
string(JSON hash GET "${j}" history 1 constants_hash)
string(SUBSTRING "${input}" 0 12 input12)
expect_match("${o}" "audit trail, one line per result[^\n]*\n  session [^\n]* result 1: analysed [0-9T:-]+Z by [^\n]* with acquisition \\[fogbench-cli run [^\n]*\\] [|] constants [0-9a-f]+ [|] fogbench [0-9.]+[^|\n]* [|] input [0-9a-f]+\n"
             "unit text: the audit of the run's result")
expect_match("${o}" "\n  session [^\n]* result 2: analysed ${when} by [^\n]* with fogbench-cli analyze \\[fogbench-cli analyze [^\n]*--gyro-sign x=-1,y=-1,z=-1\\] [|] constants ${hash} [|] fogbench [^|\n]* [|] input ${input12}\n"
             "unit text: the audit of the re-analysis")
run_expect(0 o catalog unit SN-B --db ${s} --csv)
expect_match("${o}" "\n[^\n]*,invalid,,,\"?INVALID" "unit CSV: the refused point has empty delay cells")

run_expect(0 o catalog lot L7 --db ${s} --json)
string(JSON units GET "${o}" units)
string(JSON sessions GET "${o}" sessions)
string(JSON invalid GET "${o}" by_verdict invalid)
string(JSON pass GET "${o}" by_verdict pass)
string(JSON n GET "${o}" imu_delay 0 n)
string(JSON fpy GET "${o}" first_pass_yield)
if(NOT units EQUAL 2 OR NOT sessions EQUAL 3 OR NOT invalid EQUAL 1 OR NOT pass EQUAL 2 OR NOT n EQUAL 2
   OR NOT fpy EQUAL 0.5)
  message(FATAL_ERROR "catalog lot L7: expected 2 units, 3 sessions (2 PASS, 1 INVALID), 2 delays, FPY 0.5:\n${o}")
endif()

# A batch re-analysis with another read delay: stored as new results with
# their audit (who, the batch's command line), and the folder's catalog follows.
# (exit 1: broken.fbs is refused, and has its line)
execute_process(COMMAND ${CLI} batch ${s} --jsonl ${dir}/batch.jsonl --read-delay-ms 0.06 --operator "Li Wei"
                RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 1)
  message(FATAL_ERROR "batch: expected exit 1 (one file refused), got ${c}: ${e}\n${o}")
endif()
expect_match("${o}" "catalog: SQLite catalog .* updated: 3 sessions re-indexed" "batch's catalog update")
run_expect(0 o catalog unit SN-A --db ${s} --json)
string(JSON n LENGTH "${o}" history)
math(EXPR last "${n} - 1")
string(JSON who GET "${o}" history ${last} audit who)
string(JSON command GET "${o}" history ${last} audit command)
string(JSON read GET "${o}" history ${last} constants table_read_delay_ms)
string(JSON first_shown GET "${o}" history 0 shown)
if(NOT n EQUAL 4 OR NOT who STREQUAL "Li Wei" OR NOT command MATCHES "batch .*--read-delay-ms 0.06"
   OR NOT (read GREATER 0.05999999 AND read LESS 0.06000001) OR first_shown)
  message(FATAL_ERROR "catalog unit SN-A after the batch (${n}, ${who}, ${command}, ${read}, ${first_shown}): expected 4 results, the last by Li Wei with the batch's "
                      "command and read delay 0.06, the first superseded:\n${o}")
endif()

# Named by mistake: a session as the catalog, a catalog that is not there.
file(SHA256 ${s}/a1.fbs before)
expect_fail(2 "a fogbench session file, not a catalog" catalog units --db ${s}/a1.fbs)
file(SHA256 ${s}/a1.fbs after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "a session named as --db was changed")
endif()
expect_fail(2 "no catalog at" catalog units --db ${dir}/nowhere.sqlite)
if(EXISTS ${dir}/nowhere.sqlite)
  message(FATAL_ERROR "a query made a catalog file where none was")
endif()
expect_fail(1 "no result for IMU serial 'SN-Z'" catalog unit SN-Z --db ${s})

if(DSN_FILE)
  file(READ ${DSN_FILE} dsn)
  string(STRIP "${dsn}" dsn)
  set(pg "${dsn}&dbname=postgres")
  run_expect(0 o catalog push --from ${s} --db "${pg}")
  expect_match("${o}" "pushed 7 results" "first push")
  run_expect(0 o catalog push --from ${s} --db "${pg}")
  expect_match("${o}" "pushed 0 results.*7 pushed before and unchanged" "second push")
  run_expect(0 o catalog push --from ${s} --db "${pg}" --json)
  string(JSON pushed GET "${o}" pushed)
  string(JSON before GET "${o}" already_pushed)
  if(NOT pushed EQUAL 0 OR NOT before EQUAL 7)
    message(FATAL_ERROR "push --json: expected 0 pushed, 7 before:\n${o}")
  endif()
  run_expect(0 o catalog push --from ${s} --db "${pg}" --csv)
  expect_match("${o}" "^from,to,pushed,already_pushed\nSQLite catalog [^\n]*,PostgreSQL catalog postgres on [^\n]*,0,7\n$" "push --csv")
  run_expect(0 o catalog units --db "${pg}" --json)
  string(JSON units LENGTH "${o}")
  string(JSON sa GET "${o}" 0 results)
  if(NOT units EQUAL 2 OR NOT sa EQUAL 4)
    message(FATAL_ERROR "the shared catalog after two pushes: expected 2 units, SN-A with 4 results:\n${o}")
  endif()

  # A bench offline (docs/catalog.md, "A bench offline"): `index --db` a
  # server that does not answer indexes the folder's own catalog and keeps
  # its rows pending (exit 3); the next index, when the server answers,
  # sends them once; a batch offline leaves its rows pending for the next push.
  set(b ${dir}/bench)
  file(MAKE_DIRECTORY ${b})
  set(offline "postgresql://fogbench@127.0.0.1:1/none?connect_timeout=2")
  run_expect(0 o run --preset quick --speed 0 --seed 5 --out ${b}/p.fbs --imu-serial SN-P)
  run_expect(3 o catalog index ${b} --db ${offline})
  expect_match("${o}" "SQLite catalog [^\n]*bench/fogbench-catalog.sqlite\n1 session files: 1 indexed" "index offline: the bench's catalog")
  expect_match("${o}" "shared catalog: not updated: cannot reach the PostgreSQL catalog [^\n]*; 1 result pending" "index offline")
  run_expect(0 o catalog index ${b} --db "${pg}")
  expect_match("${o}" "1 unchanged since last indexed.*shared catalog: pushed 1 results to the PostgreSQL catalog [^\n]*none pending" "index back online")
  run_expect(0 o catalog index ${b} --db "${pg}" --json)
  string(JSON pushed GET "${o}" shared pushed)
  string(JSON before GET "${o}" shared already_pushed)
  string(JSON answered GET "${o}" shared answered)
  if(NOT pushed EQUAL 0 OR NOT before EQUAL 1 OR NOT answered)
    message(FATAL_ERROR "index again: expected nothing sent twice:\n${o}")
  endif()
  execute_process(COMMAND ${CLI} batch ${b} --jsonl ${dir}/bench.jsonl --read-delay-ms 0.07 --db ${offline}
                  RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL 3)
    message(FATAL_ERROR "batch with the shared catalog offline: expected exit 3, got ${c}: ${e}\n${o}")
  endif()
  expect_match("${o}" "catalog: SQLite catalog [^\n]*bench/fogbench-catalog.sqlite updated: 1 sessions re-indexed.*shared catalog: not updated: .*2 results pending"
               "batch offline")
  run_expect(0 o catalog push --from ${b} --db "${pg}")
  expect_match("${o}" "pushed 2 results" "push after the batch offline")
  run_expect(0 o catalog push --from ${b} --db "${pg}")
  expect_match("${o}" "pushed 0 results.*2 pushed before and unchanged" "push again")
  run_expect(0 o catalog unit SN-P --db "${pg}" --json)
  string(JSON n LENGTH "${o}" history)
  if(NOT n EQUAL 2)
    message(FATAL_ERROR "the shared catalog: SN-P has ${n} results, expected 2 (no duplicate):\n${o}")
  endif()
endif()
