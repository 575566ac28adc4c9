/// \file
/// The library's exceptions. Bad input is rejected before anything is mutated (R4), and the
/// error names the field, the offending value and the SRS data constraint it breaks, so a user
/// can fix the input and an auditor can trace the check to the SRS.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "tamias2d/export.hpp"

namespace tamias2d {

namespace detail {
/// Shortest round-trip text of a double ("-1", "0.1", "nan", "inf").
inline std::string format_value(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}
inline std::string validation_message(const std::string& field, double value,
                                      const std::string& rule, const std::string& constraint) {
    const std::string head = field + " = " + format_value(value) + ": ";
    return rule.empty() ? head + "violates " + constraint : head + rule + " (" + constraint + ")";
}
} // namespace detail

/// An input violates a data constraint (SRS section 5.2.6 and its extensions, R4).
struct TAMIAS2D_EXPORT ValidationError : std::invalid_argument {
    std::string field;      ///< e.g. "shape.radius"
    double value;           ///< the offending value (NaN for non-numeric defects)
    std::string constraint; ///< the SRS data-constraint label, e.g. "DCX_shape"

    /// what(): "shape.radius = -1: violates DCX_shape".
    ValidationError(std::string field_, double value_, std::string constraint_)
        : ValidationError(std::move(field_), value_, std::string{}, std::move(constraint_)) {}

    /// what(): "shape.radius = -1: must be > 0 (DCX_shape)". `rule` says what is required.
    ValidationError(std::string field_, double value_, const std::string& rule,
                    std::string constraint_)
        : std::invalid_argument(detail::validation_message(field_, value_, rule, constraint_)),
          field(std::move(field_)), value(value_), constraint(std::move(constraint_)) {}

    /// Selects the constructor of a defect that is not a number.
    struct NotANumber {};
    /// A defect that is not a number, such as the bodies a joint names: `value` is NaN and
    /// what() states no value: "joint.body_b: must be another body than body_a, body[1 'box']
    /// (DCX_joint)".
    ValidationError(NotANumber, std::string field_, const std::string& rule,
                    std::string constraint_)
        : std::invalid_argument(field_ + ": " + rule + " (" + constraint_ + ")"),
          field(std::move(field_)), value(std::numeric_limits<double>::quiet_NaN()),
          constraint(std::move(constraint_)) {}
};

/// A body, shape or proxy handle that is stale or was never issued (a use-after-free turned into
/// an error instead of a crash).
struct TAMIAS2D_EXPORT InvalidHandle : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

/// A handle that another World issued (its tag, BodyId::world, is not this world's): refused as
/// the mistake it is instead of naming whatever lives in the same slot of this world. Thrown
/// before anything changes. An InvalidHandle, so that code catching those catches it too.
struct TAMIAS2D_EXPORT WrongWorld : InvalidHandle {
    std::string handle;         ///< the handle, e.g. "BodyId 0:1"
    std::uint32_t handle_world; ///< the tag of the world that issued it
    std::uint32_t world;        ///< the tag of the world it was used with
    /// what(): "BodyId 0:1 was issued by world 3, not by this world (world 4)".
    WrongWorld(std::string handle_, std::uint32_t handle_world_, std::uint32_t world_)
        : InvalidHandle(handle_ + " was issued by world " + std::to_string(handle_world_) +
                        ", not by this world (world " + std::to_string(world_) + ")"),
          handle(std::move(handle_)), handle_world(handle_world_), world(world_) {}
};

/// A call that does not apply to what a valid handle names: a one-step force, torque or
/// impulse on a static or kinematic body (which no force moves), or a joint's angle, travel,
/// motor speed, target or offsets asked of a joint of a kind that has none. A mistake in the
/// calling code, not in its numbers: no data constraint is broken, so none is named. Thrown
/// before anything changes: the world is left exactly as it was.
struct WrongKind : std::invalid_argument {
    std::string call;    ///< the World member called, e.g. "apply_impulse"
    std::string subject; ///< what the handle names, e.g. "body[0 'ground']" or "joint[2]"
    std::string kind;    ///< what that is, e.g. "static body" or "distance joint"
    /// what(): "apply_impulse: body[0 'ground'] is a static body: must be a dynamic body ...";
    /// `rule` says what the call needs.
    WrongKind(std::string call_, std::string subject_, std::string kind_, const std::string& rule)
        : std::invalid_argument(call_ + ": " + subject_ + " is a " + kind_ + ": " + rule),
          call(std::move(call_)), subject(std::move(subject_)), kind(std::move(kind_)) {}
};

/// World::step could not solve the joints: a velocity or displacement turned non-finite
/// (conflicting joints on light bodies, beyond what the input rules foresee). The step is
/// refused: every body's state, every joint, the sleep states and the clock are as they were
/// before the call; the contacts were brought up to date with those unchanged poses (the next
/// step would compute the same), and the step reports no events.
struct TAMIAS2D_EXPORT SolverDivergence : std::runtime_error {
    std::string field; ///< the first body found diverged, e.g. "body[3 'slider'].velocity"
    /// what(): "body[3 'slider'].velocity: turned non-finite in the joints' solve; ...".
    SolverDivergence(std::string field_, const std::string& what)
        : std::runtime_error(what), field(std::move(field_)) {}
};

/// set_allocator or reset_allocator while the library holds blocks from the current allocator
/// (a World, Recorder or Replayer alive): a block must go back to the allocator it came from.
/// Nothing changes; the message gives the counts.
struct TAMIAS2D_EXPORT AllocatorInUse : std::logic_error {
    std::size_t blocks; ///< blocks held from the current allocator
    std::size_t bytes;  ///< their sizes' sum
    /// what(): "set_allocator: refused while the library holds 12 blocks (4096 bytes) ...".
    AllocatorInUse(std::size_t blocks_, std::size_t bytes_)
        : std::logic_error("set_allocator: refused while the library holds " +
                           std::to_string(blocks_) + " blocks (" + std::to_string(bytes_) +
                           " bytes) from the current allocator: destroy every World, Recorder "
                           "and Replayer first"),
          blocks(blocks_), bytes(bytes_) {}
};

} // namespace tamias2d
