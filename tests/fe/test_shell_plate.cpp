// Plate-level accuracy of the flat shell, assembled with fe/assembly.h on meshes from
// add_rectangular_plate: simply supported square plate frequencies against Kirchhoff's
// closed form, the free plate's rigid-body modes, and a thin cantilever strip against beam
// theory (shear locking); a honeycomb sandwich section (PSHELL-style ratios) against Kirchhoff
// and the exact simply supported Mindlin frequencies.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include "core/error.h"
#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct PlateCase {
  FeModel model;
  std::vector<int> nodes;  // row-major, x fastest
};

// Square plate a × a in the global x-y plane on an n × n mesh.
PlateCase square_plate(double a, const ShellProperty& section, int n) {
  FeModelBuilder builder;
  const int property = builder.add_shell_property(section);
  RectangularPlateMesh mesh;
  mesh.edge_x = a * Eigen::Vector3d::UnitX();
  mesh.edge_y = a * Eigen::Vector3d::UnitY();
  mesh.elements_x = n;
  mesh.elements_y = n;
  mesh.property = property;
  PlateCase plate;
  plate.nodes = add_rectangular_plate(builder, mesh);
  plate.model = std::move(builder).build();
  return plate;
}

PlateCase square_plate(double a, double thickness, int n, const Material& material) {
  return square_plate(a, {"plate", material, thickness}, n);
}

// Simply supported plate as a Kirchhoff reference: w = 0 on the edges and the rotation
// about the edge normal held there ("hard" support, θx on x = 0, a and θy on y = 0, a:
// ∂w/∂(tangent) = 0 along a supported edge). In-plane DOFs and drilling are held everywhere:
// in a flat plate they do not couple to bending, so this removes only the in-plane modes.
FeModel simply_supported(double a, const ShellProperty& section, int n) {
  PlateCase plate = square_plate(a, section, n);
  std::vector<FixedDof>& fixed = plate.model.fixed_dofs;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const int node = plate.nodes[j * (n + 1) + i];
      for (Dof dof : {Dof::kUx, Dof::kUy, Dof::kRz}) fixed.push_back({node, dof});
      const bool x_edge = i == 0 || i == n;
      const bool y_edge = j == 0 || j == n;
      if (x_edge || y_edge) fixed.push_back({node, Dof::kUz});
      if (x_edge) fixed.push_back({node, Dof::kRx});
      if (y_edge) fixed.push_back({node, Dof::kRy});
    }
  }
  return std::move(plate.model);
}

FeModel simply_supported(double a, double thickness, int n, const Material& material) {
  return simply_supported(a, {"plate", material, thickness}, n);
}

// Kirchhoff ω_mn = π² ((m/a)² + (n/a)²) sqrt(D / (ρ t)), the five lowest:
// (1,1), (1,2), (2,1), (2,2), (1,3).
std::vector<double> kirchhoff_frequencies(double a, double thickness, const Material& material) {
  const double e = material.youngs_modulus, nu = material.poisson_ratio;
  const double d = e * std::pow(thickness, 3) / (12.0 * (1.0 - nu * nu));
  const double root = std::sqrt(d / (material.density * thickness));
  std::vector<double> omega;
  for (double m2n2 : {2.0, 5.0, 5.0, 8.0, 10.0}) omega.push_back(kPi * kPi * m2n2 / (a * a) * root);
  return omega;
}

