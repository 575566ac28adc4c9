# cmake -DEXE=<program> -P expect_failure.cmake -- <args...>
# Runs the program, prints its output followed by "exit code: N". The CTest entry's
# PASS_REGULAR_EXPRESSION checks both the message and a non-zero N (CTest ignores the exit status
# of a test that has a pass expression, so the status is checked through the text).
set(args "")
set(after_separator FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(after_separator)
    list(APPEND args "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(after_separator TRUE)
  endif()
endforeach()
execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}exit code: ${rc}")
