// How a libFuzzer target reports a broken promise: a message on stderr, then abort(), which
// libFuzzer records as a crash (and saves the input), and which fails the replay test.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace tamias2d::fuzz {

[[noreturn]] inline void broken_promise(const std::string& what) {
    std::fprintf(stderr, "tamias2d fuzz: broken promise: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

} // namespace tamias2d::fuzz
