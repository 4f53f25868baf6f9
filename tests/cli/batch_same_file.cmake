# A batch names each file once, however it was named: a folder given as
# "in" and "./in", a symbolic link to it, and a file inside it given again
# are one set of sessions, each analysed once (one line, one new result),
# never by two jobs at once; a rerun naming them otherwise resumes.
#   -DCLI=path -DDIR=scratch folder
set(dir ${DIR}/batch_same_file)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/in)
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/batch_lines.cmake)

foreach(seed 1 2)
  run_expect(0 o run --preset quick --speed 0 --seed ${seed} --out ${dir}/in/s${seed}.fbs)
endforeach()
file(CREATE_LINK ${dir}/in ${dir}/link SYMBOLIC)

# Run from ${dir}: "in", "./in", "link", "in/s1.fbs" and its absolute path.
execute_process(COMMAND ${CLI} batch in ./in link in/s1.fbs ${dir}/in/./s1.fbs --jsonl out.jsonl --jobs 4
                        --read-delay-ms 0.06
                WORKING_DIRECTORY ${dir} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "batch: expected exit 0, got ${c}: ${e}\n${o}")
endif()
expect_match("${o}" "batch of 2 files into out.jsonl: 2 stored" "batch of one folder named five ways")
batch_lines(${dir}/out.jsonl lines)
list(LENGTH lines n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "out.jsonl: expected a header and 2 lines, got ${n}:\n${lines}")
endif()
# Each session holds its run's result and one of the batch, no more.
run_expect(0 o sessions ${dir}/in --json)
foreach(i 0 1)
  string(JSON results GET "${o}" sessions ${i} results)
  if(NOT results EQUAL 2)
    string(JSON f GET "${o}" sessions ${i} file)
    message(FATAL_ERROR "${f}: ${results} results, expected 2 (the run's, the batch's once)")
  endif()
endforeach()

# The same batch named through the link: nothing left to do.
execute_process(COMMAND ${CLI} batch link --jsonl out.jsonl --read-delay-ms 0.06
                WORKING_DIRECTORY ${dir} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "batch resumed through the link: expected exit 0, got ${c}: ${e}\n${o}")
endif()
expect_match("${o}" "0 stored, 0 already stored, 0 refused, 2 skipped \\(listed before\\)" "batch resumed through the link")
