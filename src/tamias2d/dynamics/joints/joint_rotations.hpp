// The rotations the joints read during a step (internal): one per moving body some joint holds,
// R(phi + dq) after each position half, and one per immovable side of a solved joint, its
// transform's all step. Every jointed body's rotation is computed anew after each position half
// from its angle at the step's start plus dq, the same sum the step ends on, so that its last
// one is the rotation the step leaves the body with (StepSolver::write_back takes it). They are
// computed together, a batch of DD32's rotations, whose sincos runs in the lanes of a vector
// register: one sincos per jointed body and substep, four at a time.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

class JointRotations {
  public:
    /// Starts a step's rotations for `solver_bodies` solver bodies: none jointed.
    void begin(std::size_t solver_bodies);
    /// The index of a joint side's rotation, for a body of angle phi at the step's start. A
    /// moving side's (solver > 0) is its solver body's, listed the first time the body is
    /// named; an immovable side (solver 0) gets one of its own, R(phi + dq0), dq0 the rotation
    /// of solver body 0 (which stands for every immovable body).
    std::uint32_t side(std::uint32_t solver, double phi, double dq0);
    /// The rotations by index (stable until the next begin).
    const Rot* data() const { return rotations_.data(); }
    /// How many moving bodies are jointed.
    std::size_t moving() const { return jointed_.size(); }
    /// Whether solver body `solver` is jointed (until the next begin), and its rotation.
    bool jointed(std::uint32_t solver) const { return listed_[solver] != 0; }
    Rot rotation(std::uint32_t solver) const { return rotations_[solver]; }
    /// Turns the jointed bodies [first, last) of moving() to R(phi + dq), dq their solver
    /// bodies' rotation so far in this step.
    void turn(const SolverBody* bodies, std::size_t first, std::size_t last);

  private:
    struct Jointed {
        std::uint32_t solver; ///< solver body
        double angle;         ///< rad, at the step's start
    };
    memory::vector<Jointed> jointed_;
    memory::vector<std::uint8_t> listed_; ///< per solver body: in jointed_
    memory::vector<Rot> rotations_;       ///< per solver body, then one per immovable side
};

} // namespace tamias2d
