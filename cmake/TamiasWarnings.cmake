# Project-wide compiler flags: strict warnings, optional -Werror, sanitizers and coverage.
add_library(tamias_warnings INTERFACE)
target_compile_options(tamias_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                                 -Wno-sign-conversion)
# The solver's 4-lane packs (src/tamias2d/math/wide.hpp) are 32-byte vectors; GCC and Clang note
# that passing them by value would use another ABI with AVX enabled. They never cross a library
# boundary (everything taking them is inline), so the note says nothing here.
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(tamias_warnings INTERFACE -Wno-psabi)
endif()
if(TAMIAS_WERROR)
  target_compile_options(tamias_warnings INTERFACE -Werror)
endif()
if(TAMIAS_SANITIZE)
  # With the standard library's own bounds checks: ASan does not see an index past a vector's
  # size that stays within its capacity.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_definitions(_GLIBCXX_ASSERTIONS)
  add_link_options(-fsanitize=address,undefined)
endif()
if(TAMIAS_TSAN)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
if(TAMIAS_COVERAGE)
  add_compile_options(--coverage)
  add_link_options(--coverage)
endif()
