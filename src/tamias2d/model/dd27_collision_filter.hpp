#pragma once
#include <cstdint>

namespace tamias2d::model::dd27 {

/// \srs{DD27} A shape's collision filter: the categories it belongs to, the categories it
/// collides with, and its group.
struct Filter {
    std::uint32_t category_bits;
    std::uint32_t mask_bits;
    std::int32_t group_index;
};

/// \srs{DD27} Whether two shapes' filters let them collide: shapes of one non-zero group always
/// collide (positive group) or never (negative); otherwise each must be in a category the other
/// collides with, (c_A & m_B) != 0 and (c_B & m_A) != 0.
constexpr bool should_collide(Filter a, Filter b) {
    if (a.group_index == b.group_index && a.group_index != 0)
        return a.group_index > 0;
    return (a.category_bits & b.mask_bits) != 0 && (b.category_bits & a.mask_bits) != 0;
}

} // namespace tamias2d::model::dd27
