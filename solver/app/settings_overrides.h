// Command-line options that override a case's run settings, shared by `limber run` and
// `limber select`: --integrator, --rtol, --atol, --step, --t-end, --max-wall, --start,
// --peak-window, into run::SettingsOverrides (the Python module's keyword arguments fill the
// same struct).
#pragma once

#include <CLI/CLI.hpp>

#include "run/settings_overrides.h"

namespace limber::app {

struct SettingsOverrides : run::SettingsOverrides {
  // Adds the options to `command`; `this` must outlive it.
  void add_options(CLI::App& command);
};

}  // namespace limber::app
