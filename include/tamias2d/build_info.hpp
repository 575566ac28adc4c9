/// \file
/// What the linked library is: its version and the instruction set its solver runs with.
#pragma once

#include "tamias2d/export.hpp"
#include "tamias2d/version.hpp"

namespace tamias2d {

/// The version of the compiled library, "major.minor.patch". It equals TAMIAS2D_VERSION when
/// the headers and the library come from the same build.
TAMIAS2D_EXPORT const char* library_version() noexcept;

/// The instruction set the contact solver's packs of four run with on this machine:
/// "x86-64-v4" (AVX-512), "avx2" or "sse2" on x86-64 (chosen when the program loads; all give
/// bitwise the same results), and "generic" on other processors.
TAMIAS2D_EXPORT const char* solver_instruction_set() noexcept;

} // namespace tamias2d
