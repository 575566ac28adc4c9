/// \file
/// Playing a recording (recorder.hpp) back: its world rebuilt from its snapshot, its calls made
/// again in order, and after every step the world compared with the recorded one; the first
/// difference is reported by step, body and field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/recording_error.hpp"
#include "tamias2d/result.hpp"
#include "tamias2d/task_system.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d {

/// Where a replay first departed from its recording.
struct ReplayDivergence {
    /// The step (1: the first recorded step) after which the states differ, or before which a
    /// recorded call was refused by the replayed world.
    std::uint64_t step = 0;
    /// The first body (in slot order) whose recorded state differs; none when the body states
    /// were not recorded, or when they all agree and the difference is elsewhere (contacts,
    /// joints, sleep: the state hash alone differs), or for a refused call.
    std::optional<BodyId> body;
    /// The body's first differing field: "position.x", "position.y", "angle",
    /// "linear_velocity.x", "linear_velocity.y", "angular_velocity", or "exists" for a body
    /// one side has and the other not; "state_hash" when no body differs; "call" for a refused
    /// call.
    std::string field;
    std::uint64_t recorded_bits = 0; ///< the field's recorded bits (IEEE-754 binary64, a hash)
    std::uint64_t replayed_bits = 0; ///< the field's bits in the replay
    /// One line: "step 118: body 7 (index 7, generation 1): linear_velocity.x differs: recorded
    /// 0x... (1.25), replayed 0x... (1.2500000000000002)".
    std::string message;
};

/// A recording played back whole (replay).
struct ReplayReport {
    std::uint64_t steps = 0;          ///< steps replayed (up to and including a diverging one)
    std::uint64_t calls = 0;          ///< calls replayed, steps included
    std::uint64_t recorded_steps = 0; ///< steps in the recording
    std::optional<ReplayDivergence> divergence; ///< none: every step matched bit for bit
    /// Whether every step matched (no divergence).
    bool matched() const { return !divergence.has_value(); }
};

/// One record of a recording, as listed by recorded_calls.
struct RecordedCall {
    std::string_view name;  ///< the World call, e.g. "apply_impulse" ("create_revolute_joint")
    std::uint64_t step = 0; ///< the steps recorded before it
    std::size_t offset = 0; ///< byte offset of its arguments in the recording
    std::size_t size = 0;   ///< bytes of its arguments (a step's: dt, then its outcome)
};

/// Plays a recording back step by step: the world is built from the recording's snapshot, and
/// each advance() makes the recorded calls up to the next step, the step, and compares.
class TAMIAS2D_EXPORT Replayer {
  public:
    ~Replayer();
    Replayer(Replayer&&) noexcept;            ///< takes over the replay and its world
    Replayer& operator=(Replayer&&) noexcept; ///< takes over the replay and its world

    // The calls below may throw and are declared only when TAMIAS2D_EXCEPTIONS is 1 (config.hpp).
#if TAMIAS2D_EXCEPTIONS
    /// Reads the recording whole (every record must be readable) and builds its world, stepping
    /// with `workers` workers and `task_system` (the host's: the results are the same bits on
    /// any number). Throws RecordingError for a recording that is not one, of another format
    /// version, truncated, changed or unreadable, and for a snapshot in it that
    /// World::from_snapshot refuses (the field named "snapshot.<field>", at its offset in the
    /// recording); ValidationError for workers < 1.
    explicit Replayer(std::span<const std::byte> recording, int workers = 1,
                      const TaskSystem& task_system = {});

    /// The replayed world (read it between advances; changing it makes the replay diverge).
    const World& world() const;
    /// Whether every record has been replayed.
    bool done() const;
    /// The steps replayed so far.
    std::uint64_t steps() const;
    /// The calls replayed so far, steps included.
    std::uint64_t calls() const;
    /// The steps the recording holds.
    std::uint64_t recorded_steps() const;
    /// Makes the recorded calls up to and including the next step (or to the end), then
    /// compares the world with the recorded one after that step: the divergence if they
    /// differ, or if a recorded call is refused (an exception) by the replayed world. After a
    /// divergence the replay stops (done() is true). Does nothing once done.
    std::optional<ReplayDivergence> advance();
#endif // TAMIAS2D_EXCEPTIONS

    // The error-returning forms (result.hpp): each `try_` call is the call of the same name
    // (try_create: the constructor), returning its result or the Error its throwing form would
    // throw, instead of throwing. Declared whatever TAMIAS2D_EXCEPTIONS is.
    /// the constructor, returning its Error instead of throwing it.
    static Result<Replayer> try_create(std::span<const std::byte> recording, int workers = 1,
                                       const TaskSystem& task_system = {}) noexcept;
    /// world, returning its Error instead of throwing it.
    Result<const World*> try_world() const noexcept;
    /// done, returning its Error instead of throwing it.
    Result<bool> try_done() const noexcept;
    /// steps, returning its Error instead of throwing it.
    Result<std::uint64_t> try_steps() const noexcept;
    /// calls, returning its Error instead of throwing it.
    Result<std::uint64_t> try_calls() const noexcept;
    /// recorded_steps, returning its Error instead of throwing it.
    Result<std::uint64_t> try_recorded_steps() const noexcept;
    /// advance, returning its Error instead of throwing it.
    Result<std::optional<ReplayDivergence>> try_advance() noexcept;

    /// \cond INTERNAL
    struct Impl;
    /// \endcond

  private:
    std::unique_ptr<Impl> impl_;
};

#if TAMIAS2D_EXCEPTIONS
/// Replays a recording whole, stopping at the first divergence. Throws as Replayer's
/// constructor does.
TAMIAS2D_EXPORT ReplayReport replay(std::span<const std::byte> recording, int workers = 1,
                                    const TaskSystem& task_system = {});

/// The records of a recording, in order, without replaying it (tools, tests). Throws
/// RecordingError as Replayer does.
TAMIAS2D_EXPORT std::vector<RecordedCall> recorded_calls(std::span<const std::byte> recording);
#endif // TAMIAS2D_EXCEPTIONS

/// replay, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ReplayReport> try_replay(std::span<const std::byte> recording,
                                                int workers = 1,
                                                const TaskSystem& task_system = {}) noexcept;
/// recorded_calls, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<std::vector<RecordedCall>>
try_recorded_calls(std::span<const std::byte> recording) noexcept;

} // namespace tamias2d
