# TAMIAS_FUZZ_TARGETS: the libFuzzer targets (tests/fuzz/libfuzzer), Clang only. The whole build
# is instrumented for libFuzzer's coverage feedback and for ASan and UBSan (every sanitizer
# report is fatal, so libFuzzer records it as a crash); scripts/fuzz.sh configures such a build
# in build-fuzz/. Another compiler is told so and builds no fuzz target.
set(TAMIAS_FUZZ_ENABLED OFF)
if(TAMIAS_FUZZ_TARGETS)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    set(TAMIAS_FUZZ_ENABLED ON)
    add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                        -fno-omit-frame-pointer)
    add_link_options(-fsanitize=address,undefined)
  else()
    message(WARNING "TAMIAS_FUZZ_TARGETS needs Clang (libFuzzer): the ${CMAKE_CXX_COMPILER_ID} "
                    "build makes no fuzz target")
  endif()
endif()
