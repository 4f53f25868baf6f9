# fogbench-cli batch (issue 42, docs/sessions.md "Batch re-analysis"):
#   three good sessions (one in a subfolder), one damaged .fbs and one
#   non-session file -> one line per .fbs, the damaged one "refused" with the
#   reader's message; each good session gets exactly one new result with the
#   batch's constants; a rerun skips everything and stores nothing; a line
#   lost with a kill (stored, not listed, the line cut short) is discarded and
#   the file listed "already_stored", never stored twice; other constants with
#   the same OUT are refused and OUT is left as it was; so is a file that is
#   no batch output.
#   -DCLI=path -DDIR=scratch folder
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/batch_lines.cmake)
set(dir ${DIR}/batch_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/in/sub)
set(out ${dir}/out.jsonl)

run_expect(0 ignored run --preset quick --seed 1 --out ${dir}/in/a.fbs)
run_expect(0 ignored run --preset quick --seed 2 --out ${dir}/in/b.fbs)
run_expect(0 ignored run --preset quick --seed 3 --out ${dir}/in/sub/c.fbs)
# A session cut short after 4 KiB (its header intact, its pages gone) and a
# file that is no session at all, beside them.
execute_process(COMMAND sh -c "head -c 4096 \"$0\" > \"$1\"" ${dir}/in/a.fbs ${dir}/in/sub/damaged.fbs
                RESULT_VARIABLE c)
file(WRITE ${dir}/in/notes.txt "not a session\n")
# The reader's message for the damaged file, as `sessions` gives it.
run_expect(0 listing sessions ${dir}/in/sub --json)
string(JSON reader_error GET "${listing}" sessions 1 error)
if(reader_error STREQUAL "")
  message(FATAL_ERROR "sessions does not call damaged.fbs unreadable:\n${listing}")
endif()

# Lines of OUT: the header in `header`, the file lines in `lines` (a list of
# JSON texts), and `by_path_<name>` for each file's line.
function(read_out)
  batch_lines(${out} all)
  list(GET all 0 h)
  list(SUBLIST all 1 -1 rest)
  set(header "${h}" PARENT_SCOPE)
  set(lines "${rest}" PARENT_SCOPE)
  foreach(element ${rest})
    batch_line("${element}" l)
    string(JSON p GET "${l}" path)
    get_filename_component(name ${p} NAME_WE)
    if(DEFINED by_path_${name})
      message(FATAL_ERROR "two lines for ${p} in ${out}")
    endif()
    set(by_path_${name} "${l}")
    set(by_path_${name} "${l}" PARENT_SCOPE)
  endforeach()
endfunction()

# The number of results stored in each good session, and the newest's settings.
function(expect_results expected what)
  foreach(name a b sub/c)
    file(REMOVE ${dir}/results.json)
    run_expect(0 ignored export ${dir}/in/${name}.fbs --results-json ${dir}/results.json)
    file(READ ${dir}/results.json doc)
    string(JSON n LENGTH "${doc}" stored_results)
    if(NOT n EQUAL ${expected})
      message(FATAL_ERROR "${what}: ${name}.fbs has ${n} stored results, expected ${expected}")
    endif()
    math(EXPR last "${n} - 1")
    string(JSON by GET "${doc}" stored_results ${last} settings analysed_by)
    string(JSON read GET "${doc}" stored_results ${last} settings table_read_delay_ms)
    string(JSON limit GET "${doc}" stored_results ${last} settings imu_delay_limit_ms)
    if(NOT by STREQUAL "fogbench-cli batch ${batch_id}" OR NOT read EQUAL 0.07 OR NOT limit EQUAL 0.9)
      message(FATAL_ERROR "${what}: ${name}.fbs's newest result is not the batch's (${by}, read delay ${read}, "
                          "limit ${limit})")
    endif()
  endforeach()
endfunction()

# The first batch: exit 1 (one file refused), a line per .fbs.
run_expect(1 first batch ${dir}/in --jsonl ${out} --read-delay-ms 0.07 --limit-ms 0.9 --jobs 2)
read_out()
string(JSON batch_id GET "${header}" batch_id)
string(JSON header_read GET "${header}" settings constants read-delay-ms)
string(JSON header_limit GET "${header}" settings imu_delay_limit_ms)
if(NOT header_read EQUAL 0.07 OR NOT header_limit EQUAL 0.9 OR batch_id STREQUAL "")
  message(FATAL_ERROR "the header does not state the batch's settings:\n${header}")
