#include "tamias2d/dynamics/joints/joint_rotations.hpp"

#include <algorithm>

#include "tamias2d/model/dd32_rotation.hpp"

namespace tamias2d {

void JointRotations::begin(std::size_t solver_bodies) {
    for (const Jointed& j : jointed_) // the last step's marks
        listed_[j.solver] = 0;
    jointed_.clear();
    rotations_.resize(solver_bodies);
    listed_.resize(solver_bodies); // all false: the marks are cleared above
}

std::uint32_t JointRotations::side(std::uint32_t solver, double phi, double dq0) {
    if (solver == 0) {
        rotations_.push_back(Rot::from_angle(phi + dq0));
        return std::uint32_t(rotations_.size() - 1);
    }
    if (!listed_[solver]) {
        listed_[solver] = 1;
        jointed_.push_back({solver, phi});
    }
    return solver;
}

void JointRotations::turn(const SolverBody* bodies, std::size_t first, std::size_t last) {
    // In chunks that stay in the first cache level; the angles gathered, turned in lanes, and
    // scattered back.
    constexpr std::size_t chunk = 128;
    double phi[chunk], c[chunk], s[chunk];
    for (std::size_t b = first; b < last; b += chunk) {
        const std::size_t n = std::min(chunk, last - b);
        for (std::size_t k = 0; k < n; ++k) {
            const Jointed& j = jointed_[b + k];
            phi[k] = j.angle + bodies[j.solver].dq;
        }
        model::dd32::rotations(phi, c, s, n);
        for (std::size_t k = 0; k < n; ++k)
            rotations_[jointed_[b + k].solver] = {c[k], s[k]};
    }
}

} // namespace tamias2d
