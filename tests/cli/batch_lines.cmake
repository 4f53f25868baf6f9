# Reads the lines of a batch's OUT.jsonl into a CMake list in `out_var`. A
# line's ";" (an error message's) would split it: each is kept as "<semicolon>"
# and batch_line() gives it back.
function(batch_lines path out_var)
  file(READ ${path} text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REGEX REPLACE "\n$" "" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()
# One element of batch_lines' list as its JSON text.
function(batch_line element out_var)
  string(REPLACE "<semicolon>" ";" text "${element}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()
