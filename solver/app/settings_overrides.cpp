#include "app/settings_overrides.h"

namespace limber::app {

void SettingsOverrides::add_options(CLI::App& command) {
  command.add_option("--integrator", integrator,
                     "ida (variable-step BDF, error control) or galpha (fixed-step generalized-alpha)")
      ->check(CLI::IsMember({"ida", "galpha"}));
  command.add_option("--rtol", rtol, "IDA relative tolerance (>= 1e-11 on a mechanism)");
  command.add_option("--atol", atol, "IDA absolute tolerance (>= 1e-14 on a mechanism)");
  command.add_option("--step", step, "generalized-alpha step [s] (> 0)");
  command.add_option("--t-end", t_end, "End time [s] (>= 0)");
  command.add_option("--max-wall", max_wall,
                     "Wall-clock budget of the integration [s] (> 0; default: none): a run that has "
                     "not finished by then stops as failed, keeping its samples");
  command.add_option("--start", start,
                     "assembly (the initial poses assembled, the case's velocities) or statics "
                     "(the static equilibrium from there, hold-downs holding; docs/statics.md)")
      ->check(CLI::IsMember({"assembly", "statics"}));
  command.add_option("--peak-window", peak_window,
                     "Event peaks: the largest reactions, tracked at every step, this long [s] after the "
                     "start and after each latch engagement (>= 0; default: the case's run.peak_window; "
                     "limber run: 0, none; limber select: 0.3)");
}

}  // namespace limber::app
