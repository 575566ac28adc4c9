# cmake -DEXE=<tamias2d> -DDOC=<markdown file> -DOUT=<json file> -P doc_example.cmake
# Extracts the first ```json block of DOC into OUT and runs `tamias2d validate OUT`, printing its
# output: the documentation's complete example is checked like any other scene.
file(READ "${DOC}" text)
string(FIND "${text}" "```json\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "no json block in ${DOC}")
endif()
math(EXPR start "${start} + 8")
string(SUBSTRING "${text}" ${start} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} json)
file(WRITE "${OUT}" "${json}")
execute_process(COMMAND "${EXE}" validate "${OUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}exit code: ${rc}")
