// The report's plots of a run's acceleration probes (docs/report.md, "Shock response spectra";
// the method: docs/shock-response-spectrum.md): each probe's absolute acceleration in ground
// axes against time, and its maximax shock response spectrum on log-log axes, natural frequency
// [Hz] against peak absolute acceleration [g], one curve per window (whole run, start, each
// latch), the largest of the three ground axes at each frequency, the window named in the
// legend with its span. The per-axis values are in DIR/srs_<probe>.csv.
#pragma once

#include "plot_set.h"
#include "run_data.h"

#include <string>
#include <vector>

namespace limber::report {

// The legend entry of window w: "whole run (0-4.7 s)", "latch L1 at 2.97 s (2.97-3.27 s)".
std::string shock_window_label(const ShockSpectraData& spectra, std::size_t w);

// Per probe: its acceleration history, then its spectrum when the file has one. File names
// start with `prefix`; section PlotSection::kShock.
std::vector<NamedPlot> shock_plots(const RunData& run, const std::string& prefix);

}  // namespace limber::report
