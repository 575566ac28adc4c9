// The headers nearly every test translation unit parses (Boost.Test, Boost.Units through the
// unit layer, the world): precompiled once per build and reused by every test executable, which
// roughly halves the test suite's compile time on two cores (scripts/test.sh, the main job's
// coverage build). Tests still include what they use; this only makes it cheaper.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/quantities.hpp"
#include "tamias2d/units/vec2.hpp"
#include "tamias2d/world.hpp"
