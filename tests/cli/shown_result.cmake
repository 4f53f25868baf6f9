# One shown result everywhere (issue 39, docs/report.md "The verdict shown,
# and refused numbers"):
#  1. `run --preset quick --out q.fbs`, then `analyze q.fbs --read-delay-ms
#     0.30` (result 2, shown): `report`, `export` (report.json, delays.csv),
#     `response` and `diagnose` use result 2's constants and say so; the IMU
#     delay is the stored one to the last digit in every file;
#  2. `analyze --gyro-sign x=-1` (result 3, INVALID): `sessions` lists the
#     delays as refused, `sessions --json` says vouched false with why,
#     `export`'s delays.csv marks every row invalid/false;
#  3. the PDF's SHA-256 reads back whole (64 hex digits) through pdftotext;
#  4. a copy whose raw stream fails its checksum (its decoded samples intact)
#     says so first in export and report, and in `sessions`.
#   -DCLI=path -DDIR=scratch folder -DPDFTOTEXT=path -DSQLITE3=path
set(dir ${DIR}/shown_result_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
if(NOT PDFTOTEXT OR NOT EXISTS "${PDFTOTEXT}")
  message(FATAL_ERROR "pdftotext (poppler-utils) is missing: install it (scripts/setup.sh)")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

# The value of `quantity` of test point 1 in a delays.csv, and its verdict columns.
function(delays_row file quantity out_var)
  file(STRINGS ${file} rows REGEX "^1,[^,]*,[^,]*,${quantity},")
  list(LENGTH rows n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "${file}: no single row for ${quantity} of test point 1")
  endif()
  set(${out_var} "${rows}" PARENT_SCOPE)
endfunction()

# 1. Result 2, re-analysed with another table read delay, is shown everywhere.
set(s ${dir}/q.fbs)
cli(o c run --preset quick --out ${s})
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --preset quick --out failed (${c}):\n${o}")
endif()
cli(o c analyze ${s} --read-delay-ms 0.30)
if(NOT c EQUAL 0 OR NOT o MATCHES "Result stored")
  message(FATAL_ERROR "analyze --read-delay-ms 0.30 did not store result 2 (${c}):\n${o}")
endif()
cli(o c export ${s} --results-json ${dir}/results.json --csv ${dir}/csv)
if(NOT c EQUAL 0 OR NOT o MATCHES "note: analysed with the constants of the result shown \\(result 2 of 2")
  message(FATAL_ERROR "export does not say it uses result 2's constants (${c}):\n${o}")
endif()
file(READ ${dir}/results.json j)
string(JSON stored GET "${j}" stored_results 1 report test_points 0 imu_delay_ms)
string(JSON first GET "${j}" stored_results 0 report test_points 0 imu_delay_ms)
file(READ ${dir}/csv/report.json r)
string(JSON exported GET "${r}" test_points 0 imu_delay_ms)
delays_row(${dir}/csv/delays.csv imu_delay row)
string(REPLACE "," ";" cells "${row}")
list(GET cells 4 csvDelay)
list(GET cells 6 csvVerdict)
list(GET cells 7 csvVouched)
# The JSON keeps 17 significant digits, the CSV the shortest text that reads
# back to the same double: they agree in the first 15.
string(SUBSTRING "${stored}" 0 16 stored15)
string(SUBSTRING "${csvDelay}" 0 16 csv15)
if(NOT exported STREQUAL stored OR NOT csv15 STREQUAL stored15 OR stored STREQUAL first)
  message(FATAL_ERROR "export's IMU delay is not result 2's: stored ${stored} (result 1 ${first}), "
                      "report.json ${exported}, delays.csv ${csvDelay}")
endif()
if(NOT csvVerdict STREQUAL "pass" OR NOT csvVouched STREQUAL "true")
  message(FATAL_ERROR "delays.csv does not carry result 2's PASS: ${row}")
endif()
cli(o c report ${s} --pdf ${dir}/q.pdf)
if(NOT c EQUAL 0 OR NOT o MATCHES "result shown: result 2 of 2")
  message(FATAL_ERROR "report does not show result 2 (${c}):\n${o}")
endif()
string(SUBSTRING "${stored}" 0 6 stored4)  # "0.7657": the report prints at least four decimals
if(NOT o MATCHES "IMU delay ${stored4}")
  message(FATAL_ERROR "report's IMU delay is not result 2's (${stored}):\n${o}")
endif()
cli(o c response ${s})
if(NOT o MATCHES "note: analysed with the constants of the result shown \\(result 2 of 2")
  message(FATAL_ERROR "response does not say it uses result 2's constants (${c}):\n${o}")
endif()
cli(o c diagnose ${s} --seeds 2 --json)
if(NOT c EQUAL 0 OR NOT o MATCHES "note: analysed with the constants of the result shown \\(result 2 of 2")
  message(FATAL_ERROR "diagnose does not say it uses result 2's constants (${c}):\n${o}")
endif()
cli(o c export ${s} --csv ${dir}/given --read-delay-ms 0.05)
if(NOT c EQUAL 0 OR NOT o MATCHES "constants given on the command line over the session's own, not those of the result shown")
  message(FATAL_ERROR "export with a constant given does not say so (${c}):\n${o}")
endif()

# 3. The PDF's SHA-256 reads back whole.
pdf_text(${dir}/q.pdf text)
if(NOT text MATCHES "SHA-256 +[0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f]")
  message(FATAL_ERROR "the PDF's text has no whole 64-digit SHA-256 (ligatures?):\n${text}")
endif()
# The conventions the delays depend on are stated in the CLI's PDF as in the
# GUI's (the same page): the gyro signs and the IMU frame.
if(NOT text MATCHES "gyro signs +X \\+1, Y \\+1, Z \\+1" OR NOT text MATCHES "IMU frame")
  message(FATAL_ERROR "the PDF does not state the gyro signs and the IMU frame:\n${text}")
endif()
# And the text report (analyze without storing a result).
cli(o c analyze ${s} --no-store)
if(NOT o MATCHES "\ngyro signs: X \\+1, Y \\+1, Z \\+1 [^\n]*; IMU frame: ")
  message(FATAL_ERROR "the text report does not state the gyro signs and the IMU frame:\n${o}")
endif()

# 2. An INVALID result's delays are refused in every list and CSV.
cli(o c analyze ${s} --gyro-sign x=-1)
if(NOT c EQUAL 0 OR NOT o MATCHES "\nverdict: INVALID\n")
  message(FATAL_ERROR "analyze --gyro-sign x=-1 did not store an INVALID result (${c}):\n${o}")
endif()
cli(o c sessions ${dir})
if(NOT o MATCHES "q\\.fbs[^\n]*INVALID \\(3 of 3\\)[^\n]*refused \\([-0-9.]+, INVALID\\)")
  message(FATAL_ERROR "sessions lists the INVALID result's delays bare:\n${o}")
endif()
cli(o c sessions ${dir} --json)
string(JSON vouched GET "${o}" sessions 0 test_points 0 vouched)
string(JSON refusal GET "${o}" sessions 0 test_points 0 refusal)
if(NOT vouched STREQUAL "OFF" OR NOT refusal MATCHES "^INVALID: ")
  message(FATAL_ERROR "sessions --json does not refuse the INVALID delay (vouched ${vouched}, refusal ${refusal}):\n${o}")
endif()
cli(o c export ${s} --csv ${dir}/invalid)
delays_row(${dir}/invalid/delays.csv imu_delay row)
if(NOT row MATCHES ",invalid,false,")
  message(FATAL_ERROR "delays.csv does not mark the INVALID delay: ${row}")
endif()
# 4. A damaged raw stream under intact decoded samples.
set(raw ${dir}/raw.fbs)
file(COPY_FILE ${s} ${raw})
execute_process(COMMAND ${SQLITE3} ${raw} "UPDATE raw_chunk SET data_fnv1a = data_fnv1a + 1 WHERE seq = 0"
                RESULT_VARIABLE c ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "sqlite3 could not damage the copy (${c}): ${e}")
endif()
foreach(command "export;${raw};--csv;${dir}/raw-export" "response;${raw}" "analyze;${raw};--no-store")
  execute_process(COMMAND ${CLI} ${command} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  if(NOT e MATCHES "^fogbench-cli: note: [^\n]*raw\\.fbs is a damaged session: its raw board stream")
    message(FATAL_ERROR "'${command}' does not say first that the raw stream is damaged (${c}):\n${e}\n${o}")
  endif()
endforeach()
# The report hashes the raw stream onto the page: it refuses, naming the chunk.
cli(o c report ${raw} --pdf ${dir}/raw.pdf)
if(c EQUAL 0 OR NOT o MATCHES "raw stream chunk 0 [^\n]*fails its checksum")
  message(FATAL_ERROR "report of a damaged raw stream did not refuse it (${c}):\n${o}")
endif()
cli(o c sessions ${dir})
if(NOT o MATCHES "raw\\.fbs[^\n]*complete, raw stream damaged")
  message(FATAL_ERROR "sessions does not say the raw stream is damaged:\n${o}")
endif()

message(STATUS "one shown result: result 2's IMU delay ${stored} ms in report, export and delays.csv; "
               "result 3's INVALID refused in sessions and delays.csv; the PDF's SHA-256 whole")