endif()
list(LENGTH lines n)
if(NOT n EQUAL 4 OR DEFINED by_path_notes)
  message(FATAL_ERROR "expected one line for each of the 4 .fbs files and none for notes.txt, got ${n}:\n${lines}")
endif()
string(JSON status GET "${by_path_damaged}" status)
string(JSON error GET "${by_path_damaged}" error)
string(FIND "${error}" "${reader_error}" at)
if(NOT status STREQUAL "refused" OR at EQUAL -1)
  message(FATAL_ERROR "damaged.fbs is not refused with the reader's message (${reader_error}):\n${by_path_damaged}")
endif()
expect_match("${first}" "batch of 4 files into .*: 3 stored, 0 already stored, 1 refused, 0 skipped" "the summary")
expect_match("${first}" "verdicts of the results listed now: 3 PASS" "the summary's verdicts")
# Progress only on a terminal: nothing on a pipe.
if(NOT first_err MATCHES "^$")
  message(FATAL_ERROR "batch wrote on stderr through a pipe:\n${first_err}")
endif()
foreach(file a b sub/c)
  get_filename_component(name ${file} NAME)
  string(JSON status GET "${by_path_${name}}" status)
  string(JSON result GET "${by_path_${name}}" result)
  string(JSON verdict GET "${by_path_${name}}" verdict)
  string(JSON delay GET "${by_path_${name}}" points 0 imu_delay_ms)
  if(NOT status STREQUAL "stored" OR NOT result EQUAL 2 OR NOT verdict STREQUAL "pass")
    message(FATAL_ERROR "${name}.fbs: expected stored as result 2 with PASS:\n${by_path_${name}}")
  endif()
  # The batch's table read delay (0.07 for the session's 0.05: the table's
  # angle is 0.02 ms older than stamped) adds 0.02 ms to the IMU delay.
  run_expect(0 own analyze ${dir}/in/${file}.fbs --json --no-store)
  string(JSON own_delay GET "${own}" test_points 0 imu_delay_ms)
  execute_process(COMMAND /usr/bin/python3 -c "import sys; d=float(sys.argv[2])-float(sys.argv[1]); sys.exit(0 if abs(d-0.02)<1e-9 else 1)"
                  ${own_delay} ${delay} RESULT_VARIABLE far)
  if(NOT far EQUAL 0)
    message(FATAL_ERROR "${name}.fbs: the batch's IMU delay ${delay} is not the session's own ${own_delay} + 0.02")
  endif()
endforeach()
expect_results(2 "after the first batch")

# The same batch again: every file listed, skipped; nothing stored.
file(READ ${out} before)
run_expect(0 again batch ${dir}/in --jsonl ${out} --read-delay-ms 0.07 --limit-ms 0.9)
file(READ ${out} after)
expect_match("${again}" "0 stored, 0 already stored, 0 refused, 4 skipped" "the rerun's summary")
if(NOT before STREQUAL after)
  message(FATAL_ERROR "a rerun of a finished batch changed OUT")
endif()
expect_results(2 "after a rerun")

# A kill between storing b's result and finishing its line: OUT lacks b's
# line but ends in its first half. The rerun discards the half line and lists
# b as already stored, without storing it again.
set(kept "${header}\n")
foreach(name a c damaged)
  string(APPEND kept "${by_path_${name}}\n")
endforeach()
string(SUBSTRING "${by_path_b}" 0 20 half)
file(WRITE ${out} "${kept}${half}")
run_expect(0 resumed batch ${dir}/in --jsonl ${out} --read-delay-ms 0.07 --limit-ms 0.9)
expect_match("${resumed_err}" "ended in a line cut short \\(20 bytes" "the note on the discarded line")
expect_match("${resumed}" "0 stored, 1 already stored, 0 refused, 3 skipped" "the resumed summary")
unset(by_path_a)
unset(by_path_b)
unset(by_path_c)
unset(by_path_damaged)
read_out()
list(LENGTH lines n)
string(JSON status GET "${by_path_b}" status)
string(JSON verdict GET "${by_path_b}" verdict)
if(NOT n EQUAL 4 OR NOT status STREQUAL "already_stored" OR NOT verdict STREQUAL "pass")
  message(FATAL_ERROR "after the resume: expected 4 lines, b already stored (PASS):\n${lines}")
endif()
expect_results(2 "after the resume")

