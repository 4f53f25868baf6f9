# A session whose SQLite header is damaged is never analysed as a raw stream
# (issue 15: report printed PASS with a wrong IMU delay): analyze, report,
# noise and diagnose refuse it with one line saying how to recover, and
# sessions lists it as unreadable. The same for a session whose whole first
# page (4 KiB: header and schema) is zeroed (issue 29: it was decoded as a
# raw stream, through the database pages).
#   -DCLI=path -DDIR=scratch folder [-DHAVE_REPORT=ON]
set(dir ${DIR}/damaged_header_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(s ${dir}/hit.fbs)
execute_process(COMMAND ${CLI} run --axis z --freq-hz 1 --amp-deg 3 --duration-s 12 --seed 5 --out ${s}
                RESULT_VARIABLE c OUTPUT_QUIET ERROR_VARIABLE e)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "run --out failed (${c}): ${e}")
endif()
file(COPY_FILE ${s} ${dir}/page.fbs)
# Zero the 16-byte magic "SQLite format 3\0".
execute_process(COMMAND dd if=/dev/zero of=${s} bs=16 count=1 conv=notrunc RESULT_VARIABLE c ERROR_QUIET)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "dd failed")
endif()

# The whole first page of the copy.
execute_process(COMMAND dd if=/dev/zero of=${dir}/page.fbs bs=4096 count=1 conv=notrunc RESULT_VARIABLE c ERROR_QUIET)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "dd failed")
endif()

set(expected "session whose SQLite header .* is damaged.*not analysed as a raw stream.*dd of=COPY")
function(expect_refused)
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
  string(STRIP "${e}" e)
  if(NOT c EQUAL 2 OR NOT e MATCHES "${expected}" OR e MATCHES "\n")
    message(FATAL_ERROR "'${ARGN}': expected exit 2 and one line matching '${expected}', got ${c}:\n${e}\n${o}")
  endif()
endfunction()

expect_refused(analyze ${s})
expect_refused(analyze ${s} --json)
expect_refused(noise ${s})
expect_refused(diagnose ${s})
if(HAVE_REPORT)
  expect_refused(report ${s} --pdf ${dir}/hit.pdf)
endif()

set(expected "session whose first page .* is damaged; it is not analysed as a raw stream .*Restore it from a backup")
set(s ${dir}/page.fbs)
expect_refused(analyze ${s})
expect_refused(noise ${s})
expect_refused(diagnose ${s})
if(HAVE_REPORT)
  expect_refused(report ${s} --pdf ${dir}/page.pdf)
endif()

execute_process(COMMAND ${CLI} sessions ${dir} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e)
if(NOT c EQUAL 0 OR NOT o MATCHES "hit\\.fbs.*unreadable: .*header.*damaged" OR NOT o MATCHES "0 other files skipped"
   OR NOT o MATCHES "page\\.fbs.*unreadable: .*first page.*damaged")
  message(FATAL_ERROR "sessions should list hit.fbs as unreadable (${c}):\n${o}${e}")
endif()
