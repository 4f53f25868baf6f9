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
