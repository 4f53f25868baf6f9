# Bench constants and the gain check end to end (issue 39, docs/sessions.md):
#   1. 2-ms rate rows imported with --frame-period-ms 2 analyse to PASS with
#      "ok gain"; imported with --frame-period-ms 1000 the gyro reads 500x
#      the table: INVALID, "FAILED gain: the gyro reads 500× the table ...",
#      also with a wider --gain-tolerance;
#   2. 2.01 ms (0.5 % off) passes, 2.04 ms (2 % off) is INVALID;
#   3. `analyze S --board-delay-ms 1e308 --read-delay-ms -0.2` is refused
#      (exit 2, the option named) and stores nothing; so is a tolerance of 1.
#   -DCLI=fogbench-cli -DGEN=fog_rates_csv -DDIR=scratch folder
set(dir ${DIR}/constants_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/csv)
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

execute_process(COMMAND ${GEN} ${dir}/csv RESULT_VARIABLE c ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "fog_rates_csv failed (${c}): ${e}")
endif()

# Imports the rows with the frame period `ms` into ${dir}/p<ms>.fbs and
# analyses it: the analysis' stdout in `out_var`.
function(import_and_analyze ms out_var)
  run_expect(0 imported import ${dir}/csv --rate-convention frame_average --frame-period-ms ${ms}
             --out ${dir}/p${ms}.fbs)
  run_expect(0 analysed analyze ${dir}/p${ms}.fbs ${ARGN})
  set(${out_var} "${analysed}" PARENT_SCOPE)
endfunction()

# 1. The right frame period, and the issue's 1000 ms.
import_and_analyze(2 good)
expect_match("${good}" "\nverdict: PASS\n" "2-ms frames")
expect_match("${good}" "ok +gain: the gyro's amplitude matches the table's \\(gyro/table ratio 1\\.0000, within 1 ± 1 %\\)"
             "2-ms frames")
import_and_analyze(1000 wrong)
expect_match("${wrong}" "\nverdict: INVALID\n" "--frame-period-ms 1000")
expect_match("${wrong}" "FAILED +gain: the gyro reads 500× the table \\(gyro/table ratio 50[0-9.]+, outside 1 ± 1 %\\): the pulse equivalent or the frame period is wrong"
             "--frame-period-ms 1000")
# (the decision rule's statement names PASS as a word of the rule, not a verdict)
string(REPLACE "PASS when IMU delay + k·σ < limit" "" wrong_verdicts "${wrong}")
if(wrong_verdicts MATCHES "PASS")
  message(FATAL_ERROR "a gyro reading 500x the table still shows PASS:\n${wrong}")
endif()
run_expect(0 wider analyze ${dir}/p1000.fbs --gain-tolerance 0.5)
expect_match("${wider}" "\nverdict: INVALID\n.*outside 1 ± 50 %" "--gain-tolerance 0.5")

# 2. 0.5 % and 2 % off.
import_and_analyze(2.01 half)
expect_match("${half}" "\nverdict: PASS\n" "2.01 ms")
expect_match("${half}" "ok +gain: [^\n]*ratio 1\\.0050, within 1 ± 1 %" "2.01 ms")
import_and_analyze(2.04 two)
expect_match("${two}" "\nverdict: INVALID\n" "2.04 ms")
expect_match("${two}" "FAILED +gain: the gyro reads 2\\.00 % more than the table \\(gyro/table ratio 1\\.0200, outside 1 ± 1 %\\)"
             "2.04 ms")

# 3. Constants out of range are refused before anything is analysed or stored.
run_expect(2 refused analyze ${dir}/p2.fbs --board-delay-ms 1e308 --read-delay-ms -0.2)
expect_match("${refused_err}" "^fogbench-cli: --read-delay-ms: the table read delay must be within 0 \\.\\. 1000 ms, not -0\\.2: a delay is never negative"
             "analyze --board-delay-ms 1e308 --read-delay-ms -0.2")
run_expect(2 huge analyze ${dir}/p2.fbs --board-delay-ms 1e308)
expect_match("${huge_err}" "--board-delay-ms: the processing-board delay must be within 0 \\.\\. 1000 ms, not 1e\\+308"
             "analyze --board-delay-ms 1e308")
run_expect(2 whole analyze ${dir}/p2.fbs --gain-tolerance 1)
expect_match("${whole_err}" "--gain-tolerance: the gain tolerance must be a fraction from 1e-6 up to \\(not including\\) 1, not 1"
             "analyze --gain-tolerance 1")
run_expect(0 json export ${dir}/p2.fbs --results-json ${dir}/p2.json)
file(READ ${dir}/p2.json j)
string(JSON n LENGTH "${j}" stored_results)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "refused constants stored a result: ${n} stored results (the first analyze's only expected):\n${j}")
endif()
