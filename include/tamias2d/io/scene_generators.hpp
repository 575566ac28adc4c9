/// \file
/// Generators for large or standard scenes: a pyramid of boxes on a static ground, a rain of
/// boxes into an open-top container, and a head-on elastic pair. Each returns plain SceneBody
/// values (the scene parser expands a {"generator": ...} entry into them), so a generated scene
/// is an ordinary scene. Parameters are validated first: ValidationError names the parameter by
/// its scene-file key ("base", "container.width", ...) and the data constraint it breaks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tamias2d/io/export.hpp"
#include "tamias2d/io/scene.hpp"

namespace tamias2d::io {

/// Base N boxes on the ground, N - 1 on them, ..., 1 at the top: N (N + 1) / 2 boxes, each row
/// centred over the one below (so offset by half a box), plus one static ground box whose top
/// face is at origin.y. Rows and neighbours start `gap` apart so the stack settles cleanly:
/// row r (0 at the bottom) is centred at y = origin.y + gap + box / 2 + r (box + gap).
struct PyramidParams {
    std::string name = "pyramid";        ///< body names: "<name>/ground", "<name>/r<row>c<col>"
    static constexpr int max_base = 500; ///< 125 250 boxes
    int base = 20;                       ///< boxes in the bottom row, in [1, max_base]
    double box = 1.0;                    ///< m, box side (> 0)
    double gap = 0.001;                  ///< m, between neighbours and between rows (>= 0)
    Vec2d origin{};                      ///< m, centre of the ground's top face
    double ground_width = 0.0;           ///< m, 0: automatic (2 base box + 10 box)
    double ground_height = 0.0;          ///< m, 0: automatic (box)
    Material material{1.0, 0.0, 0.6};    ///< of every box (the ground's too)
};
/// The pyramid's bodies, ground first then the rows bottom-up, each left to right; throws
/// ValidationError for a parameter out of range.
TAMIAS2D_IO_EXPORT std::vector<SceneBody> generate_pyramid(const PyramidParams& p);

/// An open-top static container of three boxes (floor and two walls, one body) whose inner
/// floor is centred at `origin`.
struct ContainerParams {
    double width = 40.0;  ///< m, inner width (> box)
    double height = 20.0; ///< m, inner height of the walls (> 0)
    double wall = 1.0;    ///< m, thickness of floor and walls (> 0)
    Vec2d origin{};       ///< m, centre of the inner floor surface
};

/// `count` boxes on a grid above the container: columns `spacing` apart across its inner width,
/// rows `spacing` apart upwards from `drop_height` above the walls' top, each box shifted
/// horizontally by a deterministic jitter in [-jitter, jitter] drawn from `seed` (splitmix64,
/// the same on every platform). Bodies: the container first, then the boxes row by row.
struct RainParams {
    std::string name = "rain";               ///< body names: "<name>/container", "<name>/<index>"
    static constexpr int max_count = 200000; ///< the largest `count` accepted
    int count = 2000;                        ///< boxes, in [0, max_count]
    double box = 0.5;                        ///< m, box side (> 0)
    double spacing = 0.0;             ///< m, grid pitch; 0: automatic (1.5 box); must exceed box
    double jitter = -1.0;             ///< m, < 0: automatic (0.2 box); 2 jitter < spacing - box
    double drop_height = 1.0;         ///< m, clearance between the walls' top and the lowest row
    std::uint64_t seed = 1;           ///< of the jitter's random stream (SplitMix64)
    ContainerParams container{};      ///< where the boxes fall into
    Material material{1.0, 0.0, 0.6}; ///< of every box and of the container
};
/// The container and the falling boxes; throws ValidationError for a parameter out of range.
TAMIAS2D_IO_EXPORT std::vector<SceneBody> generate_rain(const RainParams& p);

/// Two equal square boxes on the x axis, approaching head-on: "<name>/left" at
/// (-distance / 2, 0) with velocity (+speed, 0) and "<name>/right" at (+distance / 2, 0) with
/// (-speed, 0). Restitution 1, friction 0 and gravity_scale 0 (no gravity): momentum and
/// kinetic energy are conserved and the bodies exchange velocities (GD1, DD12).
struct ElasticPairParams {
    std::string name = "elastic"; ///< body names: "<name>/left", "<name>/right"
    double box = 1.0;             ///< m, side (> 0)
    double speed = 1.0;           ///< m s^-1, of each box (finite)
    double distance = 3.0;        ///< m, between the centres (> box)
    double density = 1.0;         ///< kg m^-2 (> 0)
    double restitution = 1.0;     ///< C_R of both boxes (DD12), in [0, 1]
};
/// The two boxes, left first; throws ValidationError for a parameter out of range.
TAMIAS2D_IO_EXPORT std::vector<SceneBody> generate_elastic_pair(const ElasticPairParams& p);

/// The generators' deterministic random stream: splitmix64, uniform doubles in [0, 1).
struct TAMIAS2D_IO_EXPORT SplitMix64 {
    std::uint64_t state;  ///< the seed, then the stream's position
    std::uint64_t next(); ///< the next 64 random bits
    double uniform();     ///< 53 random bits / 2^53
};

} // namespace tamias2d::io
