// The benchmark scenes, described once, engine-neutrally: every engine adapter
// (bench_engines.cpp) builds exactly this geometry, so Tamias2D, Chipmunk 7 and Box2D 2.4 see
// identical bodies, shapes, masses and initial states (Box2D v3, in a process of its own, gets
// the same description through a pipe: remote_engine.hpp).
//
// Layouts follow the project's scene generators (src/tamias2d/io/scene_generators.cpp) with
// the benchmark's parameters: pyramids start with every box exactly touching its neighbours
// (gap 0, as in Box2D v3's benchmark), rain uses the generator's container and grid. The joint
// scenes are in bench_joint_scenes.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace tamias_bench {

struct V2 {
    double x = 0.0, y = 0.0;
};

/// A rectangle of half extents hx, hy centred at `center` (body frame), rotated by `angle`.
struct BoxPart {
    V2 center{};
    double hx = 0.5, hy = 0.5;
    double angle = 0.0;
};

/// Material as a pair sees it: `friction` is the contact's Coulomb coefficient when both shapes
/// carry it (geometric-mean engines set it as is; Chipmunk multiplies, so it gets the square
/// root), likewise `restitution` (Tamias2D and Box2D take the max, Chipmunk multiplies).
struct BodyDesc {
    bool dynamic = true;
    V2 position{};
    double angle = 0.0;
    V2 velocity{};
    std::vector<BoxPart> boxes;
    double density = 1.0;
    double friction = 0.6;
    double restitution = 0.0;
    /// A dynamic body without boxes takes this mass (kg) and moment of inertia about its origin
    /// (kg m^2), its centre of mass at the origin: it collides with nothing.
    double mass = 0.0;
    double inertia = 0.0;
};

/// A revolute joint (a pin): bodies[a] and bodies[b] are held together at `anchor` (world frame
/// at creation, fixed in both bodies from then on).
struct JointDesc {
    int a = 0, b = 0;
    V2 anchor{};
};

enum class SceneKind : std::uint8_t { pyramid, rain, elastic, joints };

struct SceneDesc {
    std::string name;
    SceneKind kind = SceneKind::pyramid;
    V2 gravity{0.0, -10.0};
    double dt = 1.0 / 60.0;
    std::vector<BodyDesc> bodies;
    int dynamic_count = 0;
    // Quality probes.
    std::vector<int> tops;     ///< pyramid: the top box of each pyramid
    double inner_half_w = 0.0; ///< rain: container inner half width (m), floor at y = 0
    double wall_top = 0.0;     ///< rain: height of the container's walls (m), open above
    double box = 1.0;          ///< box side (m)
    double speed = 0.0;        ///< elastic: initial speed of each box (m s^-1)
    /// Sleeping on in every engine, each with a 0.5 s time to sleep (off in the floors' scenes).
    bool sleep = false;
    std::vector<JointDesc> joints;
    /// joints: a joint whose anchors are this far apart (m) has come apart (half the distance
    /// between a link's two pins); `mass_ratio` is the heavy body's mass over a link's (0: none).
    double apart_separation = 0.0;
    double mass_ratio = 0.0;
};

inline BodyDesc box_body(V2 p, double side, bool dynamic) {
    BodyDesc b;
    b.dynamic = dynamic;
    b.position = p;
    b.boxes.push_back({{}, 0.5 * side, 0.5 * side, 0.0});
    return b;
}

/// Base N boxes (side 1 m) on a static ground whose top face is y = 0; N (N + 1) / 2 boxes.
inline SceneDesc make_pyramid(const std::string& name, int base) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::pyramid;
    const double box = 1.0;
    s.box = box;
    const double ground_w = 2.0 * base * box + 10.0 * box;
    BodyDesc ground;
    ground.dynamic = false;
    ground.position = {0.0, -0.5 * box};
    ground.boxes.push_back({{}, 0.5 * ground_w, 0.5 * box, 0.0});
    s.bodies.push_back(ground);
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        const double y = 0.5 * box + row * box;
        for (int col = 0; col < n; ++col) {
            const double x = (col - 0.5 * (n - 1)) * box;
            s.bodies.push_back(box_body({x, y}, box, true));
        }
    }
    s.dynamic_count = base * (base + 1) / 2;
    s.tops.push_back(int(s.bodies.size()) - 1);
    return s;
}

