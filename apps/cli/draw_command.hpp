// `tamias2d draw`: runs a scene as `tamias2d run` does and writes the final state as an SVG
// picture through World::draw (svg_draw.hpp).
#pragma once

#include <span>
#include <string_view>

#include "view_command.hpp"

namespace tamias2d::cli {

/// The text of `tamias2d draw --help`.
extern const char* const draw_usage;

/// Runs `tamias2d draw` with the arguments after the command word and returns the exit
/// status. Throws UsageError for a bad command line, io::SceneError for an invalid scene and
/// std::runtime_error for a failed run or an unwritable output.
int draw_command(std::span<const std::string_view> args, const SceneSource& source);

} // namespace tamias2d::cli
