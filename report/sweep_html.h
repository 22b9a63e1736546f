// The table of the "Work-precision sweep" section (docs/report.md): every grid point of
// `limber sweep` with its cost and its errors against the reference, as HTML (strings escaped,
// html.h). The section's plot comes from plot_set.h (sweep_plots).
#pragma once

#include "sweep_data.h"

#include <string>

namespace limber::report {

// Empty when the sweep has no points.
std::string sweep_table(const SweepData& sweep);

}  // namespace limber::report
