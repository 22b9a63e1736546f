// Normal modes of a component on its free DOFs (seed paper eq. 4-6):
//   (K_ff - omega^2 M_ff) phi_f = 0,  phi^T M phi = 1,  phi^T K phi = omega^2,
// expanded back to full DOF vectors (fixed DOFs hold zero).
//
// Rigid-body modes of a free (or partly held) component. The caller states how many
// rigid motions the held DOFs leave free (r = unrestrained_rigid_motion(...).cols()).
// With r > 0 the lowest r computed modes are rigid when their frequency is below
// kRigidFrequencyRatio x the frequency of mode r + 1 (the first elastic one); they are
// reported apart (in any mixture: a repeated zero eigenvalue has no preferred basis) and
// never counted as elastic modes. If fewer pass the test, only those are set aside and
// a notice says so; a notice also warns when the first elastic mode is itself below the
// ratio times the next one (a mechanism or a disconnected mesh).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "modal/modal_status.h"
#include "modal/sparse_eigensolver.h"

namespace limber::modal {

// A mode is rigid when f < kRigidFrequencyRatio x f_first_elastic. Round-off puts the
// computed rigid frequencies near sqrt(eps x lambda_max) / 2 pi, about 1e-3 of the first
// elastic frequency for the finest meshes here; two decades separate them safely.
inline constexpr double kRigidFrequencyRatio = 1e-2;

struct NormalModeRequest {
  int count = 0;                          // elastic modes wanted (upper bound with a cut-off)
  std::optional<double> max_frequency_hz; // all elastic modes up to this frequency [Hz]
  int rigid_count = 0;                    // rigid motions left free by the held DOFs (0..6)
  EigenSolverOptions solver;
};

struct NormalModes {
  ModalStatus status = ModalStatus::kOk;
  std::string message;
  std::vector<std::string> notices;
  Eigen::VectorXd eigenvalues;        // elastic omega^2 [1/s^2], ascending
  Eigen::MatrixXd shapes;             // n x count, full DOF vectors, M-normalised
  Eigen::VectorXd rigid_eigenvalues;  // omega^2 of the modes classified rigid (~0)
  Eigen::MatrixXd rigid_shapes;       // n x r
};

// Frequency [Hz] of an eigenvalue omega^2, signed: -sqrt(-lambda)/2pi for lambda < 0
// (round-off on rigid modes).
double frequency_hz(double eigenvalue);

// Lowest elastic modes of (K, M) restricted to `free_dofs` (ascending global indices).
// With a cut-off, the number of eigenpairs asked of ARPACK doubles until the highest one
// computed exceeds the cut-off (or all DOFs are used); the result holds every elastic
// mode up to the cut-off (at most `count` when count > 0). Preconditions (DEMAND):
// count > 0 or a cut-off is set; count + rigid_count <= free_dofs.size().
NormalModes compute_normal_modes(const Eigen::SparseMatrix<double>& stiffness,
                                 const Eigen::SparseMatrix<double>& mass,
                                 const std::vector<int>& free_dofs,
                                 const NormalModeRequest& request);

}  // namespace limber::modal
