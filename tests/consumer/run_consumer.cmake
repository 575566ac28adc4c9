cmake_minimum_required(VERSION 3.25)
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DEXAMPLE_EXE=... -DRUNNER_EXE=...
#       -DSCENE=... -DMODES="install;pkgconfig;fetchcontent;shared" [-DCXX=...]
#       [-DVERSION=... -DLIBRARY_OPTIONS=... -DMORE_SCENES=...] -P run_consumer.cmake
# CXX: the compiler of the build tree (default c++), for the consumers too: a FetchContent
# build compiles the library again, and its build line (the solver's code path) must match.
# Installs the build tree into WORK_DIR/prefix and builds a separate project against it (the
# CMake package, then the pkg-config file), and against the source tree through FetchContent.
# shared: builds the library alone as shared libraries (-DBUILD_SHARED_LIBS=ON, with the
# build tree's options, LIBRARY_OPTIONS: "-DA=1|-DB=2"), installs them into WORK_DIR/shared-prefix
# and builds the consumer against them (CMake package and pkg-config), which also runs
# MORE_SCENES ("a.json|b.json"); VERSION: the project's.
# Oracle: each consumer's programs print exactly what the same programs built inside the
# project's own tree print (same source, same library: the same bits).
foreach(v BUILD_DIR SOURCE_DIR WORK_DIR EXAMPLE_EXE RUNNER_EXE SCENE MODES)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_consumer.cmake: -D${v}=... is required")
  endif()
endforeach()
if(NOT DEFINED CXX)
  find_program(CXX NAMES c++ g++ clang++ REQUIRED)
endif()
set(example_src ${SOURCE_DIR}/apps/examples/two_bodies.cpp)
set(runner_src ${SOURCE_DIR}/tests/consumer/project/scene_runner.cpp)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(${EXAMPLE_EXE})
set(expected_example "${out}")
run(${RUNNER_EXE} ${SCENE})
set(expected_runner "${out}")

function(expect_same what exe)
  run(${exe} ${ARGN})
  if(what STREQUAL "example")
    set(expected "${expected_example}")
  else()
    set(expected "${expected_runner}")
  endif()
  if(NOT out STREQUAL expected)
    message(FATAL_ERROR "${exe} printed\n${out}\nbut the project's own build printed\n${expected}")
  endif()
  message(STATUS "OK: ${exe}")
endfunction()

set(prefix ${WORK_DIR}/prefix)
if("install" IN_LIST MODES OR "pkgconfig" IN_LIST MODES)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  # The exported target carries the no-contraction flag to the game's compilations.
  file(GLOB_RECURSE targets_file ${prefix}/tamias2dTargets.cmake)
  file(READ "${targets_file}" targets_text)
  if(NOT targets_text MATCHES "-ffp-contract=off")
    message(FATAL_ERROR "${targets_file} does not export -ffp-contract=off")
  endif()
  foreach(private units model dynamics collision geometry memory math)
    if(EXISTS ${prefix}/include/tamias2d/${private})
      message(FATAL_ERROR "the install holds the private headers' folder ${private}/")
    endif()
  endforeach()
endif()

if("install" IN_LIST MODES)
  set(b ${WORK_DIR}/package)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${b} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix}
      -DTAMIAS_CONSUMER_MODE=package
      -DTAMIAS_EXAMPLE=${example_src})
  run(${CMAKE_COMMAND} --build ${b})
  expect_same(example ${b}/two_bodies)
  expect_same(runner ${b}/scene_runner ${SCENE})
endif()

if("pkgconfig" IN_LIST MODES)
  file(GLOB_RECURSE pc_file ${prefix}/tamias2d.pc)
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  run(pkg-config --cflags --libs tamias2d)
  string(STRIP "${out}" core_flags)
  if(NOT core_flags MATCHES "-ffp-contract=off")
    message(FATAL_ERROR "pkg-config --cflags tamias2d lacks -ffp-contract=off: ${core_flags}")
  endif()
  separate_arguments(core_flags UNIX_COMMAND "${core_flags}")
  run(pkg-config --cflags --libs tamias2d-io)
  string(STRIP "${out}" io_flags)
  separate_arguments(io_flags UNIX_COMMAND "${io_flags}")
  # The run path: a shared build tree installs .so files outside the loader's search path.
  get_filename_component(lib_dir "${pc_dir}" DIRECTORY)
  run(${CXX} -std=c++20 -O2 ${example_src} ${core_flags} -Wl,-rpath,${lib_dir}
      -o ${WORK_DIR}/two_bodies_pc)
  expect_same(example ${WORK_DIR}/two_bodies_pc)
  run(${CXX} -std=c++20 -O2 ${runner_src} ${io_flags} -Wl,-rpath,${lib_dir}
      -o ${WORK_DIR}/scene_runner_pc)
  expect_same(runner ${WORK_DIR}/scene_runner_pc ${SCENE})
endif()

