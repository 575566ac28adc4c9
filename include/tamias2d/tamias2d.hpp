/// \file
/// Everything a game needs to simulate: include this one header and link tamias2d::tamias2d.
/// Scene files (tamias2d/io/scene.hpp) are a separate library, tamias2d::io.
#pragma once

#include "tamias2d/aabb.hpp"
#include "tamias2d/body_def.hpp"
#include "tamias2d/body_state.hpp"
#include "tamias2d/build_info.hpp"
#include "tamias2d/contact_info.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/mass_data.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/motion_locks.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/shapes.hpp"
#include "tamias2d/task_system.hpp"
#include "tamias2d/user_data.hpp"
#include "tamias2d/vec2.hpp"
#include "tamias2d/version.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_def.hpp"
