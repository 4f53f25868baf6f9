# The memory budget of docs/reliability.md (1 GiB of address space) holds for
# the largest raw stream file the bench reads, and a larger one is refused
# before a byte is read (issue 29).
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/memory_budget_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
# The longest plan allowed (1 h in all): 3 590 s of the bench's stream, 133 MiB,
# under the 160 MiB bound.
execute_process(COMMAND ${CLI} run --axis x --freq-hz 1 --amp-deg 3 --duration-s 3590 --save-raw ${dir}/long.bin
                RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --save-raw failed (${c}): ${e}")
endif()
file(SIZE ${dir}/long.bin size)
if(size LESS 130000000)
  message(FATAL_ERROR "the stream is ${size} bytes, expected about 140 MB: the test no longer tests the bound")
endif()
execute_process(COMMAND sh -c "ulimit -v 1048576 && exec \"$0\" analyze \"$1\"" ${CLI} ${dir}/long.bin
                RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0 OR NOT o MATCHES "verdict: PASS")
  message(FATAL_ERROR "analyze of a ${size}-byte stream under 1 GiB of address space: exit ${c}\n${e}")
endif()
# One byte beyond the bound (a sparse file): refused at once, nothing read.
file(TOUCH ${dir}/huge.bin)
execute_process(COMMAND truncate -s 167772161 ${dir}/huge.bin RESULT_VARIABLE c)
execute_process(COMMAND sh -c "ulimit -v 1048576 && exec \"$0\" analyze \"$1\"" ${CLI} ${dir}/huge.bin
                RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
string(STRIP "${e}" e)
if(NOT c EQUAL 2 OR NOT e MATCHES "holds 167772161 bytes, more than the 160 MiB that a raw sampling-board stream may hold")
  message(FATAL_ERROR "a stream beyond the bound: expected exit 2 and the bound, got ${c}:\n${e}")
endif()
file(REMOVE_RECURSE ${dir})
