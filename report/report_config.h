// A report config (`limber report --config FILE`, docs/report.md "Report config"): the plots to
// draw, each of a kind the report draws (plot_set.h PlotKind), with its title, time window and
// y axis. Example: cases/slider_crank_report.yaml.
//
//   plots:
//     - joint: R1              # kind reaction (the default): a joint's force or torque
//       frame: R1.j            # ground (default) | joint | a marker ("R1.j") | a body ("crank")
//       quantity: force        # force (default) | torque
//       components: [x, y, magnitude]   # any of x, y, z, magnitude (default: all four)
//     - {kind: probe, body: rod, components: [z]}      # deflection probes; body optional
//     - {kind: modal, body: rod, modes: [2, 5]}        # modal coordinates; modes optional
//     - {kind: drivers, drivers: [D1]}                 # driver efforts; drivers optional
//     - {kind: violation, y_axis: linear, window: [0.1, 0.5], title: Drift}
//   Kinds without keys of their own: deflection, energy, energy_balance, energy_residual,
//   violation, hinge_angles, latch_torques, clearance, peak_stress. Every kind takes title,
//   window [from, to] (s, from < to) and y_axis (log | linear).
//
// Bad input is an InputError "FILE:LINE:COL: expected ..., got ..." (house style §11).
#pragma once

#include "core/error.h"
#include "plot_set.h"

#include <filesystem>
#include <vector>

namespace limber::report {

struct ConfiguredPlot {
  PlotRequest request;
  SourceLocation where;  // the plot's entry in the file (for errors found against the runs)
};

// Reads `path`. Throws InputError naming the file and line on a missing file, a YAML syntax
// error, an unknown kind, a key the kind does not take, a missing joint (reaction) or body
// (modal), an unknown quantity or component, a mode number below 1, a window that is not two
// times in increasing order, a y axis other than log or linear, or an empty list.
std::vector<ConfiguredPlot> read_report_config(const std::filesystem::path& path);

// Checks every configured plot against the runs: a reaction's joint is in at least one run and
// its frame (ground, joint, or a marker or body name) exists in a run holding that joint;
// another kind is drawn for at least one run, its body has that plot there, its modes and
// drivers exist; a window holds a sample of some run. Throws InputError at the plot's line,
// listing what the runs offer.
void check_report_config(const std::vector<ConfiguredPlot>& plots, const std::vector<RunData>& runs);

}  // namespace limber::report
