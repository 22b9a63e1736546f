// The flat shell triangle (fe/shell_triangle.h: CST membrane + DKT plate): rigid motions,
// constant-curvature and constant-strain patch tests (flat and rotated in space), and the
// simply supported square plate against Kirchhoff's closed form with its convergence order.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/shell_triangle.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

ShellProperty aluminium(double thickness) {
  ShellProperty p;
  p.name = "al";
  p.material = {"al", 7.0e10, 0.3, 2700.0};
  p.thickness = thickness;
  return p;
}

TEST(ShellTriangle, RigidMotionsCarryNoEnergy) {
  // A scalene triangle tilted in space.
  const std::array<Eigen::Vector3d, 3> corners = {Eigen::Vector3d(0.1, 0.2, 0.3),
                                                  Eigen::Vector3d(1.2, 0.4, 0.1),
                                                  Eigen::Vector3d(0.5, 1.1, 0.9)};
  const ShellTriangleMatrices e = shell_triangle_matrices(corners, aluminium(0.01));
  // Three translations and three rotations about the origin: u = θ × x.
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 18, 1> rigid = Eigen::Matrix<double, 18, 1>::Zero();
    for (int n = 0; n < 3; ++n) {
      if (k < 3) {
        rigid(6 * n + k) = 1.0;
      } else {
        const Eigen::Vector3d theta = Eigen::Vector3d::Unit(k - 3);
        rigid.segment<3>(6 * n) = theta.cross(corners[n]);
        rigid.segment<3>(6 * n + 3) = theta;
      }
    }
    // Relative to |K| |rigid|: round-off of the 18×18 products (1e-15) times a few.
    EXPECT_LT((e.stiffness * rigid).norm(), 1e-12 * e.stiffness.norm() * rigid.norm())
        << "rigid motion " << k;
  }
  // Positive semi-definite with exactly 6 zero eigenvalues.
  const Eigen::SelfAdjointEigenSolver<Matrix18d> eig(e.stiffness);
  const double largest = eig.eigenvalues().maxCoeff();
  EXPECT_GT(eig.eigenvalues()(0), -1e-12 * largest);
  EXPECT_LT(eig.eigenvalues()(5), 1e-12 * largest);
  EXPECT_GT(eig.eigenvalues()(6), 1e-9 * largest);
}

TEST(ShellTriangle, DktCurvatureIsExactForQuadraticDeflections) {
  // w = a x² + b y² + c x y: θx = ∂w/∂y, θy = −∂w/∂x; κ = (−w,xx, −w,yy, −2 w,xy).
  const double a = 0.3, b = -0.7, c = 0.45;
  const TriangleCoordinates xy = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.3, 0.2),
                                  Eigen::Vector2d(0.4, 0.9)};
  Eigen::Matrix<double, 9, 1> dofs;
  for (int n = 0; n < 3; ++n) {
    const double x = xy[n].x(), y = xy[n].y();
    dofs.segment<3>(3 * n) << a * x * x + b * y * y + c * x * y, 2.0 * b * y + c * x,
        -(2.0 * a * x + c * y);
  }
  for (const auto& [xi, eta] : {std::pair{0.2, 0.3}, std::pair{0.5, 0.5}, std::pair{0.0, 0.0}}) {
    const Eigen::Vector3d kappa = dkt_curvature(xy, dofs, xi, eta);
    // Exact up to round-off of the B matrix (entries ~1/A).
    EXPECT_NEAR(kappa(0), -2.0 * a, 1e-13);
    EXPECT_NEAR(kappa(1), -2.0 * b, 1e-13);
    EXPECT_NEAR(kappa(2), -2.0 * c, 1e-13);
  }
}

