# diagnose on a jittered damped pendulum imported at its native 90 Hz table /
# 50 Hz gyro (the unbounded-memory issue) under a 1 GB address-space limit:
# it finishes with a verdict (exit 0) or a one-line refusal (exit 2), never a
# crash (134 abort / bad_alloc, 139 segfault), and a verdict is not "none".
#   -DCLI=fogbench-cli -DGEN=fog_pendulum_csv -DDIR=scratch folder
set(dir ${DIR}/diagnose_bounded)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/csv)
execute_process(COMMAND ${GEN} ${dir}/csv 0.0003 RESULT_VARIABLE c ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "fog_pendulum_csv failed (${c}): ${e}")
endif()
execute_process(COMMAND ${CLI} import ${dir}/csv --out ${dir}/pend_j.fbs RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "import failed (${c}): ${e}")
endif()
# ulimit -v is in KiB: 1048576 KiB = 1 GiB, the documented budget.
execute_process(COMMAND sh -c "ulimit -v 1048576 && exec \"$0\" diagnose \"$1\"" ${CLI} ${dir}/pend_j.fbs
                RESULT_VARIABLE c OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(c EQUAL 0)
  if(NOT out MATCHES "\nVerdict: ")
    message(FATAL_ERROR "diagnose exited 0 without a verdict:\n${out}")
  endif()
  if(out MATCHES "\nVerdict: none")
    message(FATAL_ERROR "a jittered, decaying swing against a steady replay is no agreement:\n${out}")
  endif()
elseif(c EQUAL 2)
  string(STRIP "${err}" line)
  if(line STREQUAL "" OR line MATCHES "\n")
    message(FATAL_ERROR "diagnose refused without a one-line error:\n${err}")
  endif()
else()
  message(FATAL_ERROR "diagnose under a 1 GB limit ended with ${c} (a crash or bad_alloc?):\n${err}")
endif()
