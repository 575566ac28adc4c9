// Floating-point std::to_chars and std::from_chars for emscripten 3.1.6's libc++ (LLVM 14),
// which has only the integer ones. scripts/build_wasm.sh includes this before every source
// (-include), so that the library's sources compile unchanged. The library uses them for one
// thing each: the shortest round-trip text of a value in error messages (errors.hpp) and the
// numbers of a "1/60" dt string (io/scene_reader.cpp), which strtod (correctly rounded in musl,
// the libc emscripten uses) reads to the same double.
#pragma once

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#if defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 15000

namespace std {

/// The shortest "%.Ng" text that reads back as v (to_chars' own form differs at most in the
/// choice between fixed and exponent notation).
inline to_chars_result to_chars(char* first, char* last, double v) {
    char buf[40];
    int n = 0;
    if (std::isnan(v)) {
        n = std::snprintf(buf, sizeof buf, "%s", std::signbit(v) ? "-nan" : "nan");
    } else {
        for (int precision = 1; precision <= 17; ++precision) {
            n = std::snprintf(buf, sizeof buf, "%.*g", precision, v);
            if (std::strtod(buf, nullptr) == v)
                break;
        }
    }
    if (n < 0 || n > last - first)
        return {last, errc::value_too_large};
    std::memcpy(first, buf, static_cast<size_t>(n));
    return {first + n, errc{}};
}

/// As from_chars with chars_format::general: no leading space or '+', no "0x" prefix (then
/// only the "0" is read), out-of-range values reported as result_out_of_range.
inline from_chars_result from_chars(const char* first, const char* last, double& value,
                                    chars_format = chars_format::general) {
    const string text(first, last);
    const char* s = text.c_str();
    if (text.empty() || text[0] == '+' || text[0] == ' ' || (text[0] >= '\t' && text[0] <= '\r'))
        return {first, errc::invalid_argument};
    const size_t sign = text[0] == '-' ? 1 : 0;
    if (text.size() > sign + 1 && text[sign] == '0' &&
        (text[sign + 1] == 'x' || text[sign + 1] == 'X')) {
        value = sign != 0 ? -0.0 : 0.0;
        return {first + sign + 1, errc{}};
    }
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s, &end);
    if (end == s)
        return {first, errc::invalid_argument};
    if (errno == ERANGE)
        return {first + (end - s), errc::result_out_of_range};
    value = v;
    return {first + (end - s), errc{}};
}

} // namespace std

#endif