// A patch of 4 triangles around an off-centre interior node (the classic patch test set-up):
// boundary nodes take the exact field; the interior node must come out exact.
void patch_test(const Eigen::Matrix3d& rotation) {
  const std::array<Eigen::Vector2d, 5> p = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(2.0, 0.0),
                                            Eigen::Vector2d(2.0, 1.5), Eigen::Vector2d(0.0, 1.5),
                                            Eigen::Vector2d(0.7, 0.5)};
  FeModelBuilder builder;
  for (int n = 0; n < 5; ++n) builder.add_node(n + 1, rotation * Eigen::Vector3d(p[n].x(), p[n].y(), 0.0));
  const int property = builder.add_shell_property(aluminium(0.02));
  for (int k = 0; k < 4; ++k) builder.add_triangle({{k, (k + 1) % 4, 4}, property});
  const FeModel model = std::move(builder).build();
  const Eigen::MatrixXd k = Eigen::MatrixXd(assemble(model).stiffness);

  // Exact field in the patch plane: linear membrane, quadratic deflection, θz = ω.
  const auto field = [](const Eigen::Vector2d& q) {
    const double x = q.x(), y = q.y();
    const double a = 2e-3, b = -1e-3, c = 1.5e-3;
    Eigen::Matrix<double, 6, 1> u;
    u << 1e-3 * (1.0 + 2.0 * x + 3.0 * y), 1e-3 * (-1.0 + 0.5 * x + 1.5 * y),
        a * x * x + b * y * y + c * x * y, 2.0 * b * y + c * x, -(2.0 * a * x + c * y),
        0.5 * 1e-3 * (0.5 - 3.0);
    return u;
  };
  // To global axes: translations and rotations rotate alike.
  Eigen::VectorXd exact(30);
  for (int n = 0; n < 5; ++n) {
    const Eigen::Matrix<double, 6, 1> local = field(p[n]);
    exact.segment<3>(6 * n) = rotation * local.head<3>();
    exact.segment<3>(6 * n + 3) = rotation * local.tail<3>();
  }
  // Solve for the interior node (DOFs 24..29) with the boundary prescribed.
  const Eigen::MatrixXd k_ii = k.block(24, 24, 6, 6);
  const Eigen::MatrixXd k_ib = k.block(24, 0, 6, 24);
  const Eigen::VectorXd interior = k_ii.ldlt().solve(-k_ib * exact.head(24));
  // Exact up to the conditioning of K_ii (rotational and translational terms differ by ~1e6).
  EXPECT_LT((interior - exact.tail(6)).norm(), 1e-10 * exact.tail(6).norm())
      << "got " << interior.transpose() << "\nexpected " << exact.tail(6).transpose();
}

TEST(ShellTriangle, PatchTestFlat) { patch_test(Eigen::Matrix3d::Identity()); }

TEST(ShellTriangle, PatchTestRotatedInSpace) {
  patch_test((Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 0.5).normalized())).toRotationMatrix());
}

// Lowest frequency of a simply supported square plate (side 1 m, h = 10 mm) meshed with n × n
// squares split into two triangles each.
double simply_supported_frequency(int n) {
  FeModelBuilder builder;
  const ShellProperty property = aluminium(0.01);
  const int pid = builder.add_shell_property(property);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      builder.add_node(1 + i + (n + 1) * j, Eigen::Vector3d(double(i) / n, double(j) / n, 0.0));
    }
  }
  const auto index = [n](int i, int j) { return i + (n + 1) * j; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      builder.add_triangle({{index(i, j), index(i + 1, j), index(i + 1, j + 1)}, pid});
      builder.add_triangle({{index(i, j), index(i + 1, j + 1), index(i, j + 1)}, pid});
    }
  }
  // w = 0 on the edges; the in-plane DOFs (uncoupled from bending in a flat plate) held.
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const int node = index(i, j);
      for (Dof dof : {Dof::kUx, Dof::kUy, Dof::kRz}) builder.fix(node, dof);
      if (i == 0 || j == 0 || i == n || j == n) builder.fix(node, Dof::kUz);
    }
  }
  return testing::dense_frequencies(std::move(builder).build()).at(0) / (2.0 * std::numbers::pi);
}

TEST(ShellTriangle, SimplySupportedPlateConvergesToKirchhoff) {
  // Kirchhoff (Timoshenko & Woinowsky-Krieger): ω11 = 2 π² / a² √(D / (ρ h)),
  // D = E h³ / (12 (1 − ν²)). Rotary inertia (kept) lowers it by O((h/a)²) ~ 1e-4.
  const double e = 7.0e10, nu = 0.3, rho = 2700.0, h = 0.01;
  const double d = e * h * h * h / (12.0 * (1.0 - nu * nu));
  const double exact = 2.0 * std::numbers::pi * std::numbers::pi * std::sqrt(d / (rho * h)) /
                       (2.0 * std::numbers::pi);
  const double error_8 = std::abs(simply_supported_frequency(8) - exact) / exact;
  const double error_16 = std::abs(simply_supported_frequency(16) - exact) / exact;
  // The DKT converges at second order in the mesh size for frequencies: halving h divides the
  // error by about 4 (accepting 3 to 5.5), and 16 × 16 is within 1 %.
  RecordProperty("relative_error_8x8", std::to_string(error_8));
  RecordProperty("relative_error_16x16", std::to_string(error_16));
  EXPECT_LT(error_16, 1e-2);
  EXPECT_GT(error_8 / error_16, 3.0) << error_8 << " " << error_16;
  EXPECT_LT(error_8 / error_16, 5.5) << error_8 << " " << error_16;
}

}  // namespace
}  // namespace limber::fe
