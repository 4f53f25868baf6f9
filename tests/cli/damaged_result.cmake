# A stored result damaged inside the file (its checksum fails, its JSON is
# cut) never exports as invalid JSON with exit 0 (issue 15): export writes
# valid JSON with an "error" on that result and exits 2 with one line.
#   -DCLI=path -DSQLITE3=path -DDIR=scratch folder
set(dir ${DIR}/damaged_result_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(s ${dir}/r.fbs)
execute_process(COMMAND ${CLI} run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5 --out ${s}
                RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --out failed (${c}): ${e}")
endif()
execute_process(COMMAND ${SQLITE3} ${s} "UPDATE result SET report_json = substr(report_json, 1, 40)"
                RESULT_VARIABLE c ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "sqlite3 failed: ${e}")
endif()
execute_process(COMMAND ${CLI} export ${s} --results-json ${dir}/out.json RESULT_VARIABLE c OUTPUT_VARIABLE o
                ERROR_VARIABLE e)
string(STRIP "${e}" e)
if(NOT c EQUAL 2 OR e MATCHES "\n" OR NOT e MATCHES "damaged.*restore the session from a backup")
  message(FATAL_ERROR "export of a damaged result: expected exit 2 and a line saying so, got ${c}:\n${e}")
endif()
file(READ ${dir}/out.json doc)
string(JSON err ERROR_VARIABLE parse GET "${doc}" stored_results 0 error)
if(parse OR NOT err MATCHES "checksum")
  message(FATAL_ERROR "export wrote invalid JSON or no error for the damaged result (${parse}):\n${doc}")
endif()
string(JSON lag ERROR_VARIABLE parse GET "${doc}" current_analysis report test_points 0 lag_ms)
if(parse)
  message(FATAL_ERROR "the current analysis is missing (${parse}):\n${doc}")
endif()

# sessions says the stored result is damaged instead of showing "-" (issue
# 29), and once a new analysis is stored shows that one with the count.
execute_process(COMMAND ${CLI} sessions ${dir} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0 OR NOT o MATCHES "r\\.fbs[^\n]* damaged \\(1 of 1\\)")
  message(FATAL_ERROR "sessions should show r.fbs's result as damaged (${c}):\n${o}${e}")
endif()
execute_process(COMMAND ${CLI} analyze ${s} RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "analyze to store a second result failed (${c}): ${e}")
endif()
execute_process(COMMAND ${CLI} sessions ${dir} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0 OR NOT o MATCHES "r\\.fbs[^\n]* PASS \\(2 of 2; 1 damaged\\)")
  message(FATAL_ERROR "sessions should show result 2 of 2 and the damaged one (${c}):\n${o}${e}")
endif()
execute_process(COMMAND ${CLI} sessions ${dir} --json RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
string(JSON damaged ERROR_VARIABLE parse GET "${o}" sessions 0 damaged_results)
string(JSON verdict ERROR_VARIABLE parse2 GET "${o}" sessions 0 verdict)
if(parse OR parse2 OR NOT damaged EQUAL 1 OR NOT verdict STREQUAL "pass")
  message(FATAL_ERROR "sessions --json: damaged_results ${damaged}, verdict ${verdict} (${parse}${parse2}):\n${o}")
endif()
