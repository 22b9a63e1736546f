// Overrides of a case's run settings, shared by `limber run` and `limber select` (their
// --integrator, --rtol, ... options, solver/app/settings_overrides.h) and the Python module's
// keyword arguments (solver/python): each one left empty keeps the case's value.
#pragma once

#include <optional>
#include <string>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_reader.h"

namespace limber::run {

struct SettingsOverrides {
  std::string integrator;  // "" = the case's; "ida" | "galpha"
  std::string start;       // "" = the case's; "assembly" | "statics"
  std::optional<double> rtol, atol, step, t_end, max_wall, peak_window;
  // "" or "modal" = the case's; "nonlinear": every flexible body nonlinear
  // (io/formulation_override.h; limber run --formulation, limber sweep --reference nonlinear).
  std::string formulation;

  // The case's settings with the given overrides applied. Throws InputError for an integrator
  // or start other than those above (the values themselves are checked by check_settings).
  io::RunSettings apply(io::RunSettings settings) const;
};

// `modes` normal modes for every flexible body of `input` in place of its request (its static
// modes kept, a cut-off frequency dropped), so that `limber sweep` can vary the mode count of a
// case; none when `modes` is empty. Throws InputError when `modes` is negative.
io::ModeOverrides normal_mode_overrides(const io::Case& input, std::optional<int> modes);

}  // namespace limber::run
