// The `limber render DIR` sub-command (CLI11): options as in docs/rendering.md.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace limber::render {

// A registered sub-command: the same shape as solver/app/command.h's Command (render/ does
// not see solver/app; main.cpp converts one into the other).
struct RenderCommand {
  CLI::App* cli = nullptr;   // the sub-command, parsed by the caller
  std::function<int()> run;  // renders, prints a summary, returns exit code 0
};

// Adds `render` to `app`. `run` throws InputError for bad input (missing or damaged results
// file, empty time range, bad size or camera) and std::runtime_error when no offscreen
// OpenGL context can be created or a file cannot be written.
RenderCommand add_render_command(CLI::App& app);

}  // namespace limber::render