// The `count` lowest natural frequencies [rad/s] of a model whose K(free, free) is positive
// definite, by subspace iteration (Bathe, Finite Element Procedures, 1996, §11.6) with a
// sparse LDLᵀ of K: X ← K⁻¹ M X, then Rayleigh–Ritz on span(X). With 2 count + 2 vectors the
// k-th eigenvalue converges by (λ_k / λ_{2count+3})² per sweep; the sweeps stop when the
// requested frequencies change by less than 1e-12 (relative).
std::vector<double> lowest_frequencies(const FeModel& model, int count) {
  const StructuralMatrices matrices = assemble(model);
  const std::vector<int> dofs = free_dofs(model);
  const SparseMatrix k = restrict_to(matrices.stiffness, dofs);
  const SparseMatrix m = restrict_to(matrices.mass, dofs);
  const Eigen::SimplicialLDLT<SparseMatrix> factor(k);
  LIMBER_DEMAND(factor.info() == Eigen::Success);

  // Start vectors: a deterministic pseudo-random block.
  const int size = static_cast<int>(dofs.size());
  const int block = 2 * count + 2;
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(size, block);
  std::uint32_t seed = 12345u;
  for (int j = 0; j < block; ++j) {
    for (int i = 0; i < size; ++i) {
      seed = seed * 1664525u + 1013904223u;
      x(i, j) = static_cast<double>(seed) / 4294967296.0 - 0.5;
    }
  }

  std::vector<double> omega(count, 0.0);
  for (int sweep = 0; sweep < 200; ++sweep) {
    // Inverse iteration on the block, then the projected eigenproblem.
    const Eigen::MatrixXd y = factor.solve(m * x);
    const Eigen::MatrixXd k_reduced = y.transpose() * (k * y);
    const Eigen::MatrixXd m_reduced = y.transpose() * (m * y);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(k_reduced, m_reduced);
    x = y * ritz.eigenvectors();
    // Convergence of the requested frequencies.
    double change = 0.0;
    for (int i = 0; i < count; ++i) {
      const double value = std::sqrt(ritz.eigenvalues()(i));
      change = std::max(change, std::abs(value - omega[i]) / value);
      omega[i] = value;
    }
    if (change < 1e-12) return omega;
  }
  ADD_FAILURE() << "subspace iteration did not converge in 200 sweeps";
  return omega;
}

// Why 32 × 32: MITC4 with consistent mass has, in its 1-D analogue (2-node Timoshenko beam
// with constant shear, thin limit, consistent mass for bilinear w), the dispersion
// ω_h² = ω² (1 + (k h)²/4 + O(h⁴)), i.e. a frequency error ≈ (k h)²/8 for the wavenumber
// k = mπ/a along the finer direction of the mode. For mode (1,3) that is 4.3 % at 16 × 16 and
// 1.1 % at 32 × 32 (measured 3.8 % and 0.79 %, docs/shell-element.md).
TEST(ShellPlate, SimplySupportedSquarePlateMatchesKirchhoff) {
  // a = 1 m, t = 0.01 m, steel, 32 × 32 elements: the brief's 1 % bound on the first five
  // frequencies. The Mindlin-vs-Kirchhoff shift (shear + rotary inertia, ≈ −0.18 % for
  // mode (1,3)) only lowers the FE values towards the reference.
  const Material steel = testing::paper_steel();
  const std::vector<double> omega = lowest_frequencies(simply_supported(1.0, 0.01, 32, steel), 5);
  const std::vector<double> reference = kirchhoff_frequencies(1.0, 0.01, steel);
  for (int i = 0; i < 5; ++i) {
    EXPECT_LT(testing::relative_error(omega[i], reference[i]), 0.01)
        << "mode " << i + 1 << ": " << omega[i] << " vs " << reference[i] << " rad/s";
  }
}

TEST(ShellPlate, SimplySupportedPlateConvergesToKirchhoff) {
  // Same plate on 8, 16, 32 and 64 elements a side (the table of docs/shell-element.md).
  // Each halving of h must cut every error. At 64 × 64 what remains is the Mindlin shift
  // (−0.04 % to −0.18 %) plus the discretisation error (k h)²/8 (+0.03 % to +0.27 %); of
  // opposite signs, their sum is below the larger: all five within 0.3 %.
  const Material steel = testing::paper_steel();
  const std::vector<double> reference = kirchhoff_frequencies(1.0, 0.01, steel);
  std::vector<double> previous(5, 1.0);
  for (int n : {8, 16, 32, 64}) {
    const std::vector<double> omega = lowest_frequencies(simply_supported(1.0, 0.01, n, steel), 5);
    std::printf("SS plate %2d x %2d, error %%:", n, n);
    for (int i = 0; i < 5; ++i) {
      const double error = testing::relative_error(omega[i], reference[i]);
      std::printf(" %+.3f", 100.0 * (omega[i] / reference[i] - 1.0));
      EXPECT_LT(error, previous[i]) << "mode " << i + 1 << " at n = " << n;
      previous[i] = error;
    }
    std::printf("\n");
  }
  for (int i = 0; i < 5; ++i) EXPECT_LT(previous[i], 3e-3) << "mode " << i + 1 << " at n = 64";
}