if("fetchcontent" IN_LIST MODES)
  set(b ${WORK_DIR}/fetchcontent)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${b} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DTAMIAS_CONSUMER_MODE=fetchcontent
      -DTAMIAS_SOURCE_DIR=${SOURCE_DIR} -DTAMIAS_EXAMPLE=${example_src})
  run(${CMAKE_COMMAND} --build ${b} -j2)
  expect_same(example ${b}/two_bodies)
  expect_same(runner ${b}/scene_runner ${SCENE})
endif()

if("shared" IN_LIST MODES)
  foreach(v VERSION LIBRARY_OPTIONS)
    if(NOT DEFINED ${v})
      message(FATAL_ERROR "run_consumer.cmake: -D${v}=... is required for MODES=shared")
    endif()
  endforeach()
  foreach(tool readelf nm ldd)
    find_program(${tool}_exe ${tool} REQUIRED)
  endforeach()
  set(sb ${WORK_DIR}/shared-build)
  set(sp ${WORK_DIR}/shared-prefix)
  string(REPLACE "|" ";" library_options "${LIBRARY_OPTIONS}")
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${sb} -G Ninja -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_CXX_COMPILER=${CXX} -DBUILD_SHARED_LIBS=ON -DTAMIAS_BUILD_TESTS=OFF
      -DTAMIAS_BUILD_VERIFICATION=OFF -DTAMIAS_BUILD_APPS=OFF -DTAMIAS_INSTALL=ON
      ${library_options})
  run(${CMAKE_COMMAND} --build ${sb} -j2)
  run(${CMAKE_COMMAND} --install ${sb} --prefix ${sp})

  # Oracle: the ABI policy docs/user-guide.md states: before 1.0 the SONAME carries
  # major.minor (a minor version may break the ABI), from 1.0 on the major version.
  string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _ "${VERSION}")
  if(CMAKE_MATCH_1 EQUAL 0)
    set(abi ${CMAKE_MATCH_1}.${CMAKE_MATCH_2})
  else()
    set(abi ${CMAKE_MATCH_1})
  endif()

  # dynamic_entries(<result> <tag> <file>): the values of the file's SONAME or NEEDED entries.
  function(dynamic_entries result tag file)
    run(${readelf_exe} -d ${file})
    string(REGEX MATCHALL "\\(${tag}\\)[^\n]*\\[[^]\n]*\\]" lines "${out}")
    set(values "")
    foreach(l IN LISTS lines)
      string(REGEX REPLACE ".*\\[([^]]*)\\]" "\\1" v "${l}")
      list(APPEND values ${v})
    endforeach()
    set(${result} "${values}" PARENT_SCOPE)
  endfunction()

  # The names the public headers declare (comments stripped): what an exported symbol may name;
  # and those of the validation functions and the sine the scene library calls in the physics
  # library (src/tamias2d/validation.hpp and math/sincos.hpp say why they are exported).
  function(declared_names result)
    set(names operator)
    foreach(h IN LISTS ARGN)
      file(READ ${h} text)
      string(REGEX REPLACE "//[^\n]*" "" text "${text}")
      string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" ids "${text}")
      list(APPEND names ${ids})
    endforeach()
    list(REMOVE_DUPLICATES names)
    set(${result} "${names}" PARENT_SCOPE)
  endfunction()
  file(GLOB_RECURSE headers ${SOURCE_DIR}/include/tamias2d/*.hpp)
  declared_names(public_names ${headers})
  declared_names(validation_names ${SOURCE_DIR}/src/tamias2d/validation.hpp
                                  ${SOURCE_DIR}/src/tamias2d/math/sincos.hpp)

  foreach(lib tamias2d tamias2d_io)
    file(GLOB_RECURSE so ${sp}/lib${lib}.so.${abi})
    if(NOT so)
      message(FATAL_ERROR "no lib${lib}.so.${abi} under ${sp}")
    endif()
    dynamic_entries(soname SONAME ${so})
    if(NOT soname STREQUAL "lib${lib}.so.${abi}")
      message(FATAL_ERROR "${so}: SONAME '${soname}', expected lib${lib}.so.${abi}")
    endif()
    dynamic_entries(needed NEEDED ${so})
    if(needed MATCHES "boost|gsl|json")
      message(FATAL_ERROR "${so} needs ${needed}")
    endif()
    if(lib STREQUAL "tamias2d_io" AND NOT "libtamias2d.so.${abi}" IN_LIST needed)
      message(FATAL_ERROR "${so} does not need libtamias2d.so.${abi}: ${needed}")
    endif()
    # Oracle: the public headers. Every symbol the library exports names a declaration of theirs
    # (tamias2d::World::step, typeinfo for tamias2d::ValidationError, ...) or of validation.hpp
    # or math/sincos.hpp:
    # nothing else private to the engine, no Boost or nlohmann-json code. The one exception is
    # the standard library's own: libstdc++ declares namespace std visible, so that an instance
    # of its templates (and a static inside one) stays one per program; those are weak or
    # unique definitions (nm's W, V, u) of std:: or __gnu_cxx:: names. Nothing else is allowed.
    run(${nm_exe} -D --defined-only -C ${so})
    string(REPLACE "\n" ";" symbols "${out}")
    set(api 0)
    set(validation 0)
    set(standard 0)
    set(bad "")
    foreach(line IN LISTS symbols)
      if(NOT line MATCHES "^[0-9a-f]+ ([A-Za-z]) (.*)$")
        continue()
      endif()
      set(kind "${CMAKE_MATCH_1}")
      set(symbol "${CMAKE_MATCH_2}")
      string(REGEX REPLACE "^(typeinfo name for |typeinfo for |vtable for )" "" entity "${symbol}")
      string(REGEX REPLACE "\\[abi:[a-z0-9]+\\]" "" entity "${entity}")
      string(REGEX REPLACE "::operator.*" "::operator" entity "${entity}")
      string(REGEX REPLACE "[(<].*" "" entity "${entity}")
      string(REPLACE "::" ";" parts "${entity}")
      list(POP_FRONT parts first)
      if(symbol MATCHES "boost::|nlohmann::")
        string(APPEND bad "\n  ${symbol}")
      elseif(first STREQUAL "tamias2d")
        set(public TRUE)
        set(validating TRUE)
        foreach(p IN LISTS parts)
          string(REGEX REPLACE "^~" "" p "${p}")
          if(NOT p STREQUAL "io" AND NOT p IN_LIST public_names)
            set(public FALSE)
          endif()
          if(NOT p IN_LIST validation_names)
            set(validating FALSE)
          endif()
        endforeach()
        if(public)
          math(EXPR api "${api} + 1")
        elseif(validating AND lib STREQUAL "tamias2d")
          math(EXPR validation "${validation} + 1")
        else()
          string(APPEND bad "\n  ${symbol}")
        endif()
      elseif(first MATCHES "^(std|__gnu_cxx)$" AND kind MATCHES "^[WVu]$")
        math(EXPR standard "${standard} + 1")
      else()
        string(APPEND bad "\n  ${kind} ${symbol}")
      endif()
    endforeach()
    if(bad OR api EQUAL 0)
      message(FATAL_ERROR "${so} exports ${api} symbols of the API and these others:${bad}")
    endif()
    message(STATUS "OK: ${so}: SONAME ${soname}; exports ${api} symbols of the API, "
                   "${validation} validation and sine functions and ${standard} weak "
                   "standard-library "
                   "instances, nothing else")
  endforeach()

  # linked_shared(<exe> <library>): the program needs lib<library>.so.<abi>, and the dynamic
  # loader finds it in the shared prefix.
  function(linked_shared exe library)
    dynamic_entries(needed NEEDED ${exe})
    if(NOT "lib${library}.so.${abi}" IN_LIST needed)
      message(FATAL_ERROR "${exe} does not need lib${library}.so.${abi}: ${needed}")
    endif()
    run(${ldd_exe} ${exe})
    if(NOT out MATCHES "lib${library}\\.so\\.${abi} => ${sp}/")
      message(FATAL_ERROR "${exe}: lib${library}.so.${abi} is not loaded from ${sp}:\n${out}")
    endif()
  endfunction()

  set(b ${WORK_DIR}/shared-package)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${b} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${sp}
      -DTAMIAS_CONSUMER_MODE=package -DTAMIAS_EXAMPLE=${example_src})
  run(${CMAKE_COMMAND} --build ${b})
  linked_shared(${b}/two_bodies tamias2d)
  linked_shared(${b}/scene_runner tamias2d_io)
  expect_same(example ${b}/two_bodies)
  expect_same(runner ${b}/scene_runner ${SCENE})
  # More of the engine than SCENE reaches, each against the project's own runner's bits.
  string(REPLACE "|" ";" more_scenes "${MORE_SCENES}")
  foreach(scene IN LISTS more_scenes)
    run(${RUNNER_EXE} ${scene})
    set(expected "${out}")
    run(${b}/scene_runner ${scene})
    if(NOT out STREQUAL expected)
      message(FATAL_ERROR "${b}/scene_runner ${scene} printed\n${out}\nbut the project's own "
                          "build printed\n${expected}")
    endif()
    message(STATUS "OK: ${b}/scene_runner ${scene}")
  endforeach()

  file(GLOB_RECURSE pc_file ${sp}/tamias2d.pc)
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  get_filename_component(lib_dir "${pc_dir}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  run(pkg-config --cflags --libs tamias2d-io)
  string(STRIP "${out}" io_flags)
  separate_arguments(io_flags UNIX_COMMAND "${io_flags}")
  run(${CXX} -std=c++20 -O2 ${runner_src} ${io_flags} -Wl,-rpath,${lib_dir}
      -o ${WORK_DIR}/scene_runner_shared_pc)
  linked_shared(${WORK_DIR}/scene_runner_shared_pc tamias2d_io)
  expect_same(runner ${WORK_DIR}/scene_runner_shared_pc ${SCENE})
endif()
