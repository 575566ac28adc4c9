// The busy soak of tamias_soak (--busy): see soak_busy.cpp.
#pragma once

namespace tamias2d::soak {

/// Runs the busy scene for `steps` steps; 0 when every check held, 1 (after a
/// FAIL line) if not.
int run_busy(long steps);

} // namespace tamias2d::soak
