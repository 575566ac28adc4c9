# Verification programs (GSL references, peer comparisons, benchmarks) run by the main job.
# Each is called as `<program> <out_dir>` and writes <out_dir>/<name>.json in the schema of
# docs/traceability.md. Registered programs are listed in <build>/verification_programs.txt.
# Every program links tamias_provenance: the commit and build id its results carry.
function(_tamias_provenance)
  if(TARGET tamias_provenance)
    return()
  endif()
  add_custom_target(tamias_provenance_stamp
                    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                            -DOUT_DIR=${CMAKE_BINARY_DIR}
                            -P ${PROJECT_SOURCE_DIR}/cmake/TamiasProvenance.cmake
                    BYPRODUCTS ${CMAKE_BINARY_DIR}/provenance.cpp ${CMAKE_BINARY_DIR}/provenance.json
                    VERBATIM)
  add_library(tamias_provenance STATIC ${CMAKE_BINARY_DIR}/provenance.cpp)
  add_dependencies(tamias_provenance tamias_provenance_stamp)
  target_include_directories(tamias_provenance PUBLIC ${PROJECT_SOURCE_DIR}/verification)
endfunction()

function(tamias_add_verification_program target)
  _tamias_provenance()
  target_link_libraries(${target} PRIVATE tamias_provenance)
  set_property(GLOBAL APPEND PROPERTY TAMIAS_VERIFICATION_PROGRAMS "$<TARGET_FILE:${target}>")
endfunction()

function(tamias_write_verification_list)
  get_property(programs GLOBAL PROPERTY TAMIAS_VERIFICATION_PROGRAMS)
  list(JOIN programs "\n" text)
  file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/verification_programs.txt CONTENT "${text}\n")
endfunction()
