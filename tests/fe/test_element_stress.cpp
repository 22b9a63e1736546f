// Element stress recovery (fe/element_stress.h) against closed forms: a cantilever's root
// resultants and bending stress, a circle's resultant-moment stress, a shell's membrane
// stress under uniform stretch, and a simply supported plate under uniform pressure against
// Kirchhoff's centre moment (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells,
// 2nd ed. 1959, §30, table 8) and Navier's series.
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include "fe/assembly.h"
#include "fe/element_stress.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

constexpr double kPi = 3.14159265358979323846;

// K_ff u_f = f_f with the fixed DOFs at zero; full-length displacement vector.
Eigen::VectorXd static_solution(const FeModel& model, const Eigen::VectorXd& force) {
  const std::vector<int> dofs = free_dofs(model);
  Eigen::VectorXd force_free(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) force_free(i) = force(dofs[i]);
  const Eigen::SimplicialLDLT<SparseMatrix> solver(restrict_to(assemble(model).stiffness, dofs));
  LIMBER_DEMAND(solver.info() == Eigen::Success);
  const Eigen::VectorXd u_free = solver.solve(force_free);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dof_count());
  for (std::size_t i = 0; i < dofs.size(); ++i) u(dofs[i]) = u_free(i);
  return u;
}

template <int kNodes>
Eigen::Matrix<double, 6 * kNodes, 1> element_values(const Eigen::VectorXd& u,
                                                    const std::array<int, kNodes>& nodes) {
  Eigen::Matrix<double, 6 * kNodes, 1> d;
  for (int a = 0; a < kNodes; ++a) d.template segment<6>(6 * a) = u.segment<6>(6 * nodes[a]);
  return d;
}

TEST(ElementStress, CantileverRootStressIsFLcOverI) {
  // Steel rod 0.01 (y) x 0.02 (z), L = 1 m along x, 10 elements, clamped at x = 0, tip load
  // F = 100 N along +z. Euler-Bernoulli elements are exact for end loads, so the resultants
  // from K d are exact to round-off: My(x) = −F (L − x), Vz = F, N = T = Vy = Mz = 0, and the
  // root's extreme-fibre stress is F L c / Iy with c = h/2.
  const double length = 1.0, force = 100.0;
  FeModelBuilder builder;
  StraightBeamMesh mesh;
  mesh.end = length * Eigen::Vector3d::UnitX();
  mesh.elements = 10;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = builder.add_beam_property(testing::paper_rod_property());
  const std::vector<int> nodes = add_straight_beam(builder, mesh);
  for (int d = 0; d < 6; ++d) builder.fix(nodes.front(), static_cast<Dof>(d));
  const FeModel model = std::move(builder).build();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  f(FeModel::dof_index(nodes.back(), Dof::kUz)) = force;
  const Eigen::VectorXd u = static_solution(model, f);

  const BeamProperty& property = model.beam_properties[0];
  const double scale = force * length;  // moment scale for the round-off bound
  for (std::size_t e = 0; e < model.beams.size(); ++e) {
    const BeamElement& beam = model.beams[e];
    const Eigen::Matrix<double, 12, 1> r =
        beam_resultant_operator(model.node_positions[beam.nodes[0]], model.node_positions[beam.nodes[1]],
                                beam.orientation, property) *
        element_values<2>(u, beam.nodes);
    for (int end = 0; end < 2; ++end) {
      const double x = model.node_positions[beam.nodes[end]].x();
      // Round-off: the K d products of a matrix with cond ~1e8 (relative 1e-9 leaves margin).
      EXPECT_NEAR(r(6 * end + 4), -force * (length - x), 1e-9 * scale) << "My, element " << e;
      EXPECT_NEAR(r(6 * end + 2), force, 1e-9 * force) << "Vz, element " << e;
      for (int k : {0, 1, 3, 5}) EXPECT_NEAR(r(6 * end + k), 0.0, 1e-9 * scale) << k;
    }
    if (e == 0) {
      const double closed_form = force * length * 0.01 / property.section.inertia_y;
      const double recovered = beam_extreme_fibre_stress(r, property.section);
      std::printf("cantilever root stress: recovered %.9e Pa, F L c / I = %.9e Pa\n", recovered,
                  closed_form);
      EXPECT_NEAR(recovered, closed_form, 1e-9 * closed_form);
    }
  }
}

