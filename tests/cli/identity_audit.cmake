# The unit's identity and the audit trail end to end (docs/sessions.md,
# schema 6 and "The audit trail"):
#   run --lot --bench-id --out S.fbs -> sessions --json lists the lot and the
#   bench; two analyses with other constants, one naming its operator and one
#   not, store two more audit entries: who (operator / login), tool, command
#   line, constants, and the same input_sha256 = cmake's SHA256 of the raw
#   stream the run saved (--save-raw; computed outside fogbench); export
#   --csv carries lot and bench into metadata.json, import reads them back and
#   --lot wins over the file's. With -DHAVE_REPORT=ON, report prints the unit
#   and the three entries.
#   -DCLI=path -DDIR=scratch folder [-DHAVE_REPORT=ON]
set(dir ${DIR}/identity_audit_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(s ${dir}/unit.fbs)

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

function(expect_equal what got want)
  if(NOT "${got}" STREQUAL "${want}")
    message(FATAL_ERROR "${what}: '${got}', expected '${want}'")
  endif()
endfunction()

run_expect(0 o run --preset quick --seed 2 --out ${s} --save-raw ${dir}/unit.bin --operator "Li Wei" --imu-serial SN-8
       --lot "L-2026-11 A" --bench-id "bench-3")
# A lot without a session to put it in is refused, naming what to add.
execute_process(COMMAND ${CLI} run --preset quick --lot L1 RESULT_VARIABLE c ERROR_VARIABLE e OUTPUT_QUIET)
if(NOT c EQUAL 2 OR NOT e MATCHES "--lot, --bench-id and --notes describe a session: give --out")
  message(FATAL_ERROR "run --lot without --out: expected exit 2 naming --out, got ${c}: ${e}")
endif()

run_expect(0 listed sessions ${dir} --json)
string(JSON lot GET "${listed}" sessions 0 lot)
string(JSON bench GET "${listed}" sessions 0 bench_id)
expect_equal("sessions --json lot" "${lot}" "L-2026-11 A")
expect_equal("sessions --json bench_id" "${bench}" "bench-3")
run_expect(0 table sessions ${dir})
if(NOT table MATCHES "lot +bench" OR NOT table MATCHES "L-2026-11 A +bench-3")
  message(FATAL_ERROR "sessions does not show the lot and the bench:\n${table}")
endif()

run_expect(0 o analyze ${s} --board-delay-ms 0.31 --operator "Wang Fang")
run_expect(0 o analyze ${s} --board-delay-ms 0.22)
# An operator name beyond a session text's bound is refused, storing nothing.
string(REPEAT "a" 5000 long)
execute_process(COMMAND ${CLI} analyze ${s} --operator ${long} RESULT_VARIABLE c ERROR_VARIABLE e OUTPUT_QUIET)
if(NOT c EQUAL 2 OR NOT e MATCHES "--operator is 5000 bytes; at most 4096")
  message(FATAL_ERROR "analyze --operator of 5000 bytes: expected exit 2 with the bound, got ${c}: ${e}")
endif()
run_expect(0 o export ${s} --results-json ${dir}/results.json)
file(READ ${dir}/results.json results)
string(JSON n LENGTH "${results}" stored_results)
expect_equal("stored results" "${n}" "3")
file(SHA256 ${dir}/unit.bin raw_sha)
foreach(i 0 1 2)
  string(JSON settings${i} GET "${results}" stored_results ${i} settings)
  string(JSON sha GET "${settings${i}}" audit input_sha256)
  expect_equal("result ${i}: input_sha256 (the raw stream's, as cmake hashes it)" "${sha}" "${raw_sha}")
endforeach()
string(JSON who GET "${settings0}" audit who)
string(JSON tool GET "${settings0}" audit tool)
expect_equal("the run's who" "${who}" "Li Wei")
expect_equal("the run's tool" "${tool}" "acquisition")
string(JSON who GET "${settings1}" audit who)
string(JSON source GET "${settings1}" audit who_source)
string(JSON tool GET "${settings1}" audit tool)
string(JSON command GET "${settings1}" audit command)
string(JSON board GET "${settings1}" board_delay_ms)
expect_equal("the first analysis' who" "${who}" "Wang Fang")
expect_equal("the first analysis' who_source" "${source}" "operator")
expect_equal("the first analysis' tool" "${tool}" "fogbench-cli analyze")
expect_equal("the first analysis' command" "${command}"
             "fogbench-cli analyze ${s} --board-delay-ms 0.31 --operator 'Wang Fang'")
expect_equal("the first analysis' board delay" "${board}" "0.31")
string(JSON who GET "${settings2}" audit who)
string(JSON source GET "${settings2}" audit who_source)
string(JSON board GET "${settings2}" board_delay_ms)
expect_equal("the second analysis' who_source" "${source}" "login")
if(who STREQUAL "" OR who STREQUAL "Wang Fang")
  message(FATAL_ERROR "the second analysis names no operator: its who is the login name, not '${who}'")
endif()
expect_equal("the second analysis' board delay" "${board}" "0.22")

# Export -> import keeps the identity; --lot on the command line wins.
run_expect(0 o export ${s} --csv ${dir}/csv)
file(READ ${dir}/csv/metadata.json meta)
string(JSON lot GET "${meta}" lot)
string(JSON bench GET "${meta}" bench_id)
expect_equal("metadata.json lot" "${lot}" "L-2026-11 A")
expect_equal("metadata.json bench_id" "${bench}" "bench-3")
file(MAKE_DIRECTORY ${dir}/imported)
run_expect(0 o import ${dir}/csv --out ${dir}/imported/i.fbs --lot L-9)
run_expect(0 listed sessions ${dir}/imported --json)
string(JSON lot GET "${listed}" sessions 0 lot)
string(JSON bench GET "${listed}" sessions 0 bench_id)
expect_equal("imported lot (--lot wins)" "${lot}" "L-9")
expect_equal("imported bench_id (the file's)" "${bench}" "bench-3")

if(HAVE_REPORT)
  run_expect(0 o report ${s} --pdf ${dir}/unit.pdf)
  if(NOT o MATCHES "unit: IMU not recorded, serial SN-8, lot L-2026-11 A, bench bench-3, operator Li Wei")
    message(FATAL_ERROR "report does not print the unit:\n${o}")
  endif()
  string(SUBSTRING "${raw_sha}" 0 12 prefix)
  string(REGEX MATCHALL "\n  #[0-9][^\n]*" trail "${o}")
  list(LENGTH trail entries)
  expect_equal("report: audit trail entries" "${entries}" "3")
  list(GET trail 1 second)
  if(NOT second MATCHES "#2 .* by Wang Fang \\(operator\\) fogbench-cli analyze \\[.*--board-delay-ms 0.31.*board 0.310 .*input ${prefix} \\| (PASS|FAIL|INVALID)$")
    message(FATAL_ERROR "report's second audit line:\n${second}")
  endif()
endif()
