// Which plots a report holds, built from run data (no drawing here): reactions per joint in
// ground axes and in the joint frame (seed paper Figs. 4, 5, 9), comparisons of one reaction
// component over several runs (Figs. 6, 10), driver efforts, energies and the balance's
// residual, hinge angles and latch torques, clearance between bodies, deflections, modal
// coordinates and constraint violations versus time, and the key quantities of each mode set
// `limber select` ran (Fig. 6).
#pragma once

#include "plot.h"
#include "run_data.h"

#include <string>
#include <vector>

namespace limber::report {

enum class PlotSection {
  kReactions, kSelection, kDrivers, kEnergy, kHinges, kClearance, kDeflection, kViolation,
  kComparison, kStress
};

struct NamedPlot {
  PlotSection section = PlotSection::kReactions;
  std::string file;     // PNG file name inside the report's images/ folder
  std::string caption;  // plain text (escaped when written)
  PlotSpec spec;
};

// The plots of one run; file names start with `prefix` (e.g. "run1_").
std::vector<NamedPlot> run_plots(const RunData& run, const std::string& prefix);

// One plot per quantity of selection/key_series.csv, in the file's order, overlaying that
// quantity of every mode set; legend entries are the set names, "(chosen)" or "(reference)"
// appended from comparison.csv
// (unless the set is named after its role). File names start with `prefix`.
std::vector<NamedPlot> selection_plots(const SelectionData& selection, const std::string& prefix);

// One plot per joint name present in two or more runs and per force component (joint frame),
// overlaying that component of every run holding the joint; legend entries are `labels`.
std::vector<NamedPlot> comparison_plots(const std::vector<RunData>& runs,
                                        const std::vector<std::string>& labels);

}  // namespace limber::report
