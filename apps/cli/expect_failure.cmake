# cmake -DEXE=<program> [-DINPUT=<file>] [-DSHOW=<file>] -P expect_failure.cmake -- <args...>
# Runs the program (with INPUT as its standard input), prints its output, then "exit code: N",
# then the contents of SHOW if given (a file the program wrote). The CTest entry's
# PASS_REGULAR_EXPRESSION checks the message and N (CTest ignores the exit status of a test that
# has a pass expression, so the status is checked through the text).
include(${CMAKE_CURRENT_LIST_DIR}/script_args.cmake)
set(input "")
if(DEFINED INPUT)
  set(input INPUT_FILE "${INPUT}")
endif()
if(DEFINED SHOW)
  file(REMOVE "${SHOW}")
endif()
execute_process(COMMAND "${EXE}" ${args} ${input} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}exit code: ${rc}")
if(DEFINED SHOW AND EXISTS "${SHOW}")
  file(READ "${SHOW}" shown)
  message("${SHOW}:\n${shown}")
endif()
