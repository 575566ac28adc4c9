// `tamias2d view`: runs a scene as `tamias2d run` does and writes a self-contained HTML player
// of the run (docs/viewer.md).
#pragma once

#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tamias2d/io/scene.hpp"

namespace tamias2d::cli {

/// A bad command line (exit status 2), for every command of the tool.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The text of `tamias2d view --help`.
extern const char* const view_usage;

/// How the tool reads a scene named on its command line ("-": standard input), and names it
/// in messages: `view` reads scenes exactly as `run` and `validate` do.
struct SceneSource {
    std::function<io::Scene(const std::string&)> load;
    std::function<std::string(const std::string&)> display_name;
};

/// Runs `tamias2d view` with the arguments after the command word and returns the exit
/// status. Throws UsageError for a bad command line, io::SceneError for an invalid scene and
/// std::runtime_error for a failed run or an unwritable output.
int view_command(std::span<const std::string_view> args, const SceneSource& source);

} // namespace tamias2d::cli
