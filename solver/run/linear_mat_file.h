// linear.mat of `limber linearize`: the state-space model and the tangent matrices of a
// LinearizeSummary as a MATLAB .mat file, level 5 (matio; docs/linearize.md, "MATLAB"), for
// `load` in MATLAB or Octave and scipy.io.loadmat:
//   A, B, C, D               state space (multibody/state_space.h): 2n x 2n, 2n x ni, no x 2n, no x ni
//   M, C_damping, K, Z       tangent mass, damping, stiffness (nv x nv) and null-space basis (nv x n)
//                            (the damping is not called C, which the output matrix is)
//   frequencies_hz, damping_ratios, undamped_hz   the system modes (n x 1)
//   state_names, input_names, output_names, coordinate_names   cell arrays of char (column)
// Matrices are doubles, in the units of linear.h5.
#pragma once

#include <filesystem>

#include "multibody/model.h"
#include "run/linearize_run.h"

namespace limber::run {

// Writes DIR/linear.mat (replacing it) and returns its path. Throws std::runtime_error naming
// the file and the variable when matio fails.
std::filesystem::path write_linear_mat(const multibody::Model& model, const LinearizeSummary& summary,
                                       const std::filesystem::path& directory);

}  // namespace limber::run
