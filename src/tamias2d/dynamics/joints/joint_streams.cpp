#include "tamias2d/dynamics/joints/joint_streams.hpp"

#include <algorithm>

namespace tamias2d {

void JointStreams::split(memory::vector<SolvedJoint>& solved, std::uint32_t regions,
                         std::uint32_t moving) {
    regions_ = 0;
    const std::uint32_t R = std::min(regions, max_regions);
    if (R < 2 || solved.size() < min_joints || moving < R)
        return;
    // Run r holds the solver bodies k with floor((k - 1) R / moving) = r.
    const auto run_of = [&](std::uint32_t k) {
        return std::uint32_t(std::uint64_t(k - 1) * R / moving);
    };
    std::array<std::uint32_t, max_regions + 2> count{};
    stream_of_.resize(solved.size());
    for (std::size_t i = 0; i < solved.size(); ++i) {
        const SolvedJoint& s = solved[i];
        std::uint32_t stream = R; // the rest
        if (s.solver_a != 0 && s.solver_b != 0 && run_of(s.solver_a) == run_of(s.solver_b))
            stream = run_of(s.solver_a);
        stream_of_[i] = std::uint8_t(stream);
        ++count[stream];
    }
    begin_[0] = 0;
    for (std::uint32_t r = 0; r <= R; ++r)
        begin_[r + 1] = begin_[r] + count[r];
    // A stable counting sort: creation order within each stream.
    std::array<std::uint32_t, max_regions + 2> next = begin_;
    ordered_.resize(solved.size());
    for (std::size_t i = 0; i < solved.size(); ++i)
        ordered_[next[stream_of_[i]]++] = solved[i];
    solved.swap(ordered_);
    regions_ = R;
}

} // namespace tamias2d
