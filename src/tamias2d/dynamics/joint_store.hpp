// The world's joints (internal): storage, slots and handles, and which bodies each joins (for
// the collision filter, the islands and a body's destruction). Box2D keeps the same concerns in
// joint.c.
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/dynamics/joint.hpp"
#include "tamias2d/handles.hpp"

namespace tamias2d {

class JointStore {
  public:
    std::vector<Joint> joints;

    /// The joint of a handle; throws InvalidHandle for a stale or unknown one.
    Joint& get(JointId id);
    const Joint& get(JointId id) const { return const_cast<JointStore*>(this)->get(id); }
    bool is_valid(JointId id) const;
    JointId id(std::uint32_t i) const { return {i, joints[i].generation}; }
    std::uint32_t live() const { return live_; }

    /// A slot for a joint whose fields (bodies, anchors, options) are set; returns its index.
    std::uint32_t create(const Joint& joint);
    void destroy(std::uint32_t i);
    /// The joints of body i (empty when it has none).
    const std::vector<std::uint32_t>& of_body(std::uint32_t body) const;
    /// Whether a joint between bodies a and b asks that their shapes not collide.
    bool filters(std::uint32_t a, std::uint32_t b) const;

  private:
    std::vector<std::uint32_t> free_slots_;
    std::vector<std::vector<std::uint32_t>> by_body_; ///< per body index: its joints
    std::uint32_t live_ = 0;
};

} // namespace tamias2d