TEST(ElementStress, CircleBendsAboutTheResultantMoment) {
  // σ = |N|/A + sqrt(My² + Mz²) r / I for a circle; |N|/A + |My| c_z/Iy + |Mz| c_y/Iz for a
  // rectangle (its corner), from hand-set resultants at end 1.
  Eigen::Matrix<double, 12, 1> r = Eigen::Matrix<double, 12, 1>::Zero();
  r(6) = -500.0;  // N
  r(10) = 30.0;   // My
  r(11) = -40.0;  // Mz
  const BeamSection circle = circle_section(0.02, 0.3);
  EXPECT_NEAR(beam_extreme_fibre_stress(r, circle),
              500.0 / circle.area + 50.0 * 0.01 / circle.inertia_y, 1e-12 * 1e8);
  const BeamSection rectangle = rectangle_section(0.01, 0.02);
  EXPECT_NEAR(beam_extreme_fibre_stress(r, rectangle),
              500.0 / rectangle.area + 30.0 * 0.01 / rectangle.inertia_y +
                  40.0 * 0.005 / rectangle.inertia_z,
              1e-12 * 1e9);
}

TEST(ElementStress, ShellMembraneStressOfAUniformStretchIsExact) {
  // A distorted quad tilted in space under the uniaxial stress state σxx = σ0, σyy = 0 of the
  // plane's axes (εxx = σ0/E, εyy = −ν σ0/E): N = (σ0 t, 0, 0), M = 0, von Mises σ0 on both
  // faces. The membrane passes the patch test (docs/shell-element.md), so this is exact.
  const Material steel = testing::paper_steel();
  const ShellProperty property{"plate", steel, 0.004};
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const std::array<Eigen::Vector2d, 4> plane{Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.3, 0.02),
                                             Eigen::Vector2d(0.28, 0.22), Eigen::Vector2d(-0.03, 0.2)};
  std::array<Eigen::Vector3d, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = rotation * Eigen::Vector3d(plane[k].x(), plane[k].y(), 0.0);
  const double sigma0 = 120e6, e = steel.youngs_modulus, nu = steel.poisson_ratio;
  const double eps_x = sigma0 / e, eps_y = -nu * sigma0 / e;
  // Nodal displacements in the plane's axes (e1 = rotation x, e2 = rotation y), to global.
  Eigen::Matrix<double, 24, 1> d = Eigen::Matrix<double, 24, 1>::Zero();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d u_plane(eps_x * plane[k].x(), eps_y * plane[k].y(), 0.0);
    d.segment<3>(6 * k) = rotation * u_plane;
  }
  const Eigen::Matrix<double, 6, 1> r = shell_resultant_operator(corners, property) * d;
  // The element's e1 may differ from the plane's x: compare invariants (trace, von Mises).
  EXPECT_NEAR(r(0) + r(1), sigma0 * 0.004, 1e-9 * sigma0 * 0.004);
  EXPECT_NEAR(r.tail<3>().norm(), 0.0, 1e-9 * sigma0 * 0.004 * 0.004);
  const Eigen::Vector2d vm = shell_von_mises(r, property);
  EXPECT_NEAR(vm(0), sigma0, 1e-9 * sigma0);
  EXPECT_NEAR(vm(1), sigma0, 1e-9 * sigma0);
}

// Navier's series for the simply supported plate a × a under uniform q (Timoshenko &
// Woinowsky-Krieger §30): Mx(x, y) = Σ_{m,n odd} 16 q ((m/a)² + ν (n/a)²) /
// (π⁴ m n ((m/a)² + (n/a)²)²) sin(mπx/a) sin(nπy/a). Terms fall as 1/(m n (m² + n²)): 400
// odd terms per direction leave < 1e-6 relative.
double navier_moment_x(double a, double q, double nu, double x, double y) {
  double sum = 0.0;
  for (int m = 1; m < 800; m += 2) {
    for (int n = 1; n < 800; n += 2) {
      const double mm = (m / a) * (m / a), nn = (n / a) * (n / a);
      sum += 16.0 * q * (mm + nu * nn) / (std::pow(kPi, 4) * m * n * (mm + nn) * (mm + nn)) *
             std::sin(m * kPi * x / a) * std::sin(n * kPi * y / a);
    }
  }
  return sum;
}

