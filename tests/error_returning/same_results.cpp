// Every `try_` form does what its throwing form does: a scripted sequence of calls made through
// the throwing forms and again through the `try_` forms gives the same results and the same
// state_hash after each stage, on 1 and 3 workers; a refused call refuses the same way in both
// (the world unchanged); a recording made through Recorder's `try_` forms holds the same bytes
// as one made through its throwing forms, and replays to the same state. Also the conversion
// itself (detail::capture): each exception type becomes its ErrorKind, including those no
// scripted call provokes (SolverDivergence, std::length_error, a non-std exception), and an
// exception thrown by the game's own pre-solve callback comes back as callback_failed or
// out_of_memory after the step it finished, as the throwing form's step() rethrows it.
// Compiled with exceptions: it calls the throwing forms. Plumbing, not physics: no SRS label.
// Oracles: the throwing forms' own results (state_hash, returned values, recording bytes);
// errors.hpp's fields for the conversion.
#include <cstdint>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "tamias2d/error_returning.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"

namespace {

int failures = 0;
int checks = 0;

void expect(bool ok, const std::string& what) {
    ++checks;
    if (!ok) {
        ++failures;
        std::printf("FAILED: %s\n", what.c_str());
    }
}

using namespace tamias2d;

// A call through the throwing form, or through its try_ form with the value taken (value()
// throws BadResultAccess if the try_ form refused, which fails the run).
#define CALL(twin, object, name, ...)                                                              \
    ((twin) ? (object).try_##name(__VA_ARGS__).value() : (object).name(__VA_ARGS__))

struct Outcome {
    std::vector<std::uint64_t> hashes; ///< state_hash after each stage
    std::vector<double> values;        ///< values the calls returned
    std::vector<std::string> refusals; ///< the refused calls' messages
    std::vector<std::byte> recording;
};

/// The script: builds a small scene, moves it, queries it, has a call refused, changes it.
/// `twin`: through the try_ forms; the world is recorded through a Recorder when `recorded`.
Outcome script(bool twin, int workers, bool recorded) {
    Outcome out;
    WorldDef def;
    def.workers = workers;
    World world = twin ? World::try_create(def).value() : World(def);
    // The mutating calls go through the Recorder when recorded, else to the world.
    auto run = [&](auto&& body) {
        if (recorded) {
            Recorder recorder = twin ? Recorder::try_create(world).value() : Recorder(world);
            body(recorder);
            out.recording = CALL(twin, recorder, bytes);
        } else {
            body(world);
        }
    };
    run([&](auto& w) {
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = CALL(twin, w, create_body, ground_def);
        CALL(twin, w, create_shape, ground, box_shape(40.0, 1.0));
        std::vector<BodyId> boxes;
        for (int i = 0; i < 4; ++i) {
            BodyDef b;
            b.position = {-3.0 + 2.0 * i, 1.5 + 0.5 * i};
            b.angle = 0.1 * i;
            boxes.push_back(CALL(twin, w, create_body, b));
            CALL(twin, w, create_shape, boxes.back(),
                 i % 2 ? circle_shape(0.4) : box_shape(0.8, 0.6));
        }
        RevoluteJointDef pin;
        pin.body_a = boxes[0];
        pin.body_b = boxes[1];
        pin.anchor = {-2.0, 2.0};
        const JointId joint = CALL(twin, w, create_joint, pin);
        out.values.push_back(static_cast<double>(joint.index));
        CALL(twin, w, set_velocity, boxes[2], Vec2d{1.0, 0.5});
        CALL(twin, w, apply_impulse, boxes[3], Vec2d{-0.5, 2.0}, Vec2d{3.0, 3.0});
        const std::vector<ShapeId> ground_shapes = world.shapes(ground);
        CALL(twin, w, set_friction, ground_shapes[0], 0.7);
        for (int s = 0; s < 30; ++s)
            CALL(twin, w, step, 1.0 / 60.0);
        out.hashes.push_back(CALL(twin, world, state_hash));
        // A refused call: an impulse on the static ground (WrongKind), the world unchanged.
        if (twin) {
            const Result<void> r = w.try_apply_impulse(ground, Vec2d{0, 1}, Vec2d{0, 0});
            out.refusals.push_back(r ? "accepted" : r.error().message);
        } else {
            try {
                w.apply_impulse(ground, Vec2d{0, 1}, Vec2d{0, 0});
                out.refusals.push_back("accepted");
            } catch (const WrongKind& e) {
                out.refusals.push_back(e.what());
            }
        }
        out.hashes.push_back(CALL(twin, world, state_hash));
        ExplosionDef blast;
        blast.position = {0.0, 1.0};
        blast.radius = 3.0;
        blast.impulse_per_length = 0.5;
        out.values.push_back(static_cast<double>(CALL(twin, w, explode, blast)));
        CALL(twin, w, set_gravity, Vec2d{0.5, -9.0});
        CALL(twin, w, destroy_body, boxes[1]);
        for (int s = 0; s < 30; ++s)
            CALL(twin, w, step, 1.0 / 60.0);
        out.hashes.push_back(CALL(twin, world, state_hash));
    });
    const auto hit = CALL(twin, world, ray_cast, Vec2d{-10.0, 0.2}, Vec2d{20.0, 0.0});
    out.values.push_back(hit ? hit->fraction : -1.0);
    out.values.push_back(CALL(twin, world, kinetic_energy));
    out.values.push_back(
        static_cast<double>(CALL(twin, world, query_aabb, Aabb{-5, -1, 5, 5}).size()));
    out.values.push_back(CALL(twin, world, position, CALL(twin, world, bodies).back()).x);
    return out;
}

void same_results(int workers, bool recorded) {
    const std::string where =
        " (" + std::to_string(workers) + " workers" + (recorded ? ", recorded)" : ")");
    const Outcome thrown = script(false, workers, recorded);
    const Outcome returned = script(true, workers, recorded);
    expect(thrown.hashes.size() == 3 && thrown.hashes == returned.hashes,
           "the same state_hash after each stage" + where);
    expect(thrown.hashes.size() == 3 && thrown.hashes[0] == thrown.hashes[1],
           "the refused call changed nothing" + where);
    expect(thrown.values == returned.values, "the same values returned" + where);
    expect(thrown.refusals == returned.refusals && thrown.refusals.size() == 1 &&
               thrown.refusals[0] != "accepted",
           "the same refusal, with the same message" + where);
    if (!recorded)
        return;
    expect(!thrown.recording.empty() && thrown.recording == returned.recording,
           "the same recording bytes" + where);
    const Result<ReplayReport> report = try_replay(returned.recording, workers);
    expect(report && report->matched() && report->steps == 60,
           "the try_ forms' recording replays, matched, 60 steps" + where);
    Replayer replayer = Replayer::try_create(returned.recording, workers).value();
    while (!replayer.try_done().value())
        expect(!replayer.try_advance().value().has_value(), "no divergence" + where);
    expect(replayer.try_world().value()->state_hash() == thrown.hashes.back(),
           "the replayed world's state_hash is the recorded world's" + where);
}

/// A world whose pre-solve callback runs `thrower` (what the game's own code may do when it is
/// compiled with exceptions): try_step returns `kind` where step() rethrows, and both worlds
/// end the same (the step finishes whole, world.hpp's set_pre_solve).
void callback_throws(void (*thrower)(), ErrorKind kind, const std::string& what) {
    std::uint64_t hashes[2]{};
    for (const bool twin : {false, true}) {
        World world;
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        world.create_shape(world.create_body(ground_def), box_shape(10.0, 1.0));
        BodyDef ball;
        ball.position = {0.0, 0.9};
        world.create_shape(world.create_body(ball), circle_shape(0.5));
        world.set_pre_solve([thrower](const PreSolveContact&) -> bool {
            thrower();
            return true;
        });
        const double t0 = world.time();
        if (twin) {
            const Result<void> r = world.try_step(1.0 / 60.0);
            expect(!r && r.error().kind == kind,
                   std::string("a throwing callback gives ") + to_string(kind));
            expect(!r && r.error().message.find(what) != std::string::npos,
                   "its message is the callback's what(): " + what);
        } else {
            bool thrown = false;
            try {
                world.step(1.0 / 60.0);
            } catch (...) {
                thrown = true;
            }
            expect(thrown, "step() rethrows the callback's exception");
        }
        expect(world.time() > t0, "the step finished whole");
        hashes[twin] = world.state_hash();
    }
    expect(hashes[0] == hashes[1], "both forms end in the same state");
}

template <class F> Error error_of(F&& f) {
    const Result<void> r = detail::capture(std::forward<F>(f));
    return r ? Error{} : r.error();
}

void conversion() {
    const Error diverged =
        error_of([] { throw SolverDivergence("body[3 'slider'].velocity", "x"); });
    expect(diverged.kind == ErrorKind::solver_divergence, "SolverDivergence: solver_divergence");
    expect(diverged.field == "body[3 'slider'].velocity", "SolverDivergence: its field");
    const Error length = error_of([] { throw std::length_error("vector::reserve"); });
    expect(length.kind == ErrorKind::out_of_memory, "std::length_error: out_of_memory");
    const Error alloc = error_of([] { throw std::bad_alloc(); });
    expect(alloc.kind == ErrorKind::out_of_memory, "std::bad_alloc: out_of_memory");
    const Error other = error_of([] { throw 42; });
    expect(other.kind == ErrorKind::callback_failed && !other.message.empty(),
           "a non-std exception: callback_failed, with a message");
    const Error snapshot = error_of([] { throw SnapshotError(40, "bodies[3].first_shape", "r"); });
    expect(snapshot.kind == ErrorKind::snapshot && snapshot.offset == 40 &&
               snapshot.field == "bodies[3].first_shape" && snapshot.rule == "r",
           "SnapshotError: offset, field and rule");
    const Error handle = error_of([] { throw InvalidHandle("BodyId 0:1"); });
    expect(handle.kind == ErrorKind::invalid_handle && handle.message == "BodyId 0:1",
           "InvalidHandle: invalid_handle, its what()");
    const Result<int> value = detail::capture([] { return 7; });
    expect(value && *value == 7, "a value passes through");
    bool threw = false;
    try {
        (void)Result<int>(Error{}).value();
    } catch (const BadResultAccess&) {
        threw = true;
    }
    expect(threw, "value() of an error throws BadResultAccess when exceptions are on");
}

} // namespace

int main() {
    for (const int workers : {1, 3}) {
        same_results(workers, false);
        same_results(workers, true);
    }
    callback_throws([] { throw std::runtime_error("the game's bug"); }, ErrorKind::callback_failed,
                    "the game's bug");
    callback_throws([] { throw std::bad_alloc(); }, ErrorKind::out_of_memory,
                    std::bad_alloc().what());
    conversion();
    std::printf("%d checks, %d failed\n", checks, failures);
    return failures == 0 ? 0 : 1;
}
