# Verification programs (GSL references, peer comparisons, benchmarks) run by the main job.
# Each is called as `<program> <out_dir>` and writes <out_dir>/<name>.json in the schema of
# docs/traceability.md. Registered programs are listed in <build>/verification_programs.txt.
function(tamias_add_verification_program target)
  set_property(GLOBAL APPEND PROPERTY TAMIAS_VERIFICATION_PROGRAMS "$<TARGET_FILE:${target}>")
endfunction()

function(tamias_write_verification_list)
  get_property(programs GLOBAL PROPERTY TAMIAS_VERIFICATION_PROGRAMS)
  list(JOIN programs "\n" text)
  file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/verification_programs.txt CONTENT "${text}\n")
endfunction()
