// `tamias2d record` and `tamias2d replay`: a scene's run recorded (Recorder) to a file, and a
// recording replayed and checked step by step (replay), from the command line.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "view_command.hpp"

namespace tamias2d::cli {

/// The texts of `tamias2d record --help` and `tamias2d replay --help`.
extern const char* const record_usage;
extern const char* const replay_usage;

/// The exit status of a replay that departs from its recording.
inline constexpr int diverged_status = 3;

/// Runs `tamias2d record` with the arguments after the command word; returns the exit status.
/// Throws UsageError for a bad command line, io::SceneError for an invalid scene,
/// ValidationError for a scene that cannot be recorded (a load function), std::runtime_error
/// for an unwritable output.
int record_command(std::span<const std::string_view> args, const SceneSource& source);
/// Runs `tamias2d replay`: 0 when every step matches, diverged_status with the divergence on
/// standard error otherwise. Throws UsageError, RecordingError for a file that is not a
/// readable recording, std::runtime_error for an unreadable file.
int replay_command(std::span<const std::string_view> args);

/// Whether the file starts as a recording does (its magic, "T2D-RECD").
bool is_recording_file(const std::string& path);
/// The file's bytes; throws std::runtime_error naming it when it cannot be read.
std::vector<std::byte> read_file(const std::string& path);

} // namespace tamias2d::cli
