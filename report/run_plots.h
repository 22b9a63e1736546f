// The plots of one run as drawn without a report config (plot_set.h's run_plots): reactions per
// joint and frame, the mode sets `limber select` compared, the sweep's grid, driver efforts,
// energies and the balance, hinge angles and latch torques, clearance, deflections, probes and
// modal coordinates, peak stresses, constraint violations and shock plots. Internal to
// limber_report.
#pragma once

#include "plot_set.h"

#include <string>
#include <vector>

namespace limber::report {

// Every plot of `run` without a report config, file names starting with `prefix`.
std::vector<NamedPlot> default_run_plots(const RunData& run, const std::string& prefix, const PlotOptions& options);

}  // namespace limber::report
