// Normal modes on free DOFs: the seed paper's free-free steel rod (rigid-mode
// classification, Euler-Bernoulli closed forms) and the cut-off iteration.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "modal/normal_modes.h"
#include "modal/rigid_body_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

// Free-free Euler-Bernoulli roots beta_n L of cos(bL) cosh(bL) = 1 (Blevins, "Formulas for
// Natural Frequency and Mode Shape", table 8-1).
constexpr double kFreeFreeRoots[] = {4.730040744862704, 7.853204624095838, 10.995607838001671,
                                     14.137165491257464, 17.278759657399480, 20.420352245626059};

struct BendingMode {
  double frequency_hz;
  double root;  // beta L
};

// Bending modes of the 1 m rod in both planes, ascending (first 6 of each).
std::vector<BendingMode> euler_bernoulli_free_free() {
  const fe::BeamProperty rod = testing::rod_property(false);
  const double rho_a = rod.material.density * rod.section.area;
  std::vector<BendingMode> modes;
  for (double inertia : {rod.section.inertia_y, rod.section.inertia_z}) {
    for (double root : kFreeFreeRoots) {
      modes.push_back({root * root * std::sqrt(rod.material.youngs_modulus * inertia / rho_a) /
                           (2.0 * std::numbers::pi),
                       root});
    }
  }
  std::sort(modes.begin(), modes.end(),
            [](const BendingMode& a, const BendingMode& b) { return a.frequency_hz < b.frequency_hz; });
  return modes;
}

// M-distance of the columns of R from span(Psi): ||(I - Psi (Psi^T M Psi)^-1 Psi^T M) R||_M.
double distance_from_rigid_span(const Eigen::SparseMatrix<double>& m, const Eigen::MatrixXd& psi,
                                const Eigen::MatrixXd& r) {
  const Eigen::MatrixXd m_psi = m * psi;
  const Eigen::MatrixXd rest = r - psi * (psi.transpose() * m_psi).ldlt().solve(m_psi.transpose() * r);
  return std::sqrt((rest.transpose() * (m * rest)).diagonal().maxCoeff());
}

TEST(NormalModes, FreeFreeRodHasSixRigidModesAndEulerBernoulliBending) {
  // Seed paper rod: 1 m, 0.01 x 0.02 m, 100 elements, steel; no rotary inertia so that the
  // Euler-Bernoulli closed form applies exactly in the continuum limit.
  const fe::FeModel model = testing::rod_model(100, false, {});
  const fe::StructuralMatrices matrices = fe::assemble(model);
  const Eigen::MatrixXd psi = rigid_body_modes(model);
  NormalModeRequest request;
  request.count = 10;
  request.rigid_count = static_cast<int>(unrestrained_rigid_motion(psi, {}).cols());
  ASSERT_EQ(request.rigid_count, 6);
  const NormalModes modes =
      compute_normal_modes(matrices.stiffness, matrices.mass, fe::free_dofs(model), request);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;
  EXPECT_TRUE(modes.notices.empty());

  // Six rigid modes, far below the first elastic one, spanning exactly span(Psi).
  ASSERT_EQ(modes.rigid_eigenvalues.size(), 6);
  const std::vector<BendingMode> exact = euler_bernoulli_free_free();
  for (Eigen::Index i = 0; i < 6; ++i) {
    EXPECT_LT(std::abs(frequency_hz(modes.rigid_eigenvalues[i])),
              kRigidFrequencyRatio * exact[0].frequency_hz);
  }
  // Rigid vectors are exact null vectors up to the solver's round-off (~1e-9 in M-norm for
  // this conditioning); 1e-6 separates them clearly from any elastic content (M-norm 1).
  EXPECT_LT(distance_from_rigid_span(matrices.mass, psi, modes.rigid_shapes), 1e-6);

  // The ten lowest elastic modes are the bending modes of both planes.
  ASSERT_EQ(modes.eigenvalues.size(), 10);
  for (int i = 0; i < 10; ++i) {
    const BendingMode& reference = exact[static_cast<std::size_t>(i)];
    // Cubic Hermite elements with consistent mass over-estimate the frequency by
    // (beta h)^4 / 1440 to leading order (measured: 1.2e-6 for beta h = 0.204, mode 10);
    // bound: twice that.
    const double beta_h = reference.root / 100.0;
    EXPECT_NEAR(frequency_hz(modes.eigenvalues[i]) / reference.frequency_hz, 1.0,
                std::pow(beta_h, 4) / 720.0)
        << "elastic mode " << i + 1;
  }
  // Elastic modes are M-orthogonal to every rigid motion (exact eigenvectors of a
  // different eigenvalue): relative to their unit M-norm, round-off only.
  const Eigen::MatrixXd coupling = (matrices.mass * psi).transpose() * modes.shapes;
  EXPECT_LT(coupling.cwiseAbs().maxCoeff(), 1e-8);
}

