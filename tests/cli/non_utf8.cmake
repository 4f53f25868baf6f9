# Text that is not UTF-8 never aborts JSON output (issue 15): a Latin-1
# operator name and notes, a Latin-1 session file name and raw-stream file
# name. Every JSON command exits 0 with valid JSON, and the Latin-1 text is
# shown converted ("Müller").
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/non_utf8_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
string(ASCII 252 u_latin1)   # ü in Latin-1: one byte, not UTF-8
string(ASCII 233 e_latin1)   # é
set(s ${dir}/M${u_latin1}ller.fbs)
set(raw ${dir}/r${e_latin1}sum${e_latin1}.bin)

function(run_json out_var)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' failed (${c}): ${e}")
  endif()
  set(${out_var} "${o}" PARENT_SCOPE)
endfunction()

run_json(run_out run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5 --out ${s} --save-raw ${raw}
         --operator "M${u_latin1}ller" --notes "caf${e_latin1}" --json)
string(JSON lag ERROR_VARIABLE err GET "${run_out}" test_points 0 lag_ms)
if(err)
  message(FATAL_ERROR "run --json is not valid JSON (${err}):\n${run_out}")
endif()

run_json(list_out sessions ${dir} --json)
string(JSON op ERROR_VARIABLE err GET "${list_out}" sessions 0 operator)
if(err OR NOT op STREQUAL "Müller")
  message(FATAL_ERROR "sessions --json: operator should read Müller (${err}):\n${list_out}")
endif()
string(JSON file ERROR_VARIABLE err GET "${list_out}" sessions 0 file)
if(err OR NOT file STREQUAL "Müller.fbs")
  message(FATAL_ERROR "sessions --json: file should read Müller.fbs (${err}):\n${list_out}")
endif()

run_json(analyze_out analyze ${s} --json)
string(JSON source ERROR_VARIABLE err GET "${analyze_out}" source)
if(err OR NOT source MATCHES "Müller\\.fbs")
  message(FATAL_ERROR "analyze --json of a Latin-1 named session (${err}):\n${analyze_out}")
endif()

run_json(raw_out analyze ${raw} --json)
string(JSON source ERROR_VARIABLE err GET "${raw_out}" source)
if(err OR NOT source MATCHES "résumé\\.bin")
  message(FATAL_ERROR "analyze --json of a Latin-1 named raw stream (${err}):\n${raw_out}")
endif()

run_json(export_out export ${s} --results-json ${dir}/results.json)
file(READ ${dir}/results.json doc)
string(JSON notes ERROR_VARIABLE err GET "${doc}" session notes)
if(err OR NOT notes STREQUAL "café")
  message(FATAL_ERROR "export --results-json: notes should read café (${err}):\n${doc}")
endif()
