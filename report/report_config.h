// A report config (`limber report --config FILE`, docs/report.md "Report config"): the reaction
// plots to draw, each a joint's force or torque in one frame with the components chosen.
//
//   plots:
//     - joint: R1              # required: a joint name
//       frame: R1.j            # ground (default) | joint | a marker ("R1.j") | a body ("crank")
//       quantity: force        # force (default) | torque
//       components: [x, y, magnitude]   # any of x, y, z, magnitude (default: all four)
//       title: Pin force in the crank's frame   # optional plot title
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
// error, an unknown key, a missing joint, an unknown quantity or component, or an empty list.
std::vector<ConfiguredPlot> read_report_config(const std::filesystem::path& path);

// Checks every configured plot against the runs: its joint is in at least one run and its
// frame (ground, joint, or a marker or body name) exists in a run holding that joint. Throws
// InputError at the plot's line, listing the joints or frames the runs offer.
void check_report_config(const std::vector<ConfiguredPlot>& plots, const std::vector<RunData>& runs);

}  // namespace limber::report
