// Single-element checks of the flat shell (fe/shell_element.h): rigid-body modes of the
// stiffness, mass properties of the consistent mass under rigid motions, symmetry, and the
// shape checks that throw InputError.
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "fe/shell_element.h"
#include "fe/shell_frame.h"
#include "fe_test_support.h"
#include "shell_test_quads.h"

namespace limber::fe {
namespace {

using testing::Corners;
using testing::kDistorted;
using testing::kOffset;
using testing::kRectangle;
using testing::kSmallWarp;
using testing::placed;
using testing::skew;
using testing::tilted_rotation;
using Matrix24x6d = Eigen::Matrix<double, 24, 6>;

ShellProperty steel_shell(double thickness) { return {"panel", testing::paper_steel(), thickness}; }

// Rigid-body modes about the global origin: columns are translations along x, y, z and
// small rotations about x, y, z (u = θ × r, nodal rotation θ).
Matrix24x6d rigid_modes(const Corners& corners) {
  Matrix24x6d psi = Matrix24x6d::Zero();
  for (int k = 0; k < 4; ++k) {
    psi.block<3, 3>(6 * k, 0).setIdentity();
    psi.block<3, 3>(6 * k, 3) = -skew(corners[k]);
    psi.block<3, 3>(6 * k + 3, 3).setIdentity();
  }
  return psi;
}

// Counts eigenvalues of K below `zero_tolerance` × the largest, and returns the smallest
// eigenvalue above it relative to the largest.
struct Spectrum {
  int zero_count = 0;
  double first_nonzero_ratio = 0.0;
};
Spectrum spectrum(const Matrix24d& k, double zero_tolerance) {
  const Eigen::SelfAdjointEigenSolver<Matrix24d> solver(k, Eigen::EigenvaluesOnly);
  const auto& lambda = solver.eigenvalues();
  const double largest = lambda.maxCoeff();
  Spectrum s;
  for (int i = 0; i < 24; ++i) {
    if (std::abs(lambda(i)) <= zero_tolerance * largest) ++s.zero_count;
  }
  s.first_nonzero_ratio = lambda(s.zero_count) / largest;
  return s;
}

void expect_six_rigid_modes(const Corners& corners, double thickness) {
  const ShellElementMatrices e = shell_element_matrices(corners, steel_shell(thickness));
  // Rigid motions produce no force: round-off of K entries ~1e-16 |K| times 24 terms.
  const Matrix24x6d forces = e.stiffness * rigid_modes(corners);
  const double scale = e.stiffness.norm() * rigid_modes(corners).norm();
  EXPECT_LT(forces.norm(), 1e-13 * scale);
  // Exactly six zero eigenvalues (round-off level, 1e-12 of the largest), and the next one is
  // a real stiffness (the softest mode here, plate bending, is 8e-7 to 4e-6 of the largest;
  // a mechanism would sit at round-off, ~1e-16).
  const Spectrum s = spectrum(e.stiffness, 1e-12);
  EXPECT_EQ(s.zero_count, 6);
  EXPECT_GT(s.first_nonzero_ratio, 1e-8);
}

TEST(ShellElement, RectangleHasExactlySixRigidBodyModes) {
  expect_six_rigid_modes(placed(kRectangle), 0.02);
}

TEST(ShellElement, DistortedQuadHasExactlySixRigidBodyModes) {
  expect_six_rigid_modes(placed(kDistorted), 0.05);
}

TEST(ShellElement, WarpedQuadHasExactlySixRigidBodyModes) {
  expect_six_rigid_modes(placed(kDistorted, kSmallWarp), 0.05);
}

TEST(ShellElement, MatricesAreSymmetric) {
  const ShellElementMatrices e =
      shell_element_matrices(placed(kDistorted, kSmallWarp), steel_shell(0.05));
  // The element symmetrises its triple products; exact symmetry is expected.
  EXPECT_EQ((e.stiffness - e.stiffness.transpose()).norm(), 0.0);
  EXPECT_EQ((e.mass - e.mass.transpose()).norm(), 0.0);
  // M positive definite (drilling inertia included): Cholesky succeeds.
  EXPECT_EQ(Eigen::LLT<Matrix24d>(e.mass).info(), Eigen::Success);
}

TEST(ShellElement, RigidBodyMassPropertiesOfARectangle) {
  // Rectangle a × b, thickness t, tilted and offset: Ψᵀ M Ψ must be the rigid-body mass
  // matrix [[m I, −m [c]×], [m [c]×, I_O]] with I_O = R I_c Rᵀ + m (|c|² I − c cᵀ) and, in the
  // element axes, I_c = m/12 diag(b² + t², a² + t², a² + b² + t²) (the t² terms: rotary inertia
  // ρ t³/12 on θx, θy and the documented drilling inertia on θz).
  const double a = 0.4, b = 0.3, t = 0.02;
  const Corners corners = placed(kRectangle);
  const ShellProperty property = steel_shell(t);
  const double m = property.material.density * a * b * t;
  const Eigen::Vector3d c = kOffset;
  const Eigen::Matrix3d r = tilted_rotation();
  const Eigen::Matrix3d inertia_c =
      m / 12.0 * Eigen::Vector3d(b * b + t * t, a * a + t * t, a * a + b * b + t * t).asDiagonal();
  Eigen::Matrix<double, 6, 6> expected;
  expected << m * Eigen::Matrix3d::Identity(), -m * skew(c), m * skew(c),
      r * inertia_c * r.transpose() +
          m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());

