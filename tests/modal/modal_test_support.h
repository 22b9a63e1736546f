// Helpers of the modal tests: spring-mass chains (hand-built K, M), the seed paper's
// steel rod as an FE model, dense reference eigen-solutions and matrix checks.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"

namespace limber::modal::testing {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct Chain {
  SparseMatrix stiffness;
  SparseMatrix mass;
};

// n unit masses joined by springs k_i; `grounded` adds a spring to ground before mass 0.
// springs.size() == n - 1 (+1 when grounded). Lumped (diagonal) masses `masses`.
inline Chain spring_chain(const std::vector<double>& springs, const std::vector<double>& masses,
                          bool grounded) {
  const int n = static_cast<int>(masses.size());
  std::vector<Eigen::Triplet<double>> k;
  std::vector<Eigen::Triplet<double>> m;
  int s = 0;
  if (grounded) k.emplace_back(0, 0, springs[s++]);
  for (int i = 0; i + 1 < n; ++i, ++s) {
    k.emplace_back(i, i, springs[s]);
    k.emplace_back(i + 1, i + 1, springs[s]);
    k.emplace_back(i, i + 1, -springs[s]);
    k.emplace_back(i + 1, i, -springs[s]);
  }
  for (int i = 0; i < n; ++i) m.emplace_back(i, i, masses[static_cast<std::size_t>(i)]);
  Chain chain{SparseMatrix(n, n), SparseMatrix(n, n)};
  chain.stiffness.setFromTriplets(k.begin(), k.end());
  chain.mass.setFromTriplets(m.begin(), m.end());
  return chain;
}

// Steel of the seed paper's connecting rod (docs/seed-paper.md, example 1).
inline fe::Material paper_steel() { return {"steel", 206.8e9, 0.3, 7820.0}; }

// Section 0.01 m (local y) x 0.02 m (local z).
inline fe::BeamProperty rod_property(bool rotary_inertia) {
  fe::BeamProperty property;
  property.name = "rod";
  property.material = paper_steel();
  property.section = fe::rectangle_section(0.01, 0.02);
  property.rotary_inertia = rotary_inertia;
  return property;
}

// Straight rod from `start` along +x, length `length`, `elements` beams, local axes =
// global axes (orientation +y: local z = x × y = +z). `fixed_nodes` are clamped (6 DOFs).
inline fe::FeModel rod_model(int elements, bool rotary_inertia, const std::vector<int>& fixed_nodes,
                             double length = 1.0,
                             const Eigen::Vector3d& start = Eigen::Vector3d::Zero()) {
  fe::FeModelBuilder builder;
  fe::StraightBeamMesh mesh;
  mesh.start = start;
  mesh.end = start + length * Eigen::Vector3d::UnitX();
  mesh.elements = elements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = builder.add_beam_property(rod_property(rotary_inertia));
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (int node : fixed_nodes) {
    for (int d = 0; d < fe::kDofsPerNode; ++d) {
      builder.fix(nodes[static_cast<std::size_t>(node)], static_cast<fe::Dof>(d));
    }
  }
  return std::move(builder).build();
}

// Ascending eigenvalues of (K, M) on `dofs` by a dense generalized solver (Cholesky of M).
inline Eigen::VectorXd dense_eigenvalues(const SparseMatrix& k, const SparseMatrix& m) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      Eigen::MatrixXd(k), Eigen::MatrixXd(m), Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
  return solver.eigenvalues();
}

inline double hz(double omega2) { return std::sqrt(omega2) / (2.0 * std::numbers::pi); }

// ||Phi^T M Phi - I||_max.
inline double orthonormality_error(const SparseMatrix& m, const Eigen::MatrixXd& phi) {
  const Eigen::MatrixXd g = phi.transpose() * (m * phi);
  return (g - Eigen::MatrixXd::Identity(g.rows(), g.cols())).cwiseAbs().maxCoeff();
}

// max |off-diagonal of Phi^T K Phi| / max |diagonal|.
inline double k_diagonality_error(const SparseMatrix& k, const Eigen::MatrixXd& phi) {
  Eigen::MatrixXd g = phi.transpose() * (k * phi);
  const double diag = g.diagonal().cwiseAbs().maxCoeff();
  g.diagonal().setZero();
  return g.cwiseAbs().maxCoeff() / diag;
}

}  // namespace limber::modal::testing
