// Command-line options that override a case's run settings, shared by `limber run` and
// `limber select`: --integrator, --rtol, --atol, --step, --t-end, --max-wall, --start,
// --peak-window.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "io/mechanism_reader.h"

namespace limber::app {

struct SettingsOverrides {
  std::string integrator;  // "" = the case's
  std::string start;       // "" = the case's
  std::optional<double> rtol, atol, step, t_end, max_wall, peak_window;

  // Adds the options to `command`; `this` must outlive it.
  void add_options(CLI::App& command);
  // The case's settings with the given options applied.
  io::RunSettings apply(io::RunSettings settings) const;
};

}  // namespace limber::app