/// Box2D v3's many_pyramids: `levels` x `columns` pyramids of base `base` (v3: 20 x 20 of base
/// 10, 22000 boxes of 1 m). The pyramids of a level stand 1 m apart, centred on x = 0, on a floor
/// 2 (base + 1) columns wide whose top face is y = 0 for the lowest level and (base + 1) m higher
/// for each next one, 1 m above the tops of the pyramids below. v3's floors are segments
/// (Tamias2D has none yet): here they are boxes 0.5 m thick with the same top faces, all on one
/// static body as in v3, so 0.5 m of air separates a floor from the tops under it.
inline SceneDesc make_many_pyramids(const std::string& name, int base, int levels, int columns) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::pyramid;
    const double box = 1.0, pitch = (base + 1) * box, floor = 0.5 * box;
    s.box = box;
    BodyDesc ground;
    ground.dynamic = false;
    for (int level = 0; level < levels; ++level) {
        ground.boxes.push_back(
            {{0.0, level * pitch - 0.5 * floor}, 0.5 * columns * pitch, 0.5 * floor, 0.0});
    }
    s.bodies.push_back(ground);
    for (int level = 0; level < levels; ++level) {
        for (int column = 0; column < columns; ++column) {
            const double middle = (column - 0.5 * (columns - 1)) * pitch;
            for (int row = 0; row < base; ++row) {
                const int n = base - row;
                const double y = level * pitch + (row + 0.5) * box;
                for (int col = 0; col < n; ++col) {
                    s.bodies.push_back(
                        box_body({middle + (col - 0.5 * (n - 1)) * box, y}, box, true));
                }
            }
            s.tops.push_back(int(s.bodies.size()) - 1);
        }
    }
    s.dynamic_count = levels * columns * base * (base + 1) / 2;
    return s;
}

/// splitmix64, as the scene generators use (same stream on every platform).
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
};

/// `count` boxes of 0.5 m on a grid (pitch 0.75 m, jitter +-0.1 m from splitmix64 seed 1)
/// falling into an open-top static container (walls `height` high and 1 m thick, inner floor
/// at y = 0, inner width `width`). The lowest row starts `first_row_y` above the floor.
inline SceneDesc make_rain(const std::string& name, int count, double width, double height,
                           double first_row_y) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::rain;
    const double box = 0.5, spacing = 1.5 * box, jitter = 0.2 * box, wall = 1.0;
    s.box = box;
    s.inner_half_w = 0.5 * width;
    s.wall_top = height;
    BodyDesc c;
    c.dynamic = false;
    c.boxes.push_back({{0.0, -0.5 * wall}, 0.5 * (width + 2.0 * wall), 0.5 * wall, 0.0});
    c.boxes.push_back({{-(0.5 * width + 0.5 * wall), 0.5 * height}, 0.5 * wall, 0.5 * height, 0.0});
    c.boxes.push_back({{0.5 * width + 0.5 * wall, 0.5 * height}, 0.5 * wall, 0.5 * height, 0.0});
    s.bodies.push_back(c);
    const int columns = std::max(1, int(std::floor(width / spacing)));
    SplitMix64 rng{1};
    for (int i = 0; i < count; ++i) {
        const int row = i / columns, col = i % columns;
        const double dx = jitter * (2.0 * rng.uniform() - 1.0);
        s.bodies.push_back(box_body(
            {(col - 0.5 * (columns - 1)) * spacing + dx, first_row_y + row * spacing}, box, true));
    }
    s.dynamic_count = count;
    return s;
}

/// The rain: 2000 boxes into a 40 m x 20 m container, the grid (53 columns, 38 rows) starting
/// 1 m above the walls' top, as the scene generator's defaults.
inline SceneDesc make_rain(const std::string& name, int count) {
    return make_rain(name, count, 40.0, 20.0, 20.0 + 1.0 + 0.25);
}

/// The scaling series: `count` boxes in 10 rows starting 1 m above the floor of a container
/// 10 m high and as wide as the rows (0.75 m per column). Every size has the same depth and
/// the same history (all boxes land within about 75 steps and pile up), so the work per box is
/// the same at every size and the series measures how the engine scales, not the scene.
inline SceneDesc make_wide_rain(const std::string& name, int count) {
    const int columns = (count + 9) / 10;
    return make_rain(name, count, 0.75 * columns, 10.0, 1.0 + 0.25);
}

/// Two 1 m boxes 3 m apart approaching head-on at 1 m/s each, C_R = 1, no gravity.
inline SceneDesc make_elastic_pair(const std::string& name) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::elastic;
    s.gravity = {0.0, 0.0};
    s.box = 1.0;
    s.speed = 1.0;
    for (const int side : {-1, 1}) {
        BodyDesc b = box_body({1.5 * side, 0.0}, 1.0, true);
        b.velocity = {-side * s.speed, 0.0};
        b.restitution = 1.0;
        s.bodies.push_back(b);
    }
    s.dynamic_count = 2;
    return s;
}

} // namespace tamias_bench
