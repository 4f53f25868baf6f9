# SIGINT or SIGTERM during a simulated run at real time (issue 15: the run
# printed nothing and left the session "recording"): the run says it is
# incomplete, the session is marked incomplete ("stopped by the operator")
# and keeps what was recorded, and it analyses.
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/run_interrupted_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

foreach(sig INT TERM)
  set(s ${dir}/stopped-${sig}.fbs)
  execute_process(
    COMMAND sh -c "\"$0\" run --axis z --freq-hz 2 --amp-deg 2 --duration-s 60 --settle-s 0.3 --speed 1 --out \"$1\" & pid=$!; sleep 3.5; kill -${sig} $pid; wait $pid"
            ${CLI} ${s}
    RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 60)
  if(NOT c EQUAL 0 OR NOT e MATCHES "run incomplete: stopped by the operator after [0-9.]+ s.*all kept in")
    message(FATAL_ERROR "SIG${sig}: expected exit 0 and 'run incomplete: stopped ...', got ${c}:\n${e}\n${o}")
  endif()
  if(NOT o MATCHES "measured lag")
    message(FATAL_ERROR "SIG${sig}: what was recorded was not analysed:\n${o}")
  endif()
  # Standard output carries the run's state too, never a bare PASS.
  if(NOT o MATCHES "\nverdict: INCOMPLETE \\(run stopped after [0-9.]+ s of 61\\.3 s: stopped by the operator after [0-9.]+ s\\); the data recorded give PASS\n"
     OR o MATCHES "\nverdict: PASS")
    message(FATAL_ERROR "SIG${sig}: the report on standard output does not say the run is incomplete:\n${o}")
  endif()
endforeach()

# The same in JSON: the verdict is "incomplete", with the run's state.
set(s ${dir}/stopped-json.fbs)
execute_process(
  COMMAND sh -c "\"$0\" run --axis z --freq-hz 2 --amp-deg 2 --duration-s 60 --settle-s 0.3 --speed 1 --json --out \"$1\" & pid=$!; sleep 3.5; kill -INT $pid; wait $pid"
          ${CLI} ${s}
  RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 60)
string(JSON verdict ERROR_VARIABLE err GET "${o}" verdict)
string(JSON data_verdict ERROR_VARIABLE err GET "${o}" data_verdict)
string(JSON complete ERROR_VARIABLE err GET "${o}" run complete)
string(JSON reason ERROR_VARIABLE err GET "${o}" run incomplete_reason)
if(NOT c EQUAL 0 OR NOT verdict STREQUAL "incomplete" OR NOT data_verdict STREQUAL "pass" OR complete
   OR NOT reason MATCHES "^stopped by the operator after")
  message(FATAL_ERROR "--json: expected verdict incomplete with the run's state, got ${c}:\n${e}\n${o}")
endif()
file(REMOVE ${s})

execute_process(COMMAND ${CLI} sessions ${dir} --json RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
foreach(i 0 1)
  string(JSON complete GET "${o}" sessions ${i} complete)
  string(JSON reason GET "${o}" sessions ${i} incomplete_reason)
  if(complete OR NOT reason MATCHES "stopped by the operator")
    message(FATAL_ERROR "session ${i} is not marked incomplete by the operator:\n${o}")
  endif()
endforeach()
execute_process(COMMAND ${CLI} analyze ${dir}/stopped-TERM.fbs --no-store RESULT_VARIABLE c OUTPUT_VARIABLE o
                ERROR_VARIABLE e)
if(NOT c EQUAL 0 OR NOT o MATCHES "measured lag")
  message(FATAL_ERROR "the stopped session does not analyse (${c}):\n${e}${o}")
endif()
if(NOT o MATCHES "\nverdict: INCOMPLETE \\(stopped by the operator after [0-9.]+ s\\); the data recorded give PASS\n")
  message(FATAL_ERROR "the analysis of the stopped session does not say it is incomplete:\n${o}")
endif()
