// The `limber render DIR` sub-command (CLI11): options as in docs/rendering.md.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/command.h"

namespace limber::render {

// Adds `render` to `app`. `run` renders, prints a summary and returns cli::kExitOk; it throws
// InputError for bad input (missing or damaged results file, empty time range, bad size or
// camera) and std::runtime_error when no offscreen OpenGL context can be created or a file
// cannot be written.
cli::Command add_render_command(CLI::App& app);

}  // namespace limber::render
