# The Chinese PDF report speaks Chinese (issue 31): `report --language
# zh_CN` of a session with a swing and a static segment (every page: the
# verdict, the session, the constants and delay budget, plots, fits, the
# noise page) read with pdftotext holds no English word but units, names and
# references (the allow-list below), hashes and the session's file name.
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
# A short relative name: the data source line holds it whole.
execute_process(COMMAND ${CLI} report s.fbs --language zh_CN --pdf s.pdf WORKING_DIRECTORY ${dir} RESULT_VARIABLE c
                OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "report --language zh_CN failed (${c}): ${o}${e}")
endif()
execute_process(COMMAND ${PDFTOTEXT} -layout ${dir}/s.pdf - RESULT_VARIABLE c OUTPUT_VARIABLE text ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "pdftotext failed (${c}): ${e}")
endif()
if(NOT text MATCHES "噪声")
  message(FATAL_ERROR "the report has no noise page (the static segment):\n${text}")
endif()
# What may stay: the file's name, the SHA-256 digest (whole, and its first
# 16 digits in the footer), and these words.
string(REPLACE "s.fbs" " " rest "${text}")
string(REGEX REPLACE "[0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f]+" " " rest "${text}")
string(REPLACE "s.fbs" " " rest "${rest}")
# The audit trail's data, shown as stored: the command line that made each
# result (in [...], wrapped over lines by the layout) and who ran it (the
# login name: no operator was named).
string(REGEX REPLACE "\\[[^]]*\\]" " " rest "${rest}")
execute_process(COMMAND id -un OUTPUT_VARIABLE login OUTPUT_STRIP_TRAILING_WHITESPACE)
if(login)
  string(REPLACE "${login}" " " rest "${rest}")
endif()
string(REGEX MATCHALL "[A-Za-z][A-Za-z]+" words "${rest}")
set(allowed IMU fogbench SHA CRLB Cram Rao Allan dof RMS MHz Hz kHz ms sin cos UTC Sagnac Mbaud baud IEEE Std
            arcsec ISO IEC ILAC)
set(left "")
foreach(w IN LISTS words)
  list(FIND allowed "${w}" at)
  if(at EQUAL -1)
    list(APPEND left "${w}")
  endif()
endforeach()
list(REMOVE_DUPLICATES left)
if(left)
  message(FATAL_ERROR "English left in the zh_CN PDF: ${left}\n--- text ---\n${text}")
endif()
