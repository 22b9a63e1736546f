// The PSHELL-style shell section (fe_model.h ShellProperty: bending_ratio 12I/T³, shear_ratio
// TS/T, nonstructural_mass NSM): the defaults give today's element, the bending ratio scales
// the plate bending and nothing else, and the non-structural mass joins the rigid-body mass.
// Plate frequencies with a sandwich section: test_shell_plate.cpp.
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "fe/shell_element.h"
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
using Vector24d = Eigen::Matrix<double, 24, 1>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// Rigid-body modes about the global origin (translations, then small rotations u = θ × r).
Eigen::Matrix<double, 24, 6> rigid_modes(const Corners& corners) {
  Eigen::Matrix<double, 24, 6> psi = Eigen::Matrix<double, 24, 6>::Zero();
  for (int k = 0; k < 4; ++k) {
    psi.block<3, 3>(6 * k, 0).setIdentity();
    psi.block<3, 3>(6 * k, 3) = -skew(corners[k]);
    psi.block<3, 3>(6 * k + 3, 3).setIdentity();
  }
  return psi;
}

// A honeycomb-like section: thin faces (T), a large bending ratio and a core + equipment NSM.
ShellProperty sandwich_section() {
  ShellProperty property{"sandwich", {"cfrp", 60e9, 0.3, 1600.0}, 5e-4};
  property.bending_ratio = 7650.75;
  property.shear_ratio = 0.31;
  property.nonstructural_mass = 1.6;
  return property;
}

TEST(ShellSection, DefaultsAreTheHomogeneousPlate) {
  // PSHELL defaults: 12I/T³ = 1, TS/T = 5/6 (the shear factor MITC4 used before the section
  // existed, kShellShearFactor), no non-structural mass.
  const ShellProperty property;
  EXPECT_EQ(property.bending_ratio, 1.0);
  EXPECT_EQ(property.shear_ratio, 5.0 / 6.0);
  EXPECT_EQ(property.nonstructural_mass, 0.0);
}

TEST(ShellSection, DefaultsReproduceTheElementMatricesOfCommit34ce026) {
  // Warped distorted quad, tilted in space, steel, t = 0.05 m: the golden values were printed
  // (%.17g) by the element of commit 34ce026, before the section ratios existed. The ratios
  // enter as r·(…) with r = 1 and + 0.0, which round exactly, so the values should agree
  // bit for bit; 1e-14 (relative) leaves room for a different compiler's summation order only.
  const ShellProperty property{"panel", testing::paper_steel(), 0.05};
  const ShellElementMatrices e = shell_element_matrices(placed(kDistorted, kSmallWarp), property);
  Vector24d u, v;
  for (int i = 0; i < 24; ++i) {
    u(i) = std::sin(1.0 + i);
    v(i) = std::cos(0.5 + 2.0 * i);
  }
  const double k_norm = e.stiffness.norm(), m_norm = e.mass.norm();
  std::printf("defaults: |K| = %.17g, |M| = %.17g, v'Ku = %.17g, v'Mu = %.17g\n", k_norm, m_norm,
              v.dot(e.stiffness * u), v.dot(e.mass * u));
  EXPECT_NEAR(k_norm, 24957419326.772591, 1e-14 * k_norm);
  EXPECT_NEAR(m_norm, 149.63927805766662, 1e-14 * m_norm);
  // Bilinear forms: round-off relative to |K| |u| |v|, not to the (cancelling) value itself.
  const double uv = u.norm() * v.norm();
  EXPECT_NEAR(v.dot(e.stiffness * u), 1561795304.6294341, 1e-14 * k_norm * uv);
  EXPECT_NEAR(v.dot(e.mass * u), -10.053114298471982, 1e-14 * m_norm * uv);
  EXPECT_NEAR(e.stiffness(2, 9), 359618989.543486, 1e-14 * k_norm);
  EXPECT_NEAR(e.mass(3, 15), 0.0026357297003809055, 1e-14 * m_norm);
}

// Cantilever strip L × b in the x-y plane, 20 × 2 quads, clamped at x = 0, a force `load` [N]
// along `dof` shared 1/4, 1/2, 1/4 by the tip nodes. Returns the middle tip node's 6 DOFs.
constexpr int kStripElements = 20;
Vector6d strip_tip(const ShellProperty& property, Dof dof, double length, double width,
                   double load) {
  FeModelBuilder builder;
  RectangularPlateMesh mesh;
  mesh.edge_x = length * Eigen::Vector3d::UnitX();
  mesh.edge_y = width * Eigen::Vector3d::UnitY();
  mesh.elements_x = kStripElements;
  mesh.elements_y = 2;
  mesh.property = builder.add_shell_property(property);
  const std::vector<int> nodes = add_rectangular_plate(builder, mesh);
  constexpr int kRow = kStripElements + 1;
  for (int j = 0; j <= 2; ++j) {
    for (int d = 0; d < kDofsPerNode; ++d) builder.fix(nodes[j * kRow], static_cast<Dof>(d));
  }
  const FeModel model = std::move(builder).build();

  // Static solve K_ff u_f = f_f.
  const std::vector<int> dofs = free_dofs(model);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(model.dof_count());
  const std::array<double, 3> share{0.25, 0.5, 0.25};
  for (int j = 0; j <= 2; ++j) {
    force(FeModel::dof_index(nodes[j * kRow + kStripElements], dof)) = share[j] * load;
  }
  Eigen::VectorXd force_free(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) force_free(i) = force(dofs[i]);
  const Eigen::SimplicialLDLT<SparseMatrix> solver(restrict_to(assemble(model).stiffness, dofs));
  EXPECT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd u_free = solver.solve(force_free);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t i = 0; i < dofs.size(); ++i) u(dofs[i]) = u_free(i);
  return u.segment<6>(FeModel::dof_index(nodes[kRow + kStripElements], Dof::kUx));
}

