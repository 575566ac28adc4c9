# A document quotes an example program verbatim: fails when the quote and the built file differ.
file(READ ${DOC} readme)
file(READ ${EXAMPLE} example)
string(FIND "${readme}" "${example}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${DOC} does not quote ${EXAMPLE} verbatim")
endif()
