// Boost.Test's implementation, header-only, for the cross-compiled determinism_tests and the
// WebAssembly one: no Boost library of the target architecture is needed
// (tests/support/test_main.cpp links Debian's shared one instead).
#define BOOST_TEST_MODULE tamias2d
#if defined(__EMSCRIPTEN__)
#define BOOST_TEST_DISABLE_ALT_STACK // emscripten has no sigaltstack
#endif
#include <boost/test/included/unit_test.hpp>
