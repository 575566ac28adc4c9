// Boost.Test's implementation, header-only, for the cross-compiled determinism_tests: no Boost
// library of the target architecture is needed (tests/support/test_main.cpp links Debian's
// shared one instead).
#define BOOST_TEST_MODULE tamias2d
#include <boost/test/included/unit_test.hpp>
