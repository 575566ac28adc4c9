// The conversion of the library's exceptions into Errors (error_returning.hpp) and the
// error-returning forms of the free functions of shape_def.hpp and plane_solver.hpp.
#include "tamias2d/error_returning.hpp"

#include <exception>
#include <new>
#include <stdexcept>

#include "tamias2d/allocator.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/plane_solver.hpp"
#include "tamias2d/recording_error.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/snapshot_error.hpp"

namespace tamias2d {

const char* to_string(ErrorKind kind) noexcept {
    switch (kind) {
    case ErrorKind::validation:
        return "validation";
    case ErrorKind::invalid_handle:
        return "invalid_handle";
    case ErrorKind::wrong_world:
        return "wrong_world";
    case ErrorKind::wrong_kind:
        return "wrong_kind";
    case ErrorKind::solver_divergence:
        return "solver_divergence";
    case ErrorKind::snapshot:
        return "snapshot";
    case ErrorKind::recording:
        return "recording";
    case ErrorKind::out_of_memory:
        return "out_of_memory";
    case ErrorKind::callback_failed:
        return "callback_failed";
    case ErrorKind::allocator_in_use:
        return "allocator_in_use";
    }
    return "unknown";
}

namespace detail {

namespace {
Error error_of(ErrorKind kind, const std::exception& e) {
    Error error;
    error.kind = kind;
    error.message = e.what();
    return error;
}
} // namespace

Error current_error() noexcept {
    // The most derived types first: WrongWorld is an InvalidHandle, and every one of the
    // library's types is a std::invalid_argument or std::runtime_error.
    try {
        throw;
    } catch (const ValidationError& e) {
        Error error = error_of(ErrorKind::validation, e);
        error.field = e.field;
        error.value = e.value;
        error.constraint = e.constraint;
        return error;
    } catch (const WrongWorld& e) {
        Error error = error_of(ErrorKind::wrong_world, e);
        error.handle = e.handle;
        error.handle_world = e.handle_world;
        error.world = e.world;
        return error;
    } catch (const InvalidHandle& e) {
        return error_of(ErrorKind::invalid_handle, e);
    } catch (const WrongKind& e) {
        Error error = error_of(ErrorKind::wrong_kind, e);
        error.call = e.call;
        error.subject = e.subject;
        error.subject_kind = e.kind;
        return error;
    } catch (const SolverDivergence& e) {
        Error error = error_of(ErrorKind::solver_divergence, e);
        error.field = e.field;
        return error;
    } catch (const SnapshotError& e) {
        Error error = error_of(ErrorKind::snapshot, e);
        error.offset = e.offset;
        error.field = e.field;
        error.rule = e.rule;
        return error;
    } catch (const RecordingError& e) {
        Error error = error_of(ErrorKind::recording, e);
        error.offset = e.offset;
        error.field = e.field;
        error.rule = e.rule;
        return error;
    } catch (const AllocatorInUse& e) {
        Error error = error_of(ErrorKind::allocator_in_use, e);
        error.blocks = e.blocks;
        error.bytes = e.bytes;
        return error;
    } catch (const std::bad_alloc& e) {
        return error_of(ErrorKind::out_of_memory, e);
    } catch (const std::length_error& e) {
        return error_of(ErrorKind::out_of_memory, e);
    } catch (const std::exception& e) {
        return error_of(ErrorKind::callback_failed, e);
    } catch (...) {
        Error error;
        error.kind = ErrorKind::callback_failed;
        error.message = "an exception that is not a std::exception";
        return error;
    }
}

} // namespace detail

Result<ShapeDef> try_box_shape(double width, double height, Material material, Vec2d center,
                               double angle) noexcept {
    return detail::capture([&] { return box_shape(width, height, material, center, angle); });
}

Result<ShapeDef> try_circle_shape(double radius, Material material, Vec2d center) noexcept {
    return detail::capture([&] { return circle_shape(radius, material, center); });
}

Result<ShapeDef> try_polygon_shape(std::span<const Vec2d> points, Material material) noexcept {
    return detail::capture([&] { return polygon_shape(points, material); });
}

Result<ShapeDef> try_capsule_shape(Vec2d center1, Vec2d center2, double radius,
                                   Material material) noexcept {
    return detail::capture([&] { return capsule_shape(center1, center2, radius, material); });
}

Result<ShapeDef> try_segment_shape(Vec2d point1, Vec2d point2, Material material) noexcept {
    return detail::capture([&] { return segment_shape(point1, point2, material); });
}

Result<std::vector<ShapeDef>> try_chain_shapes(std::span<const Vec2d> points, bool loop,
                                               Material material) noexcept {
    return detail::capture([&] { return chain_shapes(points, loop, material); });
}

Result<PlaneSolverResult> try_solve_planes(Vec2d target, std::span<CollisionPlane> planes,
                                           double tolerance, int max_iterations) noexcept {
    return detail::capture([&] { return solve_planes(target, planes, tolerance, max_iterations); });
}

Result<Vec2d> try_clip_vector(Vec2d v, std::span<const CollisionPlane> planes) noexcept {
    return detail::capture([&] { return clip_vector(v, planes); });
}

Result<void> try_set_allocator(const Allocator& hook) noexcept {
    return detail::capture([&] { set_allocator(hook); });
}

Result<void> try_reset_allocator() noexcept {
    return detail::capture([] { reset_allocator(); });
}

} // namespace tamias2d
