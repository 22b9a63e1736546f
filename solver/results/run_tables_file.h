// The tables results.h5 receives at the end of a run (results_writer.h, docs/results-format.md):
// the event peaks (/event_peaks) and the singular passages (/constraints/singular_passages).
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

#include "results/event_peaks.h"

namespace limber::results {

// Writes the group /event_peaks into `file`: the window and joint tables, then the [nw, nj] and
// [nw, nj, 3] peak tables row-major. Throws on an HDF5 failure. Precondition: no such group.
void write_event_peaks(hid_t file, const EventPeaks& peaks);

// Writes the group singular_passages under `constraints` (/constraints): one row per passage.
// Throws on an HDF5 failure. Precondition: equal lengths, no such group.
void write_singular_passages(hid_t constraints, const std::vector<double>& time, const std::vector<double>& ratio,
                             const std::vector<std::string>& joints, const std::vector<double>& velocity_jump);

}  // namespace limber::results
