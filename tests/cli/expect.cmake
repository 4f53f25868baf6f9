# Helpers of the end-to-end CLI scripts (include()d by them).

# Runs ${CLI} ARGN, fails unless it exits with `code`; its stdout in
# `out_var`, its stderr in `out_var`_err.
function(run_expect code out_var)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL ${code})
    message(FATAL_ERROR "'${ARGN}': expected exit ${code}, got ${c}: ${e}")
  endif()
  set(${out_var} "${o}" PARENT_SCOPE)
  set(${out_var}_err "${e}" PARENT_SCOPE)
endfunction()

# Fails unless `text` matches `regex`, saying `what` was checked.
function(expect_match text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: no match for '${regex}' in:\n${text}")
  endif()
endfunction()

# Runs ${CLI} ARGN (five minutes at most): its stdout and stderr together in
# `out_var`, its exit code in `code_var`.
function(cli out_var code_var)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 300)
  set(${out_var} "${o}${e}" PARENT_SCOPE)
  set(${code_var} ${c} PARENT_SCOPE)
endfunction()

# The text of a PDF through ${PDFTOTEXT} -layout; fails when it cannot be read.
function(pdf_text pdf out_var)
  execute_process(COMMAND ${PDFTOTEXT} -layout ${pdf} - RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL 0)
    message(FATAL_ERROR "pdftotext ${pdf} failed (${c}): ${e}")
  endif()
  set(${out_var} "${o}" PARENT_SCOPE)
endfunction()
