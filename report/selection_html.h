// The tables of the "Mode selection" section (docs/report.md): the ranking of the reaction
// components on flexible bodies and the comparison of the mode sets `limber select` ran, as
// HTML. Every string from the CSV files is escaped (html.h). The section's plots come from
// plot_set.h (selection_plots).
#pragma once

#include "run_data.h"

#include <string>

namespace limber::report {

// Ranking table (kept rows of class "kept", minimum-norm reactions marked as the joints table
// decides them, plot_set.h is_indeterminate_component, in the body's axes), then the comparison
// table (rows of class "chosen" and "reference", errors in percent); a part without rows is left
// out. Empty when both are, or when `run` has no selection.
std::string selection_tables(const RunData& run);

}  // namespace limber::report
