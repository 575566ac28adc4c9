// The World calls that change a body's transform, velocities or loads, each with valid
// arguments: for the tests that every such call checks its handle (validation/test_handles.cpp)
// and wakes a sleeping body (engine/test_sleep.cpp).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tamias2d/world.hpp"

namespace tamias2d::test {

using BodyCall = std::pair<std::string, std::function<void(World&, BodyId)>>;

inline std::vector<BodyCall> body_changes() {
    return {
        {"set_transform",
         [](World& w, BodyId id) {
             w.set_transform(id, {1.0, 1.0}, 0.5);
         }},
        {"set_velocity",
         [](World& w, BodyId id) {
             w.set_velocity(id, {1.0, 0.0});
         }},
        {"set_angular_velocity", [](World& w, BodyId id) { w.set_angular_velocity(id, 1.0); }},
        {"set_force",
         [](World& w, BodyId id) {
             w.set_force(id, {1.0, 0.0});
         }},
        {"set_torque", [](World& w, BodyId id) { w.set_torque(id, 1.0); }},
        {"apply_force",
         [](World& w, BodyId id) {
             w.apply_force(id, {1.0, 0.0}, {0.0, 0.0});
         }},
        {"apply_torque", [](World& w, BodyId id) { w.apply_torque(id, 1.0); }},
        {"apply_impulse",
         [](World& w, BodyId id) {
             w.apply_impulse(id, {1.0, 0.0}, {0.0, 0.0});
         }},
        {"set_load",
         [](World& w, BodyId id) { w.set_load(id, [](double) {
                                       return Load{{1.0, 0.0}, 0.0};
                                   }); }},
    };
}

} // namespace tamias2d::test