TEST(ShellPlate, FreePlateHasExactlySixRigidBodyModes) {
  // Free 8 × 8 steel plate, all 6 DOFs per node. Rigid modes come out at round-off,
  // sqrt(1e-16 λmax) ~ 1e-1 rad/s with λmax ~ 1e13 (s⁻²), while the first elastic mode is
  // ~200 rad/s: "zero" is below 1e-2 of the first elastic frequency.
  const PlateCase plate = square_plate(1.0, 0.01, 8, testing::paper_steel());
  const std::vector<double> omega = testing::dense_frequencies(plate.model);
  std::printf("free plate 8 x 8: |omega_1..6| <= %.3g rad/s, omega_7 = %.6g rad/s\n",
              std::max(std::abs(omega[0]), std::abs(omega[5])), omega[6]);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(omega[i]), 1e-2 * omega[6]) << "mode " << i + 1;
  // Leissa 1969 (Vibration of Plates, NASA SP-160, Table 4.74, ν = 0.3): the first free-free
  // square-plate frequency is ω a² sqrt(ρ t / D) = 13.468; an 8 × 8 mesh is within 2 %.
  const Material steel = testing::paper_steel();
  const double d = steel.youngs_modulus * 1e-6 / (12.0 * (1.0 - 0.09));
  EXPECT_NEAR(omega[6] / std::sqrt(d / (steel.density * 0.01)), 13.468, 0.02 * 13.468);
}

TEST(ShellPlate, ThinCantileverStripDoesNotLockInShear) {
  // Strip L = 1 m, b = 0.1 m, t = 1e-3 m (t/L = 1e-3), ν = 0 (so the plate strip bends as a
  // beam with no anticlastic restraint at the clamp), 20 × 2 elements, clamped at x = 0,
  // tip load P shared 1/4, 1/2, 1/4 by the tip nodes.
  const double length = 1.0, width = 0.1, t = 1e-3, load = 1.0;
  const Material material{"steel nu=0", 200e9, 0.0, 7800.0};
  FeModelBuilder builder;
  const int property = builder.add_shell_property({"strip", material, t});
  RectangularPlateMesh mesh;
  mesh.edge_x = length * Eigen::Vector3d::UnitX();
  mesh.edge_y = width * Eigen::Vector3d::UnitY();
  mesh.elements_x = 20;
  mesh.elements_y = 2;
  mesh.property = property;
  const std::vector<int> nodes = add_rectangular_plate(builder, mesh);
  for (int j = 0; j <= 2; ++j) {
    for (int dof = 0; dof < 6; ++dof) builder.fix(nodes[j * 21], static_cast<Dof>(dof));
  }
  const FeModel model = std::move(builder).build();

  // Static solve K_ff u_f = f_f.
  const std::vector<int> dofs = free_dofs(model);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(model.dof_count());
  const std::array<double, 3> share{0.25, 0.5, 0.25};
  for (int j = 0; j <= 2; ++j)
    force(FeModel::dof_index(nodes[j * 21 + 20], Dof::kUz)) = share[j] * load;
  Eigen::VectorXd force_free(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) force_free(i) = force(dofs[i]);
  const Eigen::SimplicialLDLT<SparseMatrix> solver(restrict_to(assemble(model).stiffness, dofs));
  ASSERT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd u_free = solver.solve(force_free);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t i = 0; i < dofs.size(); ++i) u(dofs[i]) = u_free(i);
  const double tip = u(FeModel::dof_index(nodes[1 * 21 + 20], Dof::kUz));

  // Timoshenko beam: P L³ / (3 E I) + P L / (k G A); the shear term is 1e-6 of the first.
  const double inertia = width * t * t * t / 12.0;
  const double reference = load * std::pow(length, 3) / (3.0 * material.youngs_modulus * inertia) +
                           load * length / (5.0 / 6.0 * material.shear_modulus() * width * t);
  // Locking would make the strip stiffer by orders of magnitude. Without it, MITC4 on this
  // strip is the 2-node Timoshenko beam with constant shear, whose thin-limit tip deflection is
  // exactly P L³/(3 E I) (1 − 1/(4 n²)) (sum of its exact midpoint curvatures; n = 20:
  // ratio 0.999375). The shear flexibility left in both is ~6e-7 of the deflection: 1e-5.
  const double expected_ratio = 1.0 - 1.0 / (4.0 * 20.0 * 20.0);
  std::printf("cantilever strip t/L = 1e-3: tip %.6e m, beam theory %.6e m, ratio %.6f\n", tip,
              reference, tip / reference);
  EXPECT_NEAR(tip / reference, expected_ratio, 1e-5)
      << "tip " << tip << " m vs " << reference << " m";
}