# Other constants with the same OUT: refused, OUT as it was, nothing stored.
file(READ ${out} before)
run_expect(2 other batch ${dir}/in --jsonl ${out} --read-delay-ms 0.08 --limit-ms 0.9)
expect_match("${other_err}" "holds a batch with other settings.*name another --jsonl or remove it" "the refusal")
file(READ ${out} after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "a refused batch changed OUT")
endif()
expect_results(2 "after a refused batch")
# A file that is no batch output is never written into.
file(WRITE ${dir}/mine.jsonl "{\"my\": 1}\n")
run_expect(2 foreign batch ${dir}/in --jsonl ${dir}/mine.jsonl)
expect_match("${foreign_err}" "is not the output of fogbench-cli batch" "the refusal of a foreign OUT")
file(READ ${dir}/mine.jsonl mine)
if(NOT mine STREQUAL "{\"my\": 1}\n")
  message(FATAL_ERROR "batch changed a file that is not its output")
endif()
run_expect(2 ignored batch ${dir}/in)
expect_match("${ignored_err}" "batch needs --jsonl OUT.jsonl" "the missing --jsonl")

# A run stopped early and a session being recorded, given as FILEs: the
# first is stored INCOMPLETE, its delays refused (never written bare); the
# second is refused, untouched, and the batch goes on.
file(MAKE_DIRECTORY ${dir}/live)
execute_process(
  COMMAND sh -c "\"$0\" run --axis z --freq-hz 2 --amp-deg 2 --duration-s 60 --settle-s 0.3 --speed 1 --out \"$1\" >/dev/null 2>&1 & pid=$!; sleep 3.5; kill -INT $pid; wait $pid"
          ${CLI} ${dir}/live/stopped.fbs
  RESULT_VARIABLE c TIMEOUT 60)
execute_process(
  COMMAND sh -c "\"$0\" run --axis z --freq-hz 2 --amp-deg 2 --duration-s 60 --settle-s 0.3 --speed 1 --out \"$1\" >/dev/null 2>&1 & pid=$!
                 sleep 2; \"$0\" batch \"$1\" \"$2\" --jsonl \"$3\"; echo \"exit $?\"; kill -INT $pid; wait $pid"
          ${CLI} ${dir}/live/recording.fbs ${dir}/live/stopped.fbs ${dir}/live.jsonl
  RESULT_VARIABLE c OUTPUT_VARIABLE live ERROR_VARIABLE live_err TIMEOUT 60)
expect_match("${live}" "2 files into .*: 1 stored, 0 already stored, 1 refused.*1 INCOMPLETE.*exit 1" "the live batch's summary")
set(out ${dir}/live.jsonl)
unset(by_path_recording)
unset(by_path_stopped)
read_out()
string(JSON status GET "${by_path_recording}" status)
string(JSON error GET "${by_path_recording}" error)
if(NOT status STREQUAL "refused" OR NOT error MATCHES "is being recorded right now")
  message(FATAL_ERROR "the session being recorded is not refused as such:\n${by_path_recording}")
endif()
string(JSON status GET "${by_path_stopped}" status)
string(JSON verdict GET "${by_path_stopped}" verdict)
string(JSON data_verdict GET "${by_path_stopped}" data_verdict)
string(JSON refusal ERROR_VARIABLE no_refusal GET "${by_path_stopped}" points 0 refusal)
string(JSON bare ERROR_VARIABLE no_bare GET "${by_path_stopped}" points 0 imu_delay_ms)
if(NOT status STREQUAL "stored" OR NOT verdict STREQUAL "incomplete" OR NOT data_verdict STREQUAL "pass"
   OR NOT refusal MATCHES "^INCOMPLETE: " OR no_bare STREQUAL "")
  message(FATAL_ERROR "the stopped run is not stored INCOMPLETE with its delay refused:\n${by_path_stopped}")
endif()

# A path that does not exist (a typo) is refused before OUT is made; a
# session named as OUT is never written.
run_expect(2 ignored batch ${dir}/in ${dir}/no-such-folder --jsonl ${dir}/typo.jsonl)
expect_match("${ignored_err}" "no-such-folder' does not exist; give folders of sessions or session files" "a typo")
if(EXISTS ${dir}/typo.jsonl)
  message(FATAL_ERROR "a refused batch made its OUT")
endif()
file(SHA256 ${dir}/in/a.fbs a_before)
run_expect(2 ignored batch ${dir}/in --jsonl ${dir}/in/a.fbs --read-delay-ms 0.07 --limit-ms 0.9)
expect_match("${ignored_err}" "is a session \\(or another database\\), never written by batch" "a session as OUT")
file(SHA256 ${dir}/in/a.fbs a_after)
if(NOT a_before STREQUAL a_after)
  message(FATAL_ERROR "a session named as --jsonl was changed")
endif()
