# A link to /dev/zero or /dev/urandom, or a FIFO, given as a session, a raw
# stream or an import file is refused at once with one line (issue 29: read
# until bad_alloc at 2.15 GB; a FIFO hung the command).
#   -DCLI=path -DDIR=scratch folder [-DHAVE_REPORT=ON]
set(dir ${DIR}/special_files_test)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir}/import)
file(CREATE_LINK /dev/zero ${dir}/zero.fbs SYMBOLIC)
file(CREATE_LINK /dev/urandom ${dir}/random.bin SYMBOLIC)
execute_process(COMMAND mkfifo ${dir}/pipe.bin RESULT_VARIABLE c)
if(NOT c EQUAL 0)
  message(FATAL_ERROR "mkfifo failed")
endif()
file(WRITE ${dir}/import/metadata.json
     "{\"bench\": {\"table_read_delay_ms\": 0.05, \"board_delay_ms\": 0.28, \"pulse_equivalent_deg\": 5e-5}, "
     "\"test_points\": [{\"axis\": \"x\"}]}")
file(CREATE_LINK /dev/urandom ${dir}/import/table.csv SYMBOLIC)
file(WRITE ${dir}/import/gyro.csv "time_s,x_inc_deg\n0.002,0.001\n")

function(expect_refused pattern)
  # The timeout catches a hang; a refusal takes milliseconds.
  execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE c OUTPUT_VARIABLE o ERROR_VARIABLE e TIMEOUT 30)
  string(STRIP "${e}" e)
  if(NOT c EQUAL 2 OR NOT e MATCHES "${pattern}" OR e MATCHES "\n")
    message(FATAL_ERROR "'${ARGN}': expected exit 2 and one line matching '${pattern}', got ${c}:\n${e}\n${o}")
  endif()
endfunction()

foreach(command analyze noise diagnose)
  expect_refused("zero\\.fbs \\(a link to /dev/zero\\) is a device, not a raw sampling-board stream" ${command} ${dir}/zero.fbs)
  expect_refused("random\\.bin \\(a link to /dev/urandom\\) is a device" ${command} ${dir}/random.bin)
  expect_refused("pipe\\.bin is a FIFO \\(named pipe\\)" ${command} ${dir}/pipe.bin)
endforeach()
if(HAVE_REPORT)
  expect_refused("is a device" report ${dir}/zero.fbs --pdf ${dir}/zero.pdf)
  expect_refused("is a FIFO" report ${dir}/pipe.bin --pdf ${dir}/pipe.pdf)
endif()
expect_refused("table\\.csv \\(a link to /dev/urandom\\) is a device, not an import file" import ${dir}/import --out ${dir}/i.fbs)
expect_refused("is a FIFO" run --plan ${dir}/pipe.bin)
if(EXISTS ${dir}/i.fbs)
  message(FATAL_ERROR "a refused import left ${dir}/i.fbs")
endif()
