// A joint as one step solves it (internal): what the warm start and the iterations read and
// write, contiguous, one record per solved joint in the step solver's array. The rest of the
// joint (its definition: limits, motor, springs) stays in its Joint, which a kind reads only
// when the part is enabled. A plain revolute joint's solve touches this record's first two
// cache lines and nothing of its Joint.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct alignas(64) JointSim {
    // First line: what every kind's solve reads.
    std::uint32_t solver_a = 0, solver_b = 0; ///< solver bodies (0: immovable this step)
    std::uint32_t joint = 0;                  ///< index in JointStore::joints: the definition
    JointType type = JointType::revolute;
    // The parts a revolute joint solves besides its pin, and whether the joint has its own
    // softness (DD37): the Joint's switches, copied so that a plain pin reads nothing else.
    bool spring : 1 = false, motor : 1 = false, limit : 1 = false, tuned : 1 = false;
    /// The bodies' rotations now (the step solver's, one per moving body, turned after each
    /// position half; an immovable side's stays as the step found it).
    const Rot* q_a = nullptr;
    const Rot* q_b = nullptr;
    Vec2d frame_a{}, frame_b{}; ///< m, the pin from each centre, body frame

    // Second line: the centres' offset, the softness and the step state's first field, the
    // pin's impulse.
    Vec2d center_offset{}; ///< m, p_B - p_A at the step's start
    Softness softness{};   ///< the rigid parts' soft bias: the world's (IM6) or the joint's (DD37)
    JointStepState step;   ///< the Joint's, solved here and written back once the step is accepted

    // Third and fourth lines: what only some kinds and parts read.
    double reference_angle = 0.0;        ///< rad, the Joint's (DD22)
    double angle_a = 0.0, angle_b = 0.0; ///< rad, the bodies' angles at the step's start
    Vec2d center_b{};                    ///< m, p_B at the step's start (target joint)
};

static_assert(sizeof(JointSim) == 256);
// The frames in the first line, the pin's impulse by the end of the second (with 4-byte
// pointers, as in WebAssembly, the fields sit 8 bytes earlier).
static_assert(offsetof(JointSim, frame_b) + sizeof(Vec2d) <= 64 &&
              offsetof(JointSim, step) + sizeof(Vec2d) <= 128);

} // namespace tamias2d
