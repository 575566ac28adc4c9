# Verification programs (GSL references, peer comparisons, benchmarks) run by the main job.
# Each is called as `<program> <out_dir>` and writes <out_dir>/<name>.json in the schema of
# docs/traceability.md. Registered programs are listed in <build>/verification_programs.txt.
# Every program links tamias_provenance: it reads <build>/provenance.json, which the build's last
# step writes (tamias_add_build_stamp), and stamps its results with it.
function(_tamias_provenance)
  if(TARGET tamias_provenance)
    return()
  endif()
  add_library(tamias_provenance STATIC ${PROJECT_SOURCE_DIR}/verification/provenance.cpp)
  target_include_directories(tamias_provenance PUBLIC ${PROJECT_SOURCE_DIR}/verification)
  target_compile_definitions(tamias_provenance
                             PRIVATE TAMIAS_PROVENANCE_JSON="${CMAKE_BINARY_DIR}/provenance.json")
  target_link_libraries(tamias_provenance PRIVATE nlohmann_json::nlohmann_json tamias_warnings)
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

# Every target of the build below dir (recursively), but interface libraries and targets left
# out of `all`.
function(_tamias_targets_in dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(dir_excluded DIRECTORY ${dir} PROPERTY EXCLUDE_FROM_ALL)
  set(kept "")
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    get_target_property(excluded ${t} EXCLUDE_FROM_ALL)
    if(NOT type STREQUAL "INTERFACE_LIBRARY" AND NOT excluded AND NOT dir_excluded)
      list(APPEND kept ${t})
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _tamias_targets_in(${sub} more)
    list(APPEND kept ${more})
  endforeach()
  set(${out} ${kept} PARENT_SCOPE)
endfunction()

# The build's last step: <build>/provenance.json (cmake/TamiasProvenance.cmake), written after
# every other target of `all` is built, so it describes a complete build. Called at the end of
# the top-level CMakeLists.txt.
function(tamias_add_build_stamp)
  _tamias_targets_in(${PROJECT_SOURCE_DIR} targets)
  file(STRINGS ${PROJECT_SOURCE_DIR}/scripts/debian-packages.txt packages REGEX "^[^#]")
  string(TOUPPER "${CMAKE_BUILD_TYPE}" config)
  get_cmake_property(variables CACHE_VARIABLES)
  set(options "CMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}")
  foreach(v IN LISTS variables)
    if(v MATCHES "^(TAMIAS_|BUILD_SHARED_LIBS$)")
      list(APPEND options "${v}=${${v}}")
    endif()
  endforeach()
  list(JOIN options " " options)
  add_custom_target(tamias_build_stamp ALL
                    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                            -DOUT_DIR=${CMAKE_BINARY_DIR}
                            "-DCOMPILER=${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} (${CMAKE_CXX_COMPILER})"
                            "-DFLAGS=${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${config}}"
                            "-DOPTIONS=${options}" "-DPACKAGES=${packages}"
                            -P ${PROJECT_SOURCE_DIR}/cmake/TamiasProvenance.cmake
                    VERBATIM)
  if(targets)
    add_dependencies(tamias_build_stamp ${targets})
  endif()
endfunction()