TEST(ShellPlate, InPlaneBendingIsExactOnRectangles) {
  // Membrane cantilever L = 1 m, depth H = 0.1 m, t = 0.01 m, ν = 0, 4 × 1 rectangles in the
  // x-y plane, clamped in-plane at x = 0, end couple M as forces ∓M/H along x at the tip
  // nodes (the consistent loads of the linear bending stress). Pure bending u = −κ x y,
  // v = κ x²/2 lies in the incompatible-mode space on rectangles and has θz = ω with no
  // drilling energy, so the tip deflection M L²/(2 E I) is exact to round-off (1e-10); a
  // plain bilinear quad fails this (parasitic shear: 0.24 of the deflection at this 2.5:1
  // aspect ratio).
  const double length = 1.0, depth = 0.1, t = 0.01, moment = 100.0;
  const Material material{"steel nu=0", 200e9, 0.0, 7800.0};
  FeModelBuilder builder;
  const int property = builder.add_shell_property({"web", material, t});
  RectangularPlateMesh mesh;
  mesh.origin = Eigen::Vector3d(0.0, -0.5 * depth, 0.0);
  mesh.edge_x = length * Eigen::Vector3d::UnitX();
  mesh.edge_y = depth * Eigen::Vector3d::UnitY();
  mesh.elements_x = 4;
  mesh.elements_y = 1;
  mesh.property = property;
  const std::vector<int> nodes = add_rectangular_plate(builder, mesh);
  for (int node : nodes) {
    for (Dof dof : {Dof::kUz, Dof::kRx, Dof::kRy}) builder.fix(node, dof);
  }
  for (int j = 0; j <= 1; ++j) {
    builder.fix(nodes[j * 5], Dof::kUx);
    builder.fix(nodes[j * 5], Dof::kUy);
  }
  const FeModel model = std::move(builder).build();

  const std::vector<int> dofs = free_dofs(model);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(model.dof_count());
  force(FeModel::dof_index(nodes[4], Dof::kUx)) = moment / depth;
  force(FeModel::dof_index(nodes[9], Dof::kUx)) = -moment / depth;
  Eigen::VectorXd force_free(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) force_free(i) = force(dofs[i]);
  const Eigen::SimplicialLDLT<SparseMatrix> solver(restrict_to(assemble(model).stiffness, dofs));
  ASSERT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd u_free = solver.solve(force_free);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t i = 0; i < dofs.size(); ++i) u(dofs[i]) = u_free(i);

  // Bottom fibre (y = −H/2) in tension for a positive couple about z: v_tip = M L²/(2 E I).
  const double inertia = t * depth * depth * depth / 12.0;
  const double reference = moment * length * length / (2.0 * material.youngs_modulus * inertia);
  for (int node : {nodes[4], nodes[9]}) {
    EXPECT_NEAR(u(FeModel::dof_index(node, Dof::kUy)), reference, 1e-10 * reference);
    // Drilling rotation equals the section rotation dv/dx = M L/(E I).
    EXPECT_NEAR(u(FeModel::dof_index(node, Dof::kRz)), 2.0 * reference / length, 1e-10 * reference);
  }
}

