# A stored result is a record (docs/sessions.md, "Stored results"): every
# view shows its verdict as stored, never a re-judgement.
#  1. `analyze --gyro-sign x=-1` stores result 2 as INVALID (reversed axis):
#     `sessions`, `report` (its stdout and the PDF's text) say INVALID, and
#     the stored settings hold the gyro sign and the limit;
#  2. `report` with another limit or constants is refused (that is a new
#     analysis: `analyze` stores it first);
#  3. a run stopped by SIGINT is INCOMPLETE in `sessions` and in the PDF.
# The PDF's text is read with pdftotext (poppler-utils, scripts/setup.sh):
# missing, the test fails; it is never skipped.
#   -DCLI=path -DDIR=scratch folder -DPDFTOTEXT=path
set(dir ${DIR}/stored_verdict_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
if(NOT PDFTOTEXT OR NOT EXISTS "${PDFTOTEXT}")
  message(FATAL_ERROR "pdftotext (poppler-utils) is missing: install it (scripts/setup.sh)")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

# 1. The invalid stored result.
set(s ${dir}/reversed.fbs)
cli(o c run --axis x --freq-hz 2 --amp-deg 2 --duration-s 10 --settle-s 0.3 --out ${s})
if(NOT c EQUAL 0 OR NOT o MATCHES "\nverdict: PASS\n")
  message(FATAL_ERROR "run --out did not pass (${c}):\n${o}")
endif()
cli(o c analyze ${s} --gyro-sign x=-1)
if(NOT c EQUAL 0 OR NOT o MATCHES "\nverdict: INVALID\n" OR NOT o MATCHES "Result stored")
  message(FATAL_ERROR "analyze --gyro-sign x=-1 did not store an INVALID result (${c}):\n${o}")
endif()
cli(o c sessions ${dir})
if(NOT o MATCHES "reversed\\.fbs[^\n]*INVALID \\(2 of 2\\)")
  message(FATAL_ERROR "sessions does not show the stored INVALID:\n${o}")
endif()
cli(o c export ${s} --results-json ${dir}/results.json)
file(READ ${dir}/results.json j)
string(JSON sign GET "${j}" stored_results 1 settings gyro_sign x)
string(JSON limit GET "${j}" stored_results 1 settings imu_delay_limit_ms)
if(NOT sign EQUAL -1 OR NOT limit EQUAL 0.8)
  message(FATAL_ERROR "result 2's settings do not hold the gyro sign and the limit:\n${j}")
endif()
cli(o c report ${s} --pdf ${dir}/reversed.pdf)
# The audit trail lists every stored result with its own stored verdict (the
# run's PASS among them): a record of what was stored, not the verdict shown.
# The decision rule's statement names PASS as a word of the rule, not a verdict.
string(REGEX REPLACE "\n  #[0-9][^\n]*" "" shown "${o}")
string(REPLACE "PASS when IMU delay + k·σ < limit" "" shown "${shown}")
if(NOT c EQUAL 0 OR NOT o MATCHES "result shown: result 2 of 2" OR NOT o MATCHES "\nINVALID: "
   OR NOT o MATCHES "test point 1: INVALID: " OR shown MATCHES "PASS"
   OR NOT o MATCHES "\n  #1 [^\n]* acquisition [^\n]*\\| PASS\n  #2 [^\n]*--gyro-sign x=-1[^\n]*\\| INVALID\n")
  message(FATAL_ERROR "report does not print the stored INVALID (${c}):\n${o}")
endif()
pdf_text(${dir}/reversed.pdf text)
# The PDF's audit trail lists the run's stored PASS too (a record of what was
# stored): it must be there, and the verdict shown elsewhere never PASS.
string(REGEX MATCH "Analyses of this session.*verdict as stored\\." trail "${text}")
string(REGEX REPLACE "Analyses of this session.*verdict as stored\\." "" shown "${text}")
if(NOT trail MATCHES "#1 .*PASS.*#2 .*INVALID")
  message(FATAL_ERROR "the PDF's audit trail does not list both stored results:\n${text}")
endif()
if(NOT text MATCHES "INVALID" OR NOT text MATCHES "result 2 of 2" OR shown MATCHES "PASS")
  message(FATAL_ERROR "the PDF does not show the stored INVALID:\n${text}")
endif()
message(STATUS "report of the reversed session:\n${o}")

# 2. Another setting is another analysis, stored first.
foreach(option "--limit-ms;0.5" "--read-delay-ms;0.45" "--gyro-sign;x=1")
  cli(o c report ${s} --pdf ${dir}/other.pdf ${option})
  if(NOT c EQUAL 2 OR NOT o MATCHES "does not apply: the report shows the session's stored result" OR EXISTS ${dir}/other.pdf)
    message(FATAL_ERROR "report ${option} was not refused (${c}):\n${o}")
  endif()
endforeach()
cli(o c analyze ${s} --gyro-sign x=1 --limit-ms 0.5)
cli(o c report ${s} --pdf ${dir}/strict.pdf)
if(NOT o MATCHES "result shown: result 3 of 3" OR NOT o MATCHES "FAIL against the 0\\.5 ms limit")
  message(FATAL_ERROR "report does not show result 3 (limit 0.5 ms, stored FAIL):\n${o}")
endif()

# 3. A run stopped by the operator.
set(s ${dir}/stopped.fbs)
execute_process(
  COMMAND sh -c "\"$0\" run --axis z --freq-hz 2 --amp-deg 2 --duration-s 60 --settle-s 0.3 --speed 1 --out \"$1\" & pid=$!; sleep 3.5; kill -INT $pid; wait $pid"
          ${CLI} ${s}
  RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 60)
if(NOT c EQUAL 0 OR NOT o MATCHES "verdict: INCOMPLETE")
  message(FATAL_ERROR "the stopped run did not say INCOMPLETE (${c}):\n${o}${e}")
endif()
cli(o c sessions ${dir})
if(NOT o MATCHES "stopped\\.fbs[^\n]*incomplete[^\n]*INCOMPLETE \\(1 of 1\\)")
  message(FATAL_ERROR "sessions does not show the stopped run as INCOMPLETE:\n${o}")
endif()
cli(o c report ${s} --pdf ${dir}/stopped.pdf)
if(NOT c EQUAL 0 OR NOT o MATCHES "\nINCOMPLETE: the run stopped before its plan ended" OR o MATCHES "\nPASS")
  message(FATAL_ERROR "report of the stopped run is not INCOMPLETE (${c}):\n${o}")
endif()
pdf_text(${dir}/stopped.pdf text)
# "PASS" only as what the data give, never as a verdict.
string(REGEX REPLACE "give[ \n]+PASS" "" verdicts "${text}")
if(NOT text MATCHES "INCOMPLETE" OR verdicts MATCHES "PASS")
  message(FATAL_ERROR "the PDF of the stopped run is not INCOMPLETE:\n${text}")
endif()
message(STATUS "report of the stopped session:\n${o}")
