# run --save-raw FILE, then analyze FILE: the delay lines must be identical.
set(raw ${DIR}/saved_run.bin)
file(REMOVE ${raw})  # --save-raw never replaces a file without --overwrite
execute_process(COMMAND ${CLI} run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5 --save-raw ${raw}
                RESULT_VARIABLE c1 OUTPUT_VARIABLE run_out ERROR_VARIABLE e1)
if(NOT c1 EQUAL 0)
  message(FATAL_ERROR "run failed: ${e1}")
endif()
execute_process(COMMAND ${CLI} analyze ${raw} RESULT_VARIABLE c2 OUTPUT_VARIABLE analyze_out ERROR_VARIABLE e2)
if(NOT c2 EQUAL 0)
  message(FATAL_ERROR "analyze failed: ${e2}")
endif()
string(REGEX MATCHALL "measured lag[^\n]*|= IMU delay[^\n]*|= gyro's own delay[^\n]*" a "${run_out}")
string(REGEX MATCHALL "measured lag[^\n]*|= IMU delay[^\n]*|= gyro's own delay[^\n]*" b "${analyze_out}")
if(NOT a OR NOT a STREQUAL b)
  message(FATAL_ERROR "run and analyze differ:\n${a}\nvs\n${b}")
endif()
