/// \file
/// The library's precompiled header (TAMIAS_LIBRARY_PCH, CMake's target_precompile_headers):
/// the standard and Boost.Units headers that most of its files include, parsed once per build
/// rather than once per file. Headers from outside the project only, so that a change to any of
/// its own files (an edit, a mutant, a module perturbed) never rebuilds it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/units/quantity.hpp>
#include <boost/units/systems/si.hpp>
