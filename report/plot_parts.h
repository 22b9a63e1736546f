// Small pieces every plot builder of limber_report shares (plot_set.cpp, run_plots.cpp,
// reaction_plot.cpp): the time axis label, the axis letters, a plot's kind tag and series as
// curves. Internal to limber_report.
#pragma once

#include "plot_set.h"

#include <array>
#include <string>
#include <vector>

namespace limber::report {

inline constexpr const char* kTimeLabel = "time [s]";
inline constexpr std::array<const char*, 3> kAxes{"x", "y", "z"};

// Marks the last plot with what it shows (a report config selects plots by kind and subject).
inline void tag(std::vector<NamedPlot>& plots, PlotKind kind, const std::string& subject) {
  plots.back().kind = kind;
  plots.back().subject = subject;
}

inline std::vector<Curve> series_curves(const Eigen::VectorXd& time, const std::vector<Series>& series) {
  std::vector<Curve> curves;
  for (const Series& s : series) curves.push_back({s.name, time, s.values});
  return curves;
}

}  // namespace limber::report