TEST(NormalModes, CutOffIteratesUntilEveryModeBelowItIsFound) {
  // Free-free rod, 40 elements: all elastic modes up to 1500 Hz (13 of them: 7 + 5 bending,
  // 1 torsion) need a second, larger ARPACK run after the first 16 eigenpairs.
  const fe::FeModel model = testing::rod_model(40, true, {});
  const fe::StructuralMatrices matrices = fe::assemble(model);
  NormalModeRequest request;
  request.max_frequency_hz = 1500.0;
  request.rigid_count = 6;
  const std::vector<int> dofs = fe::free_dofs(model);
  const NormalModes modes = compute_normal_modes(matrices.stiffness, matrices.mass, dofs, request);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;

  // Second method: a dense solution of the same 246-DOF problem.
  const Eigen::VectorXd dense = testing::dense_eigenvalues(matrices.stiffness, matrices.mass);
  std::vector<double> expected;
  for (Eigen::Index i = 6; i < dense.size(); ++i) {
    if (testing::hz(dense[i]) <= 1500.0) expected.push_back(dense[i]);
  }
  EXPECT_EQ(expected.size(), 13u);
  ASSERT_EQ(static_cast<std::size_t>(modes.eigenvalues.size()), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    // Backward-stable solvers, lambda_max / lambda ~ 1e8 at worst: relative agreement to
    // ~1e-8 (see the sparse eigen-solver test); bound 1e-7.
    EXPECT_NEAR(modes.eigenvalues[static_cast<Eigen::Index>(i)] / expected[i], 1.0, 1e-7);
  }

  // With count = 5 as well, the cut-off is bounded by the count.
  request.count = 5;
  const NormalModes bounded = compute_normal_modes(matrices.stiffness, matrices.mass, dofs, request);
  ASSERT_EQ(bounded.status, ModalStatus::kOk);
  EXPECT_EQ(bounded.eigenvalues.size(), 5);
}

TEST(NormalModes, RestrainedComponentHasNoRigidModes) {
  // Cantilever rod (node 0 clamped): first weak-plane bending f = 1.8751^2 / (2 pi)
  // sqrt(E Iz / (rho A)) / L^2 (Blevins table 8-1).
  const fe::FeModel model = testing::rod_model(50, false, {0});
  const fe::StructuralMatrices matrices = fe::assemble(model);
  NormalModeRequest request;
  request.count = 2;
  request.rigid_count = 0;
  const NormalModes modes =
      compute_normal_modes(matrices.stiffness, matrices.mass, fe::free_dofs(model), request);
  ASSERT_EQ(modes.status, ModalStatus::kOk);
  EXPECT_EQ(modes.rigid_eigenvalues.size(), 0);
  const fe::BeamProperty rod = testing::rod_property(false);
  const double root = 1.8751040687119611;
  const double f1 = root * root *
                    std::sqrt(rod.material.youngs_modulus * rod.section.inertia_z /
                              (rod.material.density * rod.section.area)) /
                    (2.0 * std::numbers::pi);
  // Hermite cubic discretisation error ~ (beta h)^4 / 1440 ~ 1e-9; bound 1e-7.
  EXPECT_NEAR(frequency_hz(modes.eigenvalues[0]) / f1, 1.0, 1e-7);
  // Fixed DOFs hold zero in the expanded shapes.
  EXPECT_EQ(modes.shapes.topRows(6).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace limber::modal
