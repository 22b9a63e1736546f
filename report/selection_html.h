// The tables of the "Mode selection" section (docs/report.md): the ranking of the reaction
// components on flexible bodies and the comparison of the mode sets `limber select` ran, as
// HTML. Every string from the CSV files is escaped (html.h). The section's plots come from
// plot_set.h (selection_plots).
#pragma once

#include "selection_data.h"

#include <string>

namespace limber::report {

// Ranking table (kept rows of class "kept", minimum-norm reactions marked), then the comparison
// table (rows of class "chosen" and "reference", errors in percent); a part without rows is left
// out. Empty when both are.
std::string selection_tables(const SelectionData& selection);

}  // namespace limber::report
