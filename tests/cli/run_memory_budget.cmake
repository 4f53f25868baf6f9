# The memory budget of a run (core/common/test_plan.h, docs/reliability.md):
# the largest plan allowed (1 h in all) runs to the end with --out in 1 GB of
# address space (`ulimit -v`), and what would not fit is refused before
# anything is simulated, with one line and exit 2 (a 23.9-h plan used to
# abort with std::bad_alloc at 1.9 GB); its session analyses and diagnoses
# within the same limit.
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/run_memory_budget_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

# A call's time limit only catches a hang: what this test checks is the
# memory, and the diagnosis of the 1-h session, held to one thread by the
# limit, takes 200-400 s on a 2-core machine that runs another test beside it.
if(NOT DEFINED CALL_TIMEOUT_S)
  set(CALL_TIMEOUT_S 1200)
endif()
function(run_limited out_code out_stdout out_stderr)
  execute_process(COMMAND sh -c "ulimit -v 1048576; exec \"$0\" \"$@\"" ${CLI} ${ARGN}
                  RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT ${CALL_TIMEOUT_S})
  set(${out_code} "${c}" PARENT_SCOPE)
  set(${out_stdout} "${o}" PARENT_SCOPE)
  set(${out_stderr} "${e}" PARENT_SCOPE)
endfunction()

# 5 s settle + 3594 s + 1 s rest = 3600 s: the largest plan allowed.
run_limited(c o e run --axis x --freq-hz 1 --amp-deg 3 --settle-s 5 --duration-s 3594 --out ${dir}/hour.fbs)
if(NOT c EQUAL 0 OR NOT o MATCHES "measured lag" OR NOT o MATCHES "verdict: PASS")
  message(FATAL_ERROR "the largest allowed plan did not run in 1 GB (exit ${c}):\n${e}\n${o}")
endif()
run_limited(c o e analyze ${dir}/hour.fbs --no-store)
if(NOT c EQUAL 0 OR NOT o MATCHES "measured lag")
  message(FATAL_ERROR "the session of the largest allowed plan did not analyse in 1 GB (exit ${c}):\n${e}\n${o}")
endif()
# Its diagnosis (on 2 threads it aborted with bad_alloc under this limit):
# the replays run on as many threads as the budget allows, and say so.
run_limited(c o e diagnose ${dir}/hour.fbs --seeds 2)
if(NOT c EQUAL 0 OR NOT o MATCHES "Verdict: " OR NOT o MATCHES "ran on 1 of the 2 threads asked for")
  message(FATAL_ERROR "the session of the largest allowed plan did not diagnose in 1 GB (exit ${c}):\n${e}\n${o}")
endif()

# One second more: refused before anything is simulated, in one line.
run_limited(c o e run --axis x --freq-hz 1 --amp-deg 3 --settle-s 5 --duration-s 3595)
if(NOT c EQUAL 2 OR NOT e MATCHES "^fogbench-cli: [^\n]*lasts 1\\.0+[0-9]* h in all; at most 1 h \\(every sample is held in memory\\)[^\n]*\n$")
  message(FATAL_ERROR "a plan over 1 h: expected exit 2 and one line, got ${c}:\n${e}")
endif()
# The 23.9-h plan of the issue.
run_limited(c o e run --axis x --freq-hz 0.1 --amp-deg 10 --settle-s 5 --duration-s 86034)
if(NOT c EQUAL 2 OR NOT e MATCHES "lasts 23\\.9 h in all; at most 1 h")
  message(FATAL_ERROR "the 23.9-h plan: expected exit 2 and a refusal, got ${c}:\n${e}")
endif()
# An allowed plan at four times the table rate would hold more samples than
# the budget: refused by the simulator before it starts.
run_limited(c o e run --axis x --freq-hz 1 --amp-deg 3 --duration-s 3000 --table-period-ms 0.25)
if(NOT c EQUAL 2 OR NOT e MATCHES "^fogbench-cli: [^\n]*table and IMU samples [^\n]*at most 6e\\+06[^\n]*\n$")
  message(FATAL_ERROR "a plan beyond the sample budget: expected exit 2 and one line, got ${c}:\n${e}")
endif()
file(REMOVE_RECURSE ${dir})
