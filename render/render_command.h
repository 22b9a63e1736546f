// The `limber render DIR` sub-command (CLI11): options as in docs/rendering.md.
#pragma once

#include <CLI/CLI.hpp>

namespace limber::render {

// Adds `render` to `app`; its callback renders and prints a short summary, and turns an
// InputError into a clear message and exit code 2 (through CLI::RuntimeError).
void add_render_command(CLI::App& app);

}  // namespace limber::render
