# Existing files are never overwritten silently (issue 15): a session never,
# not even with --overwrite (report S.fbs --pdf S.fbs used to replace the
# session with a PDF); any other file only with --overwrite: --save-raw,
# --results-json, --pdf, --png-dir pages.
#   -DCLI=path -DDIR=scratch folder [-DHAVE_REPORT=ON]
set(dir ${DIR}/overwrite_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(s ${dir}/s.fbs)
set(run_args run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5)

function(expect exit needle)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT c EQUAL exit OR NOT "${e}" MATCHES "${needle}")
    message(FATAL_ERROR "'${ARGN}': expected exit ${exit} and '${needle}', got ${c}:\n${e}")
  endif()
endfunction()
function(expect_unchanged file content)
  file(READ ${file} now)
  if(NOT now STREQUAL content)
    message(FATAL_ERROR "${file} was overwritten")
  endif()
endfunction()

expect(0 "" ${run_args} --out ${s})
file(SHA256 ${s} session_hash)
file(WRITE ${dir}/keep.txt "precious\n")

# --save-raw
expect(2 "already exists; add --overwrite" ${run_args} --save-raw ${dir}/keep.txt)
expect_unchanged(${dir}/keep.txt "precious\n")
expect(2 "is a session.*never overwritten" ${run_args} --save-raw ${s} --overwrite)
expect(0 "" ${run_args} --save-raw ${dir}/keep.txt --overwrite)
# --results-json
file(WRITE ${dir}/keep.json "{}")
expect(2 "already exists; add --overwrite" export ${s} --results-json ${dir}/keep.json)
expect_unchanged(${dir}/keep.json "{}")
expect(2 "is a session.*never overwritten" export ${s} --results-json ${s} --overwrite)

if(HAVE_REPORT)
  expect(2 "is a session.*never overwritten" report ${s} --pdf ${s})
  expect(2 "is a session.*never overwritten" report ${s} --pdf ${s} --overwrite)
  file(WRITE ${dir}/old.pdf "old")
  expect(2 "already exists; add --overwrite" report ${s} --pdf ${dir}/old.pdf)
  expect_unchanged(${dir}/old.pdf "old")
  expect(0 "" report ${s} --pdf ${dir}/old.pdf --overwrite)
  file(MAKE_DIRECTORY ${dir}/pages)
  file(WRITE ${dir}/pages/report-page-1.png "old")
  expect(2 "report-page-1\\.png' already exists; add --overwrite" report ${s} --png-dir ${dir}/pages)
  expect_unchanged(${dir}/pages/report-page-1.png "old")
  expect(0 "" report ${s} --png-dir ${dir}/pages --overwrite)
endif()

file(SHA256 ${s} after)
if(NOT after STREQUAL session_hash)
  message(FATAL_ERROR "the session was changed")
endif()