// Centre bending stress 6 M/t² of a simply supported square plate (hard support, in-plane
// DOFs and drilling held: they do not couple to bending in a flat plate) under uniform q,
// n × n mesh (n even): the mean over the four elements that meet at the centre, whose
// centres lie h/√2 from it. Returns (FE, Navier at those element centres).
std::array<double, 2> plate_centre_stress(int n, double a, double t, double q) {
  const Material steel = testing::paper_steel();
  const ShellProperty property{"plate", steel, t};
  FeModelBuilder builder;
  RectangularPlateMesh mesh;
  mesh.edge_x = a * Eigen::Vector3d::UnitX();
  mesh.edge_y = a * Eigen::Vector3d::UnitY();
  mesh.elements_x = n;
  mesh.elements_y = n;
  mesh.property = builder.add_shell_property(property);
  const std::vector<int> nodes = add_rectangular_plate(builder, mesh);
  FeModel model = std::move(builder).build();
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const int node = nodes[j * (n + 1) + i];
      for (Dof dof : {Dof::kUx, Dof::kUy, Dof::kRz}) model.fixed_dofs.push_back({node, dof});
      const bool x_edge = i == 0 || i == n, y_edge = j == 0 || j == n;
      if (x_edge || y_edge) model.fixed_dofs.push_back({node, Dof::kUz});
      if (x_edge) model.fixed_dofs.push_back({node, Dof::kRx});
      if (y_edge) model.fixed_dofs.push_back({node, Dof::kRy});
    }
  }
  // Consistent load of a uniform pressure on bilinear rectangles: q A / 4 per corner.
  const double h = a / n;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dof_count());
  for (const ShellElement& shell : model.shells) {
    for (int node : shell.nodes) f(FeModel::dof_index(node, Dof::kUz)) += q * h * h / 4.0;
  }
  const Eigen::VectorXd u = static_solution(model, f);
  // The four centre elements: (i, j) = (n/2 − 1 or n/2) x (n/2 − 1 or n/2), element j n + i.
  double fe_stress = 0.0;
  for (int j : {n / 2 - 1, n / 2}) {
    for (int i : {n / 2 - 1, n / 2}) {
      const ShellElement& shell = model.shells[static_cast<std::size_t>(j * n + i)];
      std::array<Eigen::Vector3d, 4> corners;
      for (int k = 0; k < 4; ++k) corners[k] = model.node_positions[shell.nodes[k]];
      const Eigen::Matrix<double, 6, 1> r =
          shell_resultant_operator(corners, property) * element_values<4>(u, shell.nodes);
      // Mxx and Myy are equal by symmetry at the diagonal points; take their mean.
      fe_stress += 0.25 * 6.0 * 0.5 * (std::abs(r(3)) + std::abs(r(4))) / (t * t);
    }
  }
  const double x = 0.5 * a - 0.5 * h;
  const double navier = 6.0 * navier_moment_x(a, q, steel.poisson_ratio, x, x) / (t * t);
  return {fe_stress, navier};
}

TEST(ElementStress, SimplySupportedPlateCentreStressMatchesKirchhoff) {
  // a = 1 m, t = 0.01 m, q = 10 kPa, ν = 0.3. Kirchhoff at the centre (T&W-K table 8, b/a = 1):
  // Mx = My = 0.0479 q a², σ = 6 M/t² = 28.74 MPa. The FE value is the mean of the four centre
  // elements, located h/√2 from the centre where Navier's series gives the Kirchhoff moment
  // exactly; the FE error against that is discretisation (O(h²), printed for 8, 16, 32) plus
  // the Mindlin shear correction (~t²/a², 1e-4).
  const double a = 1.0, t = 0.01, q = 1e4;
  const double table = 6.0 * 0.0479 * q * a * a / (t * t);
  const double navier_centre = 6.0 * navier_moment_x(a, q, 0.3, 0.5 * a, 0.5 * a) / (t * t);
  std::printf("plate centre stress: T&W-K table %.6e Pa, Navier %.6e Pa\n", table, navier_centre);
  // The table rounds β = 0.0479 to 3 digits: ±0.0001/0.0479 = 0.2 %.
  EXPECT_NEAR(navier_centre, table, 0.002 * table);
  std::array<double, 3> errors{};
  double finest = 0.0;
  const std::array<int, 3> meshes{8, 16, 32};
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    const std::array<double, 2> s = plate_centre_stress(meshes[k], a, t, q);
    errors[k] = s[0] / s[1] - 1.0;
    finest = s[0];
    std::printf("  %2d x %2d: FE %.6e Pa, Navier at the element centres %.6e Pa (%+.3f %%), "
                "vs table at the plate centre %+.3f %%\n",
                meshes[k], meshes[k], s[0], s[1], 100.0 * errors[k], 100.0 * (s[0] / table - 1.0));
  }
  // O(h²): each halving of h cuts the error by ~4 (3 to 5 allowed for the higher-order terms).
  EXPECT_GT(std::abs(errors[0] / errors[1]), 3.0);
  EXPECT_LT(std::abs(errors[0] / errors[1]), 5.0);
  EXPECT_GT(std::abs(errors[1] / errors[2]), 3.0);
  EXPECT_LT(std::abs(errors[1] / errors[2]), 5.0);
  // 32 x 32: within 1 % of Navier at the element centres (the convergence above extrapolates
  // the 16 x 16 error by /4); against the table's centre value within 1 % too, since the centre
  // elements sit where the moment is within 0.2 % of its maximum.
  EXPECT_LT(std::abs(errors[2]), 0.01);
  EXPECT_NEAR(finest, table, 0.01 * table);
}

}  // namespace
}  // namespace limber::fe
