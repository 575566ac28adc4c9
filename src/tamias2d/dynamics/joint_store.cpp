#include "tamias2d/dynamics/joint_store.hpp"

#include <algorithm>
#include <string>

#include "tamias2d/errors.hpp"

namespace tamias2d {

Joint& JointStore::get(JointId id) {
    if (!is_valid(id)) {
        throw InvalidHandle("stale or unknown JointId " + std::to_string(id.index) + ":" +
                            std::to_string(id.generation));
    }
    return joints[id.index];
}

bool JointStore::is_valid(JointId id) const {
    return id.index < joints.size() && joints[id.index].alive &&
           joints[id.index].generation == id.generation;
}

std::uint32_t JointStore::create(const Joint& joint) {
    std::uint32_t i;
    if (!free_slots_.empty()) {
        i = free_slots_.back();
        free_slots_.pop_back();
    } else {
        i = std::uint32_t(joints.size());
        joints.emplace_back();
    }
    const std::uint32_t generation = joints[i].generation + 1;
    joints[i] = joint;
    joints[i].generation = generation;
    joints[i].alive = true;
    const std::uint32_t top = std::max(joint.body_a, joint.body_b);
    if (by_body_.size() <= top)
        by_body_.resize(top + 1);
    by_body_[joint.body_a].push_back(i);
    by_body_[joint.body_b].push_back(i);
    ++live_;
    return i;
}

void JointStore::destroy(std::uint32_t i) {
    Joint& j = joints[i];
    for (const std::uint32_t body : {j.body_a, j.body_b}) {
        auto& list = by_body_[body];
        list.erase(std::find(list.begin(), list.end(), i));
    }
    j.alive = false;
    free_slots_.push_back(i);
    --live_;
}

const std::vector<std::uint32_t>& JointStore::of_body(std::uint32_t body) const {
    static const std::vector<std::uint32_t> none;
    return body < by_body_.size() ? by_body_[body] : none;
}

bool JointStore::filters(std::uint32_t a, std::uint32_t b) const {
    for (const std::uint32_t i : of_body(a)) {
        const Joint& j = joints[i];
        if (!j.collide_connected &&
            ((j.body_a == a && j.body_b == b) || (j.body_a == b && j.body_b == a)))
            return true;
    }
    return false;
}

} // namespace tamias2d
