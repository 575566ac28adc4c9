#include "tamias2d/io/chain_runs.hpp"

#include "tamias2d/errors.hpp"
#include "tamias2d/math/same_bits.hpp"

namespace tamias2d::io {

namespace {

// Bits, not values: -0 and 0 differ in the file, and the round trip is promised bit for bit.
bool same(double a, double b) {
    return math::same_bits(a, b);
}
bool same(Vec2d a, Vec2d b) {
    return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const ChainSegment& a, const ChainSegment& b) {
    return same(a.ghost1, b.ghost1) && same(a.point1, b.point1) && same(a.point2, b.point2) &&
           same(a.ghost2, b.ghost2);
}
bool same(const Material& a, const Material& b) {
    return same(a.density, b.density) && same(a.restitution, b.restitution) &&
           same(a.friction, b.friction) && a.user_material_id == b.user_material_id &&
           same(a.rolling_resistance, b.rolling_resistance) &&
           same(a.tangent_speed, b.tangent_speed);
}

/// Whether b can follow a in one chain: b starts where a ends, and each one's ghost there is
/// the other's far end. One material, filter and sensor flag for the whole chain.
bool linked(const ShapeDef& a, const ShapeDef& b) {
    if (b.geometry.type != ShapeType::chain_segment || !same(a.material, b.material) ||
        !(a.filter == b.filter) || a.is_sensor != b.is_sensor ||
        a.enable_pre_solve != b.enable_pre_solve)
        return false;
    const ChainSegment& x = a.geometry.chain_segment;
    const ChainSegment& y = b.geometry.chain_segment;
    return same(x.point2, y.point1) && same(x.ghost2, y.point2) && same(y.ghost1, x.point1);
}

} // namespace

ChainRun chain_run_at(std::span<const ShapeDef> shapes, std::size_t first) {
    ChainRun run;
    std::size_t last = first;
    while (true) {
        // A loop closes at the first segment that leads back to the start.
        if (last - first >= 2 && linked(shapes[last], shapes[first])) {
            run.loop = true;
            break;
        }
        if (last + 1 == shapes.size() || !linked(shapes[last], shapes[last + 1]))
            break;
        ++last;
    }
    run.count = last - first + 1;
    for (std::size_t k = first; k <= last; ++k)
        run.points.push_back(shapes[k].geometry.chain_segment.point1);
    if (!run.loop)
        run.points.push_back(shapes[last].geometry.chain_segment.point2);
    std::vector<ShapeDef> again;
    try {
        again = chain_shapes(run.points, run.loop, shapes[first].material);
    } catch (const ValidationError&) {
        return run;
    }
    if (again.size() != run.count)
        return run;
    for (std::size_t k = 0; k < run.count; ++k)
        if (!same(again[k].geometry.chain_segment, shapes[first + k].geometry.chain_segment))
            return run;
    run.reproduced = true;
    return run;
}

} // namespace tamias2d::io
