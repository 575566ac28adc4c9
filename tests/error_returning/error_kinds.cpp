// Compiled with -fno-exceptions, as a game without exceptions is: only the `try_` forms are
// declared here (config.hpp). For each kind of Error a refusing call can return, a call that is
// refused returns that kind with the fields its exception carries, and leaves the world exactly
// as it was (state_hash unchanged). Plumbing, not physics: no SRS label.
// Oracles: the contracts of the throwing forms as world.hpp, errors.hpp, snapshot_error.hpp and
// recording_error.hpp state them (the field and constraint each names), and the world's own
// state_hash before the call.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tamias2d/allocator.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

#if TAMIAS2D_EXCEPTIONS
#error "this file is compiled as a game without exceptions: TAMIAS2D_EXCEPTIONS must be 0"
#endif

namespace {

int failures = 0;
int checks = 0;

void expect(bool ok, const char* what) {
    ++checks;
    if (!ok) {
        ++failures;
        std::printf("FAILED: %s\n", what);
    }
}

using namespace tamias2d;

/// A world with a static ground and a dynamic box on it, stepped once.
World make_world(int workers) {
    WorldDef def;
    def.workers = workers;
    Result<World> made = World::try_create(def);
    expect(made.has_value(), "try_create with valid settings succeeds");
    World world = std::move(made).value();
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = *world.try_create_body(ground_def);
    expect(world.try_create_shape(ground, *try_box_shape(20.0, 1.0)).has_value(),
           "the ground's shape is accepted");
    BodyDef box_def;
    box_def.position = {0.0, 2.0};
    const BodyId box = *world.try_create_body(box_def);
    expect(world.try_create_shape(box, *try_box_shape(1.0, 1.0)).has_value(),
           "the box's shape is accepted");
    expect(world.try_step(1.0 / 60.0).has_value(), "a step succeeds");
    return world;
}

void refused_kinds(int workers) {
    World world = make_world(workers);
    const std::vector<BodyId> bodies = *world.try_bodies();
    expect(bodies.size() == 2, "two bodies");
    const BodyId ground = bodies[0];
    const BodyId box = bodies[1];
    const std::uint64_t before = *world.try_state_hash();

    // validation: a circle of radius -1 (errors.hpp's example: shape.radius, DCX_shape)
    ShapeDef bad = *try_circle_shape(1.0);
    bad.geometry.circle.radius = -1.0;
    const Result<ShapeId> shape = world.try_create_shape(box, bad);
    expect(!shape && shape.error().kind == ErrorKind::validation, "radius -1: validation");
    expect(!shape && shape.error().field == "shape.radius", "radius -1: field shape.radius");
    expect(!shape && shape.error().constraint == "DCX_shape", "radius -1: constraint DCX_shape");
    expect(!shape && shape.error().value == -1.0, "radius -1: value -1");
    expect(!shape && !shape.error().message.empty(), "radius -1: a message");
    expect(*world.try_state_hash() == before, "radius -1: the world unchanged");

    // validation of a free function: a box of width -1 (shape_def.hpp)
    const Result<ShapeDef> box_def = try_box_shape(-1.0, 1.0);
    expect(!box_def && box_def.error().kind == ErrorKind::validation, "box width -1: validation");
    expect(!box_def && !box_def.error().constraint.empty(), "box width -1: a constraint");

    // wrong_kind: an impulse on the static ground (world.hpp: WrongKind for a static body)
    const Result<void> impulse = world.try_apply_impulse(ground, {0.0, 1.0}, {0.0, 0.0});
    expect(!impulse && impulse.error().kind == ErrorKind::wrong_kind, "impulse: wrong_kind");
    expect(!impulse && impulse.error().call == "apply_impulse", "impulse: call apply_impulse");
    expect(!impulse && impulse.error().subject_kind == "static body", "impulse: a static body");
    expect(*world.try_state_hash() == before, "impulse: the world unchanged");

    // invalid_handle: a body destroyed, then asked for its position
    World other = make_world(workers);
    const BodyId doomed = (*other.try_bodies())[1];
    expect(other.try_destroy_body(doomed).has_value(), "destroying a body succeeds");
    const std::uint64_t other_before = *other.try_state_hash();
    const Result<Vec2d> stale = other.try_position(doomed);
    expect(!stale && stale.error().kind == ErrorKind::invalid_handle, "stale: invalid_handle");
    const Result<void> stale_set = other.try_set_velocity(doomed, {1.0, 0.0});
    expect(!stale_set && stale_set.error().kind == ErrorKind::invalid_handle,
           "stale set_velocity: invalid_handle");
    expect(*other.try_state_hash() == other_before, "stale: the world unchanged");

    // wrong_world: a handle of `other` used with `world`
    const BodyId foreign = (*other.try_bodies())[0];
    const Result<void> moved = world.try_set_velocity(foreign, {1.0, 0.0});
    expect(!moved && moved.error().kind == ErrorKind::wrong_world, "foreign: wrong_world");
    expect(!moved && moved.error().handle_world == *other.try_tag(), "foreign: its world's tag");
    expect(!moved && moved.error().world == *world.try_tag(), "foreign: this world's tag");
    expect(!moved && !moved.error().handle.empty(), "foreign: the handle named");
    expect(*world.try_state_hash() == before, "foreign: the world unchanged");

    // snapshot: bytes that are not a snapshot (snapshot_error.hpp: header.magic)
    std::vector<std::byte> junk(64, std::byte{0x5a});
    const Result<World> from = World::try_from_snapshot(junk, workers);
    expect(!from && from.error().kind == ErrorKind::snapshot, "junk snapshot: snapshot");
    expect(!from && from.error().field == "header.magic", "junk snapshot: header.magic");
    expect(!from && from.error().offset == 0, "junk snapshot: at byte 0");
    expect(!from && !from.error().rule.empty(), "junk snapshot: a rule");
    const Result<void> restored = world.try_restore(junk);
    expect(!restored && restored.error().kind == ErrorKind::snapshot, "junk restore: snapshot");
    expect(*world.try_state_hash() == before, "junk restore: the world unchanged");

    // a snapshot that is one: taken, restored after a step, gives the hash back
    const std::vector<std::byte> snap = *world.try_snapshot();
    expect(world.try_step(1.0 / 60.0).has_value(), "a second step succeeds");
    expect(world.try_restore(snap).has_value(), "restoring a real snapshot succeeds");
    expect(*world.try_state_hash() == before, "restored: the hash of the snapshot's world");

    // recording: bytes that are not a recording (recording_error.hpp: header.magic)
    const Result<std::vector<RecordedCall>> calls = try_recorded_calls(junk);
    expect(!calls && calls.error().kind == ErrorKind::recording, "junk recording: recording");
    expect(!calls && calls.error().field == "header.magic", "junk recording: header.magic");
    const Result<Replayer> replayer = Replayer::try_create(junk, workers);
    expect(!replayer && replayer.error().kind == ErrorKind::recording, "junk replayer: recording");

    // validation of a constructor: workers < 1 (world.hpp: world.workers)
    WorldDef zero;
    zero.workers = 0;
    const Result<World> none = World::try_create(zero);
    expect(!none && none.error().kind == ErrorKind::validation, "workers 0: validation");
    expect(!none && none.error().field == "world.workers", "workers 0: field world.workers");
    expect(!none && std::isfinite(none.error().value) && none.error().value == 0.0,
           "workers 0: value 0");
}

void* aligned_block(std::size_t size, std::size_t alignment, void*) {
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}
void free_block(void* p, std::size_t, std::size_t, void*) {
    std::free(p);
}

// The allocator hook's refusals (allocator.hpp's contract): a hook without its free function
// is a validation error naming allocator.free; while a world holds blocks, allocator_in_use with
// the counts allocator_use() reports, and the allocator unchanged; with nothing held, both calls
// succeed.
void allocator_refusals() {
    const Allocator hook{aligned_block, free_block, nullptr};
    Allocator half = hook;
    half.free = nullptr;
    const Result<void> no_free = try_set_allocator(half);
    expect(!no_free && no_free.error().kind == ErrorKind::validation &&
               no_free.error().field == "allocator.free" &&
               no_free.error().constraint == "allocator",
           "a hook without free: validation naming allocator.free");
    {
        const World world = make_world(1);
        const AllocatorUse held = allocator_use();
        const Result<void> busy = try_set_allocator(hook);
        expect(held.blocks > 0 && !busy && busy.error().kind == ErrorKind::allocator_in_use &&
                   busy.error().blocks == held.blocks && busy.error().bytes == held.bytes,
               "a world alive: allocator_in_use with the blocks and bytes held");
        expect(current_allocator().allocate == nullptr, "refused: the default allocator stays");
        const Result<void> reset = try_reset_allocator();
        expect(!reset && reset.error().kind == ErrorKind::allocator_in_use,
               "a world alive: reset refused as allocator_in_use");
    }
    expect(allocator_use().blocks == 0 && try_set_allocator(hook).has_value() &&
               current_allocator().allocate == hook.allocate,
           "nothing held: the hook is installed");
    {
        const World world = make_world(1);
        expect(allocator_use().blocks > 0, "the world's blocks come from the hook");
    }
    expect(try_reset_allocator().has_value() && current_allocator().allocate == nullptr,
           "nothing held: back to the default allocator");
}

} // namespace

int main() {
    for (const int workers : {1, 3})
        refused_kinds(workers);
    allocator_refusals();
    expect(std::string(to_string(ErrorKind::wrong_world)) == "wrong_world",
           "to_string names the kind as declared");
    std::printf("%d checks, %d failed\n", checks, failures);
    return failures == 0 ? 0 : 1;
}
