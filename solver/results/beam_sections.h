// The beams' cross-sections of a flexible body's mesh group (results.h5, docs/results-format.md
// "Beam sections"): what render/beam_solids.h sweeps along each beam. Written by the results
// writer, read by render and the ParaView export through read_beam_sections.
//
// Outlines are polygons in a beam's local y-z plane about its centroid, (y, z) [m]:
// counter-clockwise about local x; a hollow one (tube, box) is an outer polygon followed by an
// inner one with as many points, inner point i across from outer point i (fe/section_outline.h).
#pragma once

#include <hdf5.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace limber::results {

class H5Reader;

struct BeamSections {
  // nl x 3: each beam's local y axis in the body frame (unit; local x runs from its first node
  // to its second, z = x × y).
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> y_axes;
  std::vector<int> outline;  // nl: index into the outline table
  // The table of distinct outlines: outline k is points rows offsets[k] .. offsets[k + 1] - 1.
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> points;  // np x 2, (y, z) [m]
  std::vector<int> offsets;                                          // no + 1, offsets[0] = 0
  std::vector<std::int8_t> hollow;      // no: 1 = second half of the points is the inner polygon
  std::vector<std::int8_t> equivalent;  // no: 1 = stand-in from A and I (section shape unknown)

  bool empty() const { return outline.empty(); }
  int outline_count() const { return static_cast<int>(hollow.size()); }
};

// Writes `sections` (not empty) into the open mesh group `mesh`; false on an HDF5 failure
// (the caller names the file). Precondition (LIMBER_DEMAND): consistent sizes.
bool try_write_beam_sections(hid_t mesh, const BeamSections& sections);

// The sections of mesh group `mesh` (e.g. "/bodies/rod/mesh") whose beams are `line_count`
// lines: empty when the file has none (files before them, or a body without beams). Throws
// InputError (naming the file) when they are present but inconsistent: sizes, indices out of
// range, an outline of fewer than 3 points (per polygon), a hollow outline of an odd count,
// axes that are not unit vectors.
BeamSections read_beam_sections(const H5Reader& file, const std::string& mesh, long line_count);

}  // namespace limber::results
