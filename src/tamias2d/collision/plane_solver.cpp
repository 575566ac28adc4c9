// The plane solver of a mover (DD43): projected Gauss-Seidel on the planes' pushes, and the
// velocity clipped against the planes it pressed against. Pure functions: no world.
#include "tamias2d/plane_solver.hpp"

#include <cmath>
#include <string>

#include "tamias2d/errors.hpp"
#include "tamias2d/math/hypot.hpp"
#include "tamias2d/model/dd43_plane_solver.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

namespace {
namespace u = tamias2d::units;
namespace dd43 = tamias2d::model::dd43;

u::Vec2<double> unit(Vec2d n) {
    return {n.x, n.y};
}

/// \srs{DD43} The planes as the problem needs them: unit normals (to 1e-6), offsets within
/// the supported range, push limits >= 0 (infinite allowed).
void check_planes(std::span<const CollisionPlane> planes) {
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const std::string at = "planes[" + std::to_string(i) + "].";
        const CollisionPlane& p = planes[i];
        require_finite(at + "normal", p.normal);
        const double n = math::hypot(p.normal.x, p.normal.y);
        if (!(std::abs(n - 1.0) <= 1e-6))
            throw ValidationError(at + "normal", n, "must have length 1 (to 1e-6)", "DD43");
        require_within(at + "offset", p.offset, supported::input_max, "m");
        if (!(p.push_limit >= 0.0))
            throw ValidationError(at + "push_limit", p.push_limit, "must be >= 0 (m)", "DD43");
    }
}
} // namespace

PlaneSolverResult solve_planes(Vec2d target, std::span<CollisionPlane> planes, double tolerance,
                               int max_iterations) {
    require_within("target", target, supported::input_max, "m");
    check_planes(planes);
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw ValidationError("tolerance", tolerance, "must be finite and > 0 (m)", "DD43");
    if (max_iterations < 1)
        throw ValidationError("max_iterations", double(max_iterations), "must be >= 1", "DD43");
    for (CollisionPlane& p : planes)
        p.push = 0.0;
    u::Vec2<u::Length> d = u::vec_from_values<u::Length>(target.x, target.y);
    PlaneSolverResult out;
    while (out.iterations < max_iterations) {
        ++out.iterations;
        double moved = 0.0; // the sweep's pushes, summed
        for (CollisionPlane& p : planes) {
            const u::Vec2<double> n = unit(p.normal);
            const u::Length s = dd43::separation(n, u::from_value<u::Length>(p.offset), d);
            const u::Length before = u::from_value<u::Length>(p.push);
            const u::Length after =
                dd43::updated_push(before, s, u::from_value<u::Length>(p.push_limit));
            d = dd43::translation_after(d, n, after - before);
            p.push = after.value();
            moved += std::abs((after - before).value());
        }
        if (moved < tolerance) {
            out.converged = true;
            break;
        }
    }
    out.translation = {d.x.value(), d.y.value()};
    return out;
}

Vec2d clip_vector(Vec2d v, std::span<const CollisionPlane> planes) {
    require_within("vector", v, supported::input_max, "m s^-1");
    check_planes(planes);
    u::Vec2<u::Velocity> w = u::vec_from_values<u::Velocity>(v.x, v.y);
    for (const CollisionPlane& p : planes)
        if (p.push > 0.0 && p.clip_velocity)
            w = dd43::clipped(w, unit(p.normal));
    return {w.x.value(), w.y.value()};
}

} // namespace tamias2d
