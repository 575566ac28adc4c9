/// \file
/// A game's own value attached to the world, a body, a shape or a joint (World::set_user_data).
#pragma once

#include <cstdint>

namespace tamias2d {

/// An opaque pointer-sized value the library stores and hands back, never reads: a pointer to
/// the game's entity (`reinterpret_cast<UserData>(entity)`), an index or an id. It is not
/// simulation state: World::state_hash does not see it, and scene files do not store it.
/// 0, the default, is "none".
using UserData = std::uintptr_t;

} // namespace tamias2d
