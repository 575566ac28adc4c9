/// \file
/// Which shapes a world query sees (World::ray_cast, shape_cast, query_aabb, query_point,
/// overlap_shape): Box2D v3's b2QueryFilter, with a body to leave out.
#pragma once

#include <cstdint>

#include "tamias2d/handles.hpp"

namespace tamias2d {

/// \srs{DD27} A query's filter. A shape is seen when DD27's category rule admits the pair of
/// the query and the shape, (query.category_bits & shape.mask_bits) != 0 and
/// (shape.category_bits & query.mask_bits) != 0 (the shape's group plays no part: the query
/// has none), and the shape is not on `exclude_body`. The default sees every shape whose
/// mask is not zero.
struct QueryFilter {
    std::uint32_t category_bits = 0xFFFFFFFF; ///< the categories the query belongs to
    std::uint32_t mask_bits = 0xFFFFFFFF;     ///< the categories of the shapes it sees
    /// A body whose shapes are not seen (a character's own body); the default names none.
    BodyId exclude_body{};
};

} // namespace tamias2d
