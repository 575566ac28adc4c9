# Runs EXE with ARGS ("|"-separated), prints its output followed by "exit code: N". The CTest
# entry's PASS_REGULAR_EXPRESSION checks both the message and a non-zero N (CTest ignores the
# exit status of a test that has a pass expression, so the status is checked through the text).
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}exit code: ${rc}")
