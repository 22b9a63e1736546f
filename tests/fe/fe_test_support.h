// Helpers shared by the FE tests: the seed paper's steel rod, an InputError catcher and a
// dense generalized eigen-solver for small models.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/fe_model.h"

namespace limber::fe::testing {

// Steel of the seed paper's connecting rod (docs/seed-paper.md, example 1).
inline Material paper_steel() { return {"steel", 206.8e9, 0.3, 7820.0}; }

// The paper's rod section 0.01 m (local y) x 0.02 m (local z).
inline BeamProperty paper_rod_property(bool timoshenko = false, bool rotary_inertia = true) {
  BeamProperty property;
  property.name = "rod";
  property.material = paper_steel();
  property.section = rectangle_section(0.01, 0.02);
  property.timoshenko = timoshenko;
  property.rotary_inertia = rotary_inertia;
  return property;
}

// what() of the InputError thrown by `action`, or "no InputError" when none is thrown.
template <typename Action>
std::string input_error_of(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "no InputError";
}

// Natural circular frequencies [rad/s] of the free DOFs, ascending, by a dense
// generalized symmetric eigen-solver (small models only). Tiny negative eigenvalues of
// rigid-body modes are reported as -sqrt(|lambda|) so that they stay "near zero".
inline std::vector<double> dense_frequencies(const FeModel& model) {
  const StructuralMatrices matrices = assemble(model);
  const std::vector<int> dofs = free_dofs(model);
  const Eigen::MatrixXd k = Eigen::MatrixXd(restrict_to(matrices.stiffness, dofs));
  const Eigen::MatrixXd m = Eigen::MatrixXd(restrict_to(matrices.mass, dofs));
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      k, m, Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
  std::vector<double> omega;
  for (double lambda : solver.eigenvalues()) {
    omega.push_back(lambda >= 0.0 ? std::sqrt(lambda) : -std::sqrt(-lambda));
  }
  std::sort(omega.begin(), omega.end());
  return omega;
}

inline double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

}  // namespace limber::fe::testing
