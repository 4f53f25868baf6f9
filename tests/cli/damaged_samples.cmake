# A session whose decoded samples are damaged but whose raw stream is intact
# is analysed from that raw stream (the session's source of truth), and says
# so in the first line of its output, before the report (issue 28). Its
# delay is the undamaged session's. A damaged header stays refused
# (damaged_header.cmake).
#   -DCLI=path -DSQLITE3=path -DDIR=scratch folder [-DHAVE_REPORT=ON]
set(dir ${DIR}/damaged_samples_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(s ${dir}/S.fbs)
execute_process(COMMAND ${CLI} run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5 --out ${s}
                RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --out failed (${c}): ${e}")
endif()
execute_process(COMMAND ${CLI} analyze ${s} --json --no-store RESULT_VARIABLE c OUTPUT_VARIABLE before ERROR_VARIABLE e)
string(JSON lagBefore ERROR_VARIABLE parse GET "${before}" test_points 0 lag_ms)
if(NOT c EQUAL 0 OR parse)
  message(FATAL_ERROR "analyze of the intact session failed (${c}): ${e}${parse}")
endif()
execute_process(COMMAND ${SQLITE3} ${s} "UPDATE decoded SET counter_bits = 4000" RESULT_VARIABLE c ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "sqlite3 failed: ${e}")
endif()

set(note "^fogbench-cli: note: [^\n]*S\\.fbs is a damaged session \\([^\n]*decoded samples are damaged[^\n]*\\); analysed from the raw board stream it holds[^\n]*\n")
# stdout and stderr merged in the order written: the note comes first.
function(expect_noted)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE o)
  if(NOT c EQUAL 0 OR NOT o MATCHES "${note}")
    message(FATAL_ERROR "'${ARGN}': expected exit 0 and the damage as the first line, got ${c}:\n${o}")
  endif()
  set(output "${o}" PARENT_SCOPE)
endfunction()

expect_noted(analyze ${s} --no-store)
if(NOT output MATCHES "source: session [^\n]*S\\.fbs[^\n]*\\[damaged session, analysed from the raw stream it holds\\]")
  message(FATAL_ERROR "the report's source should say the session is damaged:\n${output}")
endif()
# --json: the note on stderr, stdout one JSON document with the same delay.
execute_process(COMMAND ${CLI} analyze ${s} --json --no-store RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
string(JSON lagAfter ERROR_VARIABLE parse GET "${o}" test_points 0 lag_ms)
if(NOT c EQUAL 0 OR parse OR NOT e MATCHES "^fogbench-cli: note: [^\n]*is a damaged session")
  message(FATAL_ERROR "analyze --json of the damaged session (${c}): ${parse}\n${e}\n${o}")
endif()
if(NOT lagAfter EQUAL lagBefore AND NOT lagAfter STREQUAL lagBefore)
  message(FATAL_ERROR "the raw stream gave another lag: ${lagAfter} ms, the intact session ${lagBefore} ms")
endif()
expect_noted(export ${s} --csv ${dir}/csv)
if(HAVE_REPORT)
  expect_noted(report ${s} --pdf ${dir}/S.pdf)
endif()
