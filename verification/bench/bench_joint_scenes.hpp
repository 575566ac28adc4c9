// The joint scenes: bodies joined by revolute joints (pins) and nothing else, described once for
// every engine (bench_scenes.hpp).
//
// No body has a shape: each carries the mass and moment of inertia of the shape it stands for,
// and no scene has a contact. Box2D v3's joint_grid, which `joint_grid` follows, gives its
// circles a collision filter that keeps them from colliding with one another, so its grid has
// no contact either; the grid folds as it falls, so spacing alone cannot keep neighbours apart,
// and the shared description has no filter to give every engine. Leaving the shapes out makes
// the scenes identical and contact-free (the one difference from v3: its filtered shapes still
// cost it broad-phase updates, ours cost none). The chains have no shapes either, so that their
// drift is the joints' own, not a contact's push between folded links.
#pragma once

#include <numbers>
#include <string>

#include "bench_scenes.hpp"

namespace tamias_bench {

inline BodyDesc massive_point(V2 p, bool dynamic, double mass, double inertia) {
    BodyDesc b;
    b.dynamic = dynamic;
    b.position = p;
    b.mass = dynamic ? mass : 0.0;
    b.inertia = dynamic ? inertia : 0.0;
    return b;
}

/// Box2D v3's joint_grid: an n x n grid (v3: n = 100) of discs of radius 0.4 m and density 1 at
/// unit spacing, body (k, i) at (k, -i); each is pinned to its upper and left neighbours at the
/// midpoint between them. The seven middle bodies of the top row (k = n/2 - 3 ... n/2 + 3) are
/// static, so the grid hangs from them and folds down under gravity. The six pins between two of
/// those static bodies are left out: they join nothing that moves (and Chipmunk aborts on a
/// constraint between two static bodies, "unsolvable constraint").
inline SceneDesc make_joint_grid(const std::string& name, int n) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::joints;
    const double r = 0.4, m = std::numbers::pi * r * r, inertia = 0.5 * m * r * r;
    s.box = 2.0 * r;
    s.apart_separation = 0.5;
    const auto fixed = [n](int k, int i) { return i == 0 && k >= n / 2 - 3 && k <= n / 2 + 3; };
    const auto index = [n](int k, int i) { return k * n + i; };
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            s.bodies.push_back(massive_point({double(k), double(-i)}, !fixed(k, i), m, inertia));
            s.dynamic_count += fixed(k, i) ? 0 : 1;
            if (i > 0 && !(fixed(k, i - 1) && fixed(k, i)))
                s.joints.push_back({index(k, i - 1), index(k, i), {double(k), 0.5 - i}});
            if (k > 0 && !(fixed(k - 1, i) && fixed(k, i)))
                s.joints.push_back({index(k - 1, i), index(k, i), {k - 0.5, double(-i)}});
        }
    }
    return s;
}

/// A chain of `links` links, each a 1 m x 0.25 m box of density 1 (0.25 kg) pinned to the next
/// at its ends, the first pinned to a static body at the origin; laid out horizontally to the
/// right and released from rest, it swings down and hangs from the pin. With `mass_ratio` > 0,
/// a 1 m square `mass_ratio` times a link's mass hangs from the last link by the middle of its
/// near side: the drift test (light links holding a heavy body).
inline SceneDesc make_chain(const std::string& name, int links, double mass_ratio = 0.0) {
    SceneDesc s;
    s.name = name;
    s.kind = SceneKind::joints;
    const double len = 1.0, thick = 0.25;
    const double m = len * thick, inertia = m * (len * len + thick * thick) / 12.0;
    s.box = len;
    s.apart_separation = 0.5 * len;
    s.mass_ratio = mass_ratio;
    s.bodies.push_back(massive_point({}, false, 0.0, 0.0));
    for (int j = 0; j < links; ++j) {
        s.bodies.push_back(massive_point({(j + 0.5) * len, 0.0}, true, m, inertia));
        s.joints.push_back({j, j + 1, {j * len, 0.0}});
    }
    if (mass_ratio > 0.0) {
        const double side = 1.0, heavy = mass_ratio * m;
        s.bodies.push_back(
            massive_point({links * len + 0.5 * side, 0.0}, true, heavy, heavy * side * side / 6.0));
        s.joints.push_back({links, links + 1, {links * len, 0.0}});
    }
    s.dynamic_count = int(s.bodies.size()) - 1;
    return s;
}

} // namespace tamias_bench
