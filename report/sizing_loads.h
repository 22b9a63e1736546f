// "Loads for sizing" (issue 25): per hinge and per event window, the peak reaction of every run
// in the report, from results.h5's /event_peaks (tracked at every integrator step, not at the
// samples; docs/results-format.md, "Event peaks"), and, with several runs, how far the runs
// are apart. The table a structures engineer sizes hinges, latches and hold-downs from.
#pragma once

#include <string>
#include <vector>

#include "report_html.h"

namespace limber::report {

// The section's HTML (id "sizing"), or "" when no run has event peaks. Rows: every revolute
// joint in every window, and the other joints in the first window (hold-downs carry their
// largest load before they let go); a row none of the runs loads is left out.
std::string sizing_loads_section(const std::vector<RunSection>& runs);

}  // namespace limber::report