TEST(ShellSection, BendingRatioScalesThePlateBendingOnly) {
  // Strip L = 1 m, b = 0.1 m, T = 1e-4 m, ν = 0 (beam-like bending, no anticlastic restraint),
  // bending ratio r = 1 and 1000 (the latter bends like a homogeneous 1 mm strip).
  const double length = 1.0, width = 0.1, t = 1e-4, load = 1.0;
  const Material material{"steel nu=0", 200e9, 0.0, 7800.0};
  ShellProperty property{"strip", material, t};
  std::array<double, 2> tip_w{};
  for (int i = 0; i < 2; ++i) {
    const double r = i == 0 ? 1.0 : 1000.0;
    property.bending_ratio = r;
    // Out-of-plane tip load against Timoshenko beam theory with EI = E r T³/12 b and shear
    // stiffness G (TS/T) T b. MITC4 on this strip is the 2-node Timoshenko beam with constant
    // shear, exactly P L³/(3EI) (1 − 1/(4n²)) in the thin limit (test_shell_plate.cpp); the
    // shear term is 6e-9 r of the bending one (6e-6 at r = 1000): 1e-5.
    const double inertia = r * width * t * t * t / 12.0;
    const double reference =
        load * std::pow(length, 3) / (3.0 * material.youngs_modulus * inertia) +
        load * length / (property.shear_ratio * material.shear_modulus() * width * t);
    tip_w[i] = strip_tip(property, Dof::kUz, length, width, load)(2);
    const double expected_ratio = 1.0 - 1.0 / (4.0 * kStripElements * kStripElements);
    std::printf("strip r = %6.0f: tip w %.9e m, beam theory %.9e m, ratio %.7f\n", r, tip_w[i],
                reference, tip_w[i] / reference);
    EXPECT_NEAR(tip_w[i] / reference, expected_ratio, 1e-5) << "r = " << r;

    // In-plane stretch: u = P L/(E T b) whatever r, exact for the uniform stress state (ν = 0,
    // patch test); 1e-10 is the solve's round-off (as the in-plane bending test).
    const double stretch = load * length / (material.youngs_modulus * t * width);
    const double u_tip = strip_tip(property, Dof::kUx, length, width, load)(0);
    EXPECT_NEAR(u_tip, stretch, 1e-10 * stretch) << "r = " << r;
  }
  // Deflection scales as 1/r: the two shear terms differ by 6e-6 of the deflection.
  std::printf("strip tip w(r = 1) / w(r = 1000) = %.7f\n", tip_w[0] / tip_w[1]);
  EXPECT_NEAR(tip_w[0] / tip_w[1], 1000.0, 1e-5 * 1000.0);
}

TEST(ShellSection, RigidBodyMassIncludesTheNonStructuralMass) {
  // Tilted, offset rectangle a × b with the sandwich section. Ψᵀ M Ψ must be the rigid-body
  // mass matrix with m = (ρT + NSM) a b and, in the element axes,
  // I_c = diag(m b²/12 + ρI ab, m a²/12 + ρI ab, m (a² + b²)/12 + ρT³/12 ab): rotary inertia
  // ρI = ρ (12I/T³) T³/12 on the bending rotations, the homogeneous drilling term on θz.
  const double a = 0.4, b = 0.3;
  const ShellProperty property = sandwich_section();
  const double t = property.thickness, rho = property.material.density;
  const double area = a * b;
  const double m = (rho * t + property.nonstructural_mass) * area;
  const double rotary = rho * property.bending_ratio * t * t * t / 12.0 * area;
  const double drilling = rho * t * t * t / 12.0 * area;
  const Eigen::Vector3d c = kOffset;
  const Eigen::Matrix3d r = tilted_rotation();
  const Eigen::Matrix3d inertia_c =
      Eigen::Vector3d(m * b * b / 12.0 + rotary, m * a * a / 12.0 + rotary,
                      m * (a * a + b * b) / 12.0 + drilling)
          .asDiagonal();
  Eigen::Matrix<double, 6, 6> expected;
  expected << m * Eigen::Matrix3d::Identity(), -m * skew(c), m * skew(c),
      r * inertia_c * r.transpose() +
          m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());

  const Corners corners = placed(kRectangle);
  const ShellElementMatrices e = shell_element_matrices(corners, property);
  const Eigen::Matrix<double, 6, 6> rigid =
      rigid_modes(corners).transpose() * e.mass * rigid_modes(corners);
  std::printf("sandwich rectangle: mass %.17g kg, (rho T + NSM) A = %.17g kg\n", rigid(0, 0), m);
  // 2×2 Gauss integrates N_i N_j exactly: round-off only (1e-12 of the largest entry).
  EXPECT_LT((rigid - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(rigid(i, i), m, 1e-13 * m);

  // Distorted quad: mass (ρT + NSM) A with A from the shoelace formula, same round-off.
  double distorted_area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d& p = kDistorted[k];
    const Eigen::Vector2d& q = kDistorted[(k + 1) % 4];
    distorted_area += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  const double distorted_mass = (rho * t + property.nonstructural_mass) * distorted_area;
  const Corners distorted = placed(kDistorted);
  const Eigen::Matrix<double, 6, 6> distorted_rigid =
      rigid_modes(distorted).transpose() * shell_element_matrices(distorted, property).mass *
      rigid_modes(distorted);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(distorted_rigid(i, i), distorted_mass, 1e-13 * distorted_mass);
  }
}

}  // namespace
}  // namespace limber::fe
