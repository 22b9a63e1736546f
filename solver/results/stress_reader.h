// The typed reader of results.h5, the stresses (docs/results-format.md, "Stress"): per flexible
// body with stress output, the mesh's peak equivalent stress at every sample and the history of
// the recorded elements. Read on demand (results_reader.h reads the rest): by
// `limber render --color von_mises`, the VTU and XDMF exports and `limber report`.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "results/results_reader.h"

namespace limber::results {

struct StressTrack {
  Eigen::VectorXd peak;          // ns: largest equivalent stress over the mesh [Pa]
  Eigen::VectorXi peak_element;  // ns: its element (0-based: lines, then quads)
  std::vector<int> elements;     // ne recorded elements (0-based, ascending)
  Eigen::VectorXd time;          // nss history times [s]
  Eigen::MatrixXd equivalent;    // nss x ne [Pa]: beams' extreme-fibre, shells' von Mises

  // The history row at or before time t (the first row before the first time); -1 when empty.
  Eigen::Index row_at(double t) const;
  // Per element of the whole mesh (lines, then quads) the equivalent stress of history row
  // `row` [Pa]; elements not recorded are NaN (drawn in the "no data" colour).
  Eigen::VectorXd element_values(Eigen::Index row, int element_count) const;
};

// One entry per body of `results` (same order): the body's stresses, or none when it has no
// stress output. Series are cut to results' sample count and to the last complete history row.
// Throws InputError when a stress group is malformed.
std::vector<std::optional<StressTrack>> read_stress_tracks(const Results& results);

}  // namespace limber::results
