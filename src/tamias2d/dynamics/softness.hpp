// Soft constraint coefficients (Catto, "Solver2D" / "Soft Step", 2024): a contact (IM7) or a
// joint (IM6) behaves like a damped spring of stiffness `hertz` and `damping_ratio`, solved
// implicitly over a substep h, which removes overlap smoothly instead of Baumgarte's
// energy-adding kicks.
#pragma once

#include "tamias2d/model/dd37_joint_tuning.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/model/im7_soft_contact.hpp"

namespace tamias2d {

struct Softness {
    double bias_rate = 0.0;     ///< s^-1: velocity bias per metre of overlap
    double mass_scale = 1.0;    ///< fraction of the rigid impulse applied
    double impulse_scale = 0.0; ///< fraction of the accumulated impulse relaxed away
};

/// IM7's coefficients (model/im7_soft_contact.hpp), unwrapped; once per step and constraint.
inline Softness make_softness(double hertz, double damping_ratio, double h) {
    namespace u = tamias2d::units;
    const model::im7::Softness s = model::im7::softness(
        u::from_value<u::Rate>(hertz), u::from_value<u::Dimensionless>(damping_ratio),
        u::from_value<u::Time>(h));
    return {s.bias_rate.value(), s.mass_scale.value(), s.impulse_scale.value()};
}

/// IM6's coefficients of a joint's spring (the same as IM7's), unwrapped; once per step and joint.
inline Softness make_joint_softness(double hertz, double damping_ratio, double h) {
    namespace u = tamias2d::units;
    const model::im6::Softness s = model::im6::softness(
        u::from_value<u::Rate>(hertz), u::from_value<u::Dimensionless>(damping_ratio),
        u::from_value<u::Time>(h));
    return {s.bias_rate.value(), s.mass_scale.value(), s.impulse_scale.value()};
}

/// DD37's softness of a joint with a tuning of its own (hertz, damping ratio), capped as the
/// world's is (n substeps of dt, each h), unwrapped; once per step and tuned joint.
inline Softness make_tuned_joint_softness(double hertz, double damping_ratio, int substeps,
                                          double dt, double h) {
    namespace u = tamias2d::units;
    const model::im6::Softness s = model::dd37::softness(
        {u::from_value<u::Rate>(hertz), u::from_value<u::Dimensionless>(damping_ratio)}, substeps,
        u::from_value<u::Time>(dt), u::from_value<u::Time>(h));
    return {s.bias_rate.value(), s.mass_scale.value(), s.impulse_scale.value()};
}

/// IM7's frequency cap: a quarter of the substep rate (Hz).
inline double capped_frequency(double hertz, int substeps, double dt) {
    namespace u = tamias2d::units;
    return model::im7::frequency(u::from_value<u::Rate>(hertz), substeps,
                                 u::from_value<u::Time>(dt))
        .value();
}

/// IM6's frequency cap of the joints' spring: the contacts' (Hz).
inline double capped_joint_frequency(double hertz, int substeps, double dt) {
    namespace u = tamias2d::units;
    return model::im6::frequency(u::from_value<u::Rate>(hertz), substeps,
                                 u::from_value<u::Time>(dt))
        .value();
}

} // namespace tamias2d
