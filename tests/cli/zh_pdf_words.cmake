# The Chinese PDF report speaks Chinese (issue 31): `report --language
# zh_CN` of a session with a swing and a static segment (every page: the
# verdict, the session, the constants and delay budget, plots, fits, the
# noise page), and of a frequency response of the simulator's 2-ms lag (the
# model table and its notes, the effect named in the data source), read with
# pdftotext holds no English word but units, names and references (the
# allow-list below), hashes and the session's file name.
# pdftotext (poppler-utils, scripts/setup.sh) is required, never skipped.
#   -DCLI=path -DDIR=scratch folder -DPDFTOTEXT=path
set(dir ${DIR}/zh_pdf_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
if(NOT PDFTOTEXT OR NOT EXISTS "${PDFTOTEXT}")
  message(FATAL_ERROR "pdftotext (poppler-utils) is missing: install it (scripts/setup.sh)")
endif()
file(WRITE ${dir}/plan.json [=[{"rest_between_s": 1, "points": [
  {"kind": "static", "axis": "x", "duration_s": 120, "settle_s": 0},
  {"axis": "x", "frequency_hz": 1, "amplitude_deg": 3, "duration_s": 20, "settle_s": 1}]}]=])
execute_process(COMMAND ${CLI} run --plan ${dir}/plan.json --out ${dir}/s.fbs RESULT_VARIABLE c OUTPUT_VARIABLE o
                ERROR_VARIABLE e TIMEOUT 300)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --out failed (${c}): ${o}${e}")
endif()
# The English a Chinese PDF may keep: the file's name, the SHA-256 digest
# (whole, and its first 16 or 12 digits in the footer and the audit trail), the audit trail's data as
# stored (the command line that made each result, in [...], wrapped over
# lines by the layout, and who ran it: the login name, no operator was
# named), references to the docs, and the words below (units, names of
# methods and people).
execute_process(COMMAND id -un OUTPUT_VARIABLE login OUTPUT_STRIP_TRAILING_WHITESPACE)
function(expect_chinese_pdf session what)
  # A short relative name: the data source line holds it whole.
  execute_process(COMMAND ${CLI} report ${session}.fbs --language zh_CN --pdf ${session}.pdf WORKING_DIRECTORY ${dir}
                  RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "report --language zh_CN of ${what} failed (${c}): ${o}${e}")
  endif()
  execute_process(COMMAND ${PDFTOTEXT} -layout ${dir}/${session}.pdf - RESULT_VARIABLE c OUTPUT_VARIABLE text
                  ERROR_VARIABLE e)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "pdftotext failed (${c}): ${e}")
  endif()
  set(pdf_text "${text}" PARENT_SCOPE)
  string(REGEX REPLACE "[0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f]+" " " rest "${text}")
  string(REPLACE "${session}.fbs" " " rest "${rest}")
  string(REGEX REPLACE "\\[[^]]*\\]" " " rest "${rest}")
  string(REGEX REPLACE "docs/[a-z-]+[.]md" " " rest "${rest}")
  if(login)
    string(REPLACE "${login}" " " rest "${rest}")
  endif()
  string(REGEX MATCHALL "[A-Za-z][A-Za-z]+" words "${rest}")
  set(allowed IMU fogbench SHA CRLB Cram Rao Allan dof RMS MHz Hz kHz ms dB sin cos UTC Sagnac Mbaud baud IEEE Std
              arcsec ISO IEC ILAC AIC BIC)
  set(left "")
  foreach(w IN LISTS words)
    list(FIND allowed "${w}" at)
    if(at EQUAL -1)
      list(APPEND left "${w}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES left)
  if(left)
    message(FATAL_ERROR "English left in the zh_CN PDF of ${what}: ${left}\n--- text ---\n${text}")
  endif()
endfunction()

expect_chinese_pdf(s "a swing and a static segment")
if(NOT pdf_text MATCHES "噪声")
  message(FATAL_ERROR "the report has no noise page (the static segment):\n${pdf_text}")
endif()

# A frequency response (issue 41): six points 0.5-11 Hz behind the
# simulator's 2-ms lag, named in the data source line ("effect
# first_order_lag=2"), with its model table, notes and phase budget.
file(WRITE ${dir}/response.json [=[{"rest_between_s": 0.5, "points": [
  {"axis": "x", "frequency_hz": 0.5, "amplitude_deg": 10, "duration_s": 6, "settle_s": 1},
  {"axis": "x", "frequency_hz": 1, "amplitude_deg": 10, "duration_s": 4, "settle_s": 1},
  {"axis": "x", "frequency_hz": 2, "amplitude_deg": 5, "duration_s": 3, "settle_s": 1},
  {"axis": "x", "frequency_hz": 4, "amplitude_deg": 3, "duration_s": 3, "settle_s": 1},
  {"axis": "x", "frequency_hz": 7, "amplitude_deg": 1.2, "duration_s": 3, "settle_s": 1},
  {"axis": "x", "frequency_hz": 11, "amplitude_deg": 0.5, "duration_s": 3, "settle_s": 1}]}]=])
execute_process(COMMAND ${CLI} run --plan ${dir}/response.json --effect first_order_lag=2 --out ${dir}/r.fbs
                RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --effect first_order_lag=2 failed (${c}): ${o}${e}")
endif()
expect_chinese_pdf(r "a frequency response")
if(NOT pdf_text MATCHES "AIC" OR NOT pdf_text MATCHES "一阶滞后=2")
  message(FATAL_ERROR "the response's PDF has no model table or names no effect in Chinese:\n${pdf_text}")
endif()
