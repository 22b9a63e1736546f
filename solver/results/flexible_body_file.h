// A flexible body's fixed data in results.h5 (results_writer.h, docs/results-format.md): its
// mesh (nodes, ids, elements, tube radius, beam sections) and its modes (translations,
// frequencies, kinds and labels), written once when the body is declared.
#pragma once

#include <hdf5.h>

#include "results/results_writer.h"

namespace limber::results {

// Writes /bodies/<body>/mesh and /bodies/<body>/modes under `body_group`. Throws on an HDF5
// failure. Precondition: the body's sizes are consistent (ResultsWriter::add_flexible_body).
void write_mesh_and_modes(hid_t body_group, const FlexibleBodySpec& body);

}  // namespace limber::results