  const ShellElementMatrices e = shell_element_matrices(corners, property);
  const Eigen::Matrix<double, 6, 6> rigid =
      rigid_modes(corners).transpose() * e.mass * rigid_modes(corners);
  // 2×2 Gauss integrates N_i N_j exactly: agreement to round-off (1e-12 of the largest entry).
  EXPECT_LT((rigid - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(ShellElement, MassAndCentroidOfADistortedQuad) {
  // Total mass ρ t A and first moment m c with A, c from the polygon (shoelace) formulas.
  const double t = 0.05;
  const ShellProperty property = steel_shell(t);
  double area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& p = kDistorted[k];
    const Eigen::Vector2d& q = kDistorted[(k + 1) % 4];
    const double cross = p.x() * q.y() - q.x() * p.y();
    area += 0.5 * cross;
    moment += cross * (p + q) / 6.0;
  }
  const double m = property.material.density * t * area;
  const Eigen::Vector2d centroid_2d = moment / area;
  const Eigen::Vector3d centroid =
      kOffset + tilted_rotation() * Eigen::Vector3d(centroid_2d.x(), centroid_2d.y(), 0.0);

  const Corners corners = placed(kDistorted);
  const ShellElementMatrices e = shell_element_matrices(corners, property);
  const Eigen::Matrix<double, 6, 6> rigid =
      rigid_modes(corners).transpose() * e.mass * rigid_modes(corners);
  // Exact integration again: round-off tolerance.
  EXPECT_NEAR(rigid(0, 0), m, 1e-12 * m);
  EXPECT_NEAR(rigid(2, 2), m, 1e-12 * m);
  // Block (rotation, translation) = m [c]×.
  const Eigen::Matrix3d expected = m * skew(centroid);
  EXPECT_LT((rigid.block<3, 3>(3, 0) - expected).cwiseAbs().maxCoeff(),
            1e-12 * m * centroid.norm());
}

TEST(ShellElement, FrameFollowsTheNodeOrder) {
  // e3 from the diagonals' cross product: the rectangle's normal is the tilted z axis.
  const ShellFrame frame = shell_frame(placed(kRectangle));
  EXPECT_LT((frame.rotation_WL.col(2) - tilted_rotation().col(2)).norm(), 1e-14);
  EXPECT_NEAR(frame.area, 0.4 * 0.3, 1e-15);
}

TEST(ShellElement, RejectsBadShapes) {
  const ShellProperty property = steel_shell(0.01);
  const auto error = [&](const Corners& corners) {
    return testing::input_error_of([&] { shell_element_matrices(corners, property); });
  };
  const auto flat = [](std::array<Eigen::Vector2d, 4> xy, std::array<double, 4> z = {}) {
    Corners c;
    for (int k = 0; k < 4; ++k) c[k] = Eigen::Vector3d(xy[k].x(), xy[k].y(), z[k]);
    return c;
  };
  // Warp ratio 0.06 / 1 above the 0.05 limit.
  EXPECT_NE(error(flat({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {0.06, -0.06, 0.06, -0.06}))
                .find("warped shell quad: expected a warp ratio"),
            std::string::npos);
  // Just inside the limit is accepted.
  EXPECT_EQ(error(flat({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {0.04, -0.04, 0.04, -0.04})),
            "no InputError");
  // A dart (reflex corner at node 3).
  EXPECT_NE(error(flat({{{0, 0}, {2, 0}, {0.5, 0.5}, {0, 2}}})).find("non-convex"),
            std::string::npos);
  // Collapsed edge (nodes 3 and 4 coincide): a zero corner.
  EXPECT_NE(error(flat({{{0, 0}, {1, 0}, {1, 1}, {1, 1}}})).find("expected every corner ratio"),
            std::string::npos);
  // Crossed (bow-tie) quad: parallel diagonals.
  EXPECT_NE(error(flat({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}})).find("degenerate shell quad"),
            std::string::npos);
  // All corners on a line.
  EXPECT_NE(error(flat({{{0, 0}, {1, 0}, {2, 0}, {3, 0}}})).find("degenerate shell quad"),
            std::string::npos);
}

}  // namespace
}  // namespace limber::fe