// The honeycomb solar panel of docs/shell-element.md as a PSHELL-style section: CFRP faces
// 2 × 0.25 mm (E = 60 GPa, ν = 0.3, ρ = 1600 kg/m³) on a 25 mm aluminium honeycomb core
// (32 kg/m³) carrying 0.8 kg/m² of cells and wiring. T = 2 t_f; I = 2 t_f (h/2)² with
// h = core + t_f the distance between the face centroids; NSM = core + cells.
ShellProperty honeycomb_section(double shear_ratio) {
  const double face = 0.25e-3, core = 25e-3, core_density = 32.0, cells = 0.8;
  const double h = core + face;
  const double t = 2.0 * face;
  ShellProperty section{"honeycomb", {"cfrp", 60e9, 0.3, 1600.0}, t};
  section.bending_ratio = 12.0 * (2.0 * face * 0.25 * h * h) / (t * t * t);
  section.shear_ratio = shear_ratio;
  section.nonstructural_mass = core_density * core + cells;
  return section;
}

// Per unit area: bending rigidity D = E I/(1 − ν²) [N·m], mass m = ρT + NSM [kg/m²], shear
// stiffness S = G (TS/T) T [N/m], rotary inertia J = ρ I [kg] (shell_element.cpp).
struct SectionConstants {
  double d, mass, shear, rotary;
};
SectionConstants section_constants(const ShellProperty& s) {
  const Material& material = s.material;
  const double inertia = s.bending_ratio * std::pow(s.thickness, 3) / 12.0;
  const double nu = material.poisson_ratio;
  return {material.youngs_modulus * inertia / (1.0 - nu * nu),
          material.density * s.thickness + s.nonstructural_mass,
          s.shear_ratio * material.shear_modulus() * s.thickness, material.density * inertia};
}

// Kirchhoff ω = k² sqrt(D/m), k² = π² ((m/a)² + (n/b)²).
double kirchhoff_omega(const SectionConstants& c, double k2) {
  return k2 * std::sqrt(c.d / c.mass);
}

// Exact flexural ω of the hard simply supported Mindlin plate (the supports of
// simply_supported): w = W sin sin and rotations ∇(Φ sin sin) give, per unit of the modal
// integrals, stiffness [[S k², S k²], [S k², S k² + D k⁴]] and mass diag(m, J k²) on (W, Φ);
// the lower root of the 2 × 2 determinant (as 2c/(−b + √(b² − 4ac)) to avoid cancellation).
double mindlin_omega(const SectionConstants& c, double k2) {
  const double qa = c.mass * c.rotary * k2;
  const double qb = -(c.mass * (c.shear * k2 + c.d * k2 * k2) + c.shear * k2 * c.rotary * k2);
  const double qc = c.shear * c.d * k2 * k2 * k2;
  return std::sqrt(2.0 * qc / (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)));
}

// (m² + n²) of the five lowest modes of a square plate, (1,1), (1,2), (2,1), (2,2), (1,3), and
// max(m, n), the half-waves along the mode's finer direction.
constexpr std::array<double, 5> kSquareModes{2.0, 5.0, 5.0, 8.0, 10.0};
constexpr std::array<double, 5> kFinerHalfWaves{1.0, 2.0, 2.0, 2.0, 3.0};

// Discretisation error bound of a frequency on an n × n mesh of a plate of side a: (k h)²/8,
// k = max(m, n) π/a, from the dispersion of MITC4's 1-D analogue (docs/shell-element.md);
// the homogeneous plate's table, taken against the exact Mindlin values, sits below it
// (e.g. (1,3) at 32 × 32: 0.97 % against 1.08 %).
double discretisation_bound(int mode, double a, int n) {
  const double kh = kFinerHalfWaves[mode] * kPi / a * (a / n);
  return kh * kh / 8.0;
}

TEST(ShellPlate, SandwichPlateMatchesKirchhoffWhenItsShearIsStiff) {
  // Honeycomb section with TS/T = 100 (shear shift ½ k² D/S ≤ 0.03 %), 1 m square, 32 × 32.
  // FE against exact Mindlin: the discretisation bound (k h)²/8 (0.12 % to 1.08 %). Against
  // Kirchhoff (D = E I/(1 − ν²), m = ρT + NSM) the rotary inertia ρI also lowers the
  // frequencies by ½ k² J/m = 0.05 % to 0.26 %, so FE − Kirchhoff ≤ 1.08 − 0.26 < 1 %.
  const int n = 32;
  const ShellProperty section = honeycomb_section(100.0);
  const SectionConstants c = section_constants(section);
  const std::vector<double> omega = lowest_frequencies(simply_supported(1.0, section, n), 5);
  for (int i = 0; i < 5; ++i) {
    const double k2 = kPi * kPi * kSquareModes[i];
    const double kirchhoff = kirchhoff_omega(c, k2);
    const double mindlin = mindlin_omega(c, k2);
    std::printf("sandwich, TS/T = 100, mode %d: %.4f rad/s, Kirchhoff %+.3f %%, Mindlin %+.3f %%\n",
                i + 1, omega[i], 100.0 * (omega[i] / kirchhoff - 1.0),
                100.0 * (omega[i] / mindlin - 1.0));
    EXPECT_LT(testing::relative_error(omega[i], kirchhoff), 0.01) << "mode " << i + 1;
    EXPECT_LT(testing::relative_error(omega[i], mindlin), discretisation_bound(i, 1.0, n))
        << "mode " << i + 1;
  }
}

TEST(ShellPlate, SandwichPlateWithCoreShearMatchesMindlin) {
  // Same panel with the core's shear stiffness, S = G_c h²/c (G_c = 140 MPa; Allen 1969,
  // Analysis and Design of Structural Sandwich Panels): TS/T = S/(G T) = 0.309. The section
  // is now 1.5 % (mode 1) to 6.7 % (mode 5) softer than Kirchhoff, so the reference is the
  // exact Mindlin frequency; what is left is discretisation, within (k h)²/8 as above.
  const double face = 0.25e-3, core = 25e-3, core_shear_modulus = 140e6;
  const double h = core + face;
  const ShellProperty stiff = honeycomb_section(1.0);
  const double shear_ratio =
      core_shear_modulus * h * h / core / (stiff.material.shear_modulus() * stiff.thickness);
  const ShellProperty section = honeycomb_section(shear_ratio);
  const SectionConstants c = section_constants(section);
  const int n = 32;
  const std::vector<double> omega = lowest_frequencies(simply_supported(1.0, section, n), 5);
  for (int i = 0; i < 5; ++i) {
    const double k2 = kPi * kPi * kSquareModes[i];
    const double mindlin = mindlin_omega(c, k2);
    std::printf("sandwich, TS/T = %.4f, mode %d: %.4f rad/s, Kirchhoff %+.3f %%, "
                "Mindlin %+.3f %%\n",
                shear_ratio, i + 1, omega[i], 100.0 * (omega[i] / kirchhoff_omega(c, k2) - 1.0),
                100.0 * (omega[i] / mindlin - 1.0));
    EXPECT_LT(testing::relative_error(omega[i], mindlin), discretisation_bound(i, 1.0, n))
        << "mode " << i + 1;
  }
}

}  // namespace
}  // namespace limber::fe
