// Modal geometric stiffness (modal/geometric_stiffness.h) against closed forms:
//  - a pinned-pinned Euler–Bernoulli rod under an axial compressive end load P: first
//    bending frequency f = f0 √(1 − P/P_cr) (the mode sin(πx/L) is unchanged by P) and the
//    buckling load P_cr = π² E I / L² (Euler), found where the loaded modal stiffness's
//    smallest eigenvalue crosses zero;
//  - a cantilever spinning about an axis through its root, normal to it: flapwise (out of the
//    plane of rotation) ω² = ω0² + K_S Ω² with the Southwell coefficient of the first mode
//    K_S = 1.1933 (uniform beam, zero hub radius; Wright, Smith, Thresher & Wang, "Vibration
//    modes of centrifugally stiffened beams", J. Appl. Mech. 49(2), 1982, table 1);
//  - a free-free rod: the frame's rigid acceleration fields are balanced by inertia relief
//    and carry no geometric stiffness;
//  - a simply supported square plate under uniaxial compression: buckling at
//    N_cr = 4 π² D / b² (Timoshenko & Gere, "Theory of Elastic Stability", 2nd ed., 1961, §9.2);
//  - node moments: on a bent frame a couple loads the legs axially (statics by hand), on a
//    straight rod it does not.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "fe/beam_geometric_stiffness.h"
#include "fe/mesh_generators.h"
#include "modal/component_modes.h"
#include "modal/geometric_stiffness.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

using std::numbers::pi;

constexpr int kElements = 40;
constexpr double kLength = 1.0;  // [m]

// The seed paper's rod along x, 0.01 (y) x 0.02 (z) m, Euler–Bernoulli without rotary inertia
// (the closed forms' theory). Supports: held DOFs per node index.
fe::FeModel rod(const std::vector<std::pair<int, std::vector<fe::Dof>>>& supports) {
  fe::FeModelBuilder builder;
  fe::StraightBeamMesh mesh;
  mesh.end = kLength * Eigen::Vector3d::UnitX();
  mesh.elements = kElements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = builder.add_beam_property(testing::rod_property(false));
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (const auto& [node, dofs] : supports) {
    for (fe::Dof dof : dofs) builder.fix(nodes[static_cast<std::size_t>(node)], dof);
  }
  return std::move(builder).build();
}

struct Reduced {
  ModeSet modes;
  ModalGeometricStiffness geometric;
};

Reduced reduce(const fe::FeModel& model, int normal_modes, const std::vector<int>& load_nodes) {
  const fe::StructuralMatrices matrices = fe::assemble(model);
  ModeRequest request;
  request.normal_count = normal_modes;
  ModalResult modes = compute_component_modes(model, matrices, request);
  EXPECT_EQ(modes.status, ModalStatus::kOk) << modes.message;
  ModalGeometricStiffnessResult geometric =
      compute_modal_geometric_stiffness(model, matrices, modes.mode_set.shapes, load_nodes);
  EXPECT_EQ(geometric.status, ModalStatus::kOk) << geometric.message;
  return {std::move(modes.mode_set), std::move(geometric.stiffness)};
}

double lowest_eigenvalue(const Eigen::MatrixXd& k) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k, Eigen::EigenvaluesOnly).eigenvalues()(0);
}

// Weak axis of the section: bending along y uses Iz = 0.02 · 0.01³ / 12.
double weak_inertia() { return testing::rod_property(false).section.inertia_z; }

TEST(GeometricStiffness, ElementMatrixIsTheSecondOrderWorkOfTheAxialForce) {
  // For a cubic v(x) the second-order work ½ N ∫ v'² dx is exact in the Hermite interpolation:
  // v = x²(L − x) on [0, L] has v(0) = v(L) = 0, v'(0) = 0, v'(L) = −L², ∫ v'² = 2 L⁵/15.
  const fe::BeamProperty property = testing::rod_property(false);
  const double n = 1000.0, l = 0.7;
  const fe::Matrix12d k = fe::beam_local_geometric_stiffness(l, n, property);
  fe::Vector12d u = fe::Vector12d::Zero();
  u(11) = -l * l;  // θz1 = v'(L) in the x-y plane
  EXPECT_NEAR(0.5 * u.dot(k * u), 0.5 * n * 2.0 * std::pow(l, 5) / 15.0, 1e-12 * n);
  // The same in the x-z plane (θy = −w').
  u.setZero();
  u(10) = l * l;
  EXPECT_NEAR(0.5 * u.dot(k * u), 0.5 * n * 2.0 * std::pow(l, 5) / 15.0, 1e-12 * n);
  // A rigid translation carries none; a rigid rotation does (½ N θ² L: the prestressed bar's
  // rotation is second order in the displacements, which is why the floating frame carries it).
  fe::Vector12d rigid = fe::Vector12d::Zero();
  rigid(1) = rigid(7) = 1.0;
  EXPECT_LT((k * rigid).norm(), 1e-12 * n);
  rigid.setZero();
  rigid(7) = l;
  rigid(5) = rigid(11) = 1.0;
  EXPECT_NEAR(0.5 * rigid.dot(k * rigid), 0.5 * n * l, 1e-12 * n);
}

TEST(GeometricStiffness, PinnedRodUnderCompressionSoftensAsEulerColumn) {
  // Pinned at node 0 (ux uy uz rx), on a roller at the far end (uy uz): the end load is a
  // node force along −x at the last node. 4 normal modes (the first two bending modes of
  // each plane are within the lowest ones).
  using fe::Dof;
  const fe::FeModel model = rod({{0, {Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx}}, {kElements, {Dof::kUy, Dof::kUz}}});
  const Reduced r = reduce(model, 4, {kElements});
  const fe::Material steel = testing::paper_steel();
  const double ei = steel.youngs_modulus * weak_inertia();
  const double rho_a = steel.density * 0.01 * 0.02;
  const double p_cr = pi * pi * ei / (kLength * kLength);  // Euler load, 3.402 kN
  const double f0 = pi / (2.0 * kLength * kLength) * std::sqrt(ei / rho_a);
  const Eigen::MatrixXd k0 = r.modes.modal_stiffness.asDiagonal();
  const Eigen::MatrixXd& k_axial = r.geometric.node_forces[0][0];  // per N along +x
  // Unloaded: the FE frequency is the closed form to the 40-element discretisation error.
  EXPECT_NEAR(testing::hz(lowest_eigenvalue(k0)) / f0, 1.0, 1e-5);
  // Loaded by P along −x: K(P) = K0 − P K_G,x. The discretisation error of f0 and P_cr
  // (~1e-6) is amplified by P/(P_cr − P) ≤ 9 in f(P): 1e-4 relative is a tight bound.
  for (double ratio : {0.25, 0.5, 0.75, 0.9}) {
    const double p = ratio * p_cr;
    const double f = testing::hz(lowest_eigenvalue(k0 - p * k_axial));
    EXPECT_NEAR(f / (f0 * std::sqrt(1.0 - ratio)), 1.0, 1e-4) << "P/P_cr = " << ratio;
  }
  // Buckling: bisection on P for the zero crossing of the smallest eigenvalue of K(P).
  double low = 0.0, high = 2.0 * p_cr;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (lowest_eigenvalue(k0 - mid * k_axial) > 0.0 ? low : high) = mid;
  }
  // The issue asks 1 %; the 40-element consistent K_G gives P_cr to ~1e-6.
  EXPECT_NEAR(low / p_cr, 1.0, 1e-3);
  std::printf("buckling load %.6g N, Euler %.6g N (ratio %.8f)\n", low, p_cr, low / p_cr);
  // Tension stiffens: f rises above f0.
  EXPECT_GT(lowest_eigenvalue(k0 + 0.5 * p_cr * k_axial), lowest_eigenvalue(k0));
}

TEST(GeometricStiffness, SpinningCantileverFollowsSouthwellCoefficient) {
  // Clamped at node 0, spinning about z through the root: the centrifugal case ω_z² (index
  // 2). Flapwise bending = along z (stiff axis Iy); the first flapwise mode is the lowest mode
  // with z motion. Small Ω (Ω/ω0 = 0.1) so the slope is the Southwell coefficient.
  using fe::Dof;
  const fe::FeModel model = rod({{0, {Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx, Dof::kRy, Dof::kRz}}});
  const Reduced r = reduce(model, 6, {});
  // The first mode bending along z: largest uz at the tip among the modes.
  int flap = 0;
  const Eigen::Index tip_uz = 6 * kElements + 2;
  for (int i = 1; i < r.modes.shapes.cols(); ++i) {
    if (std::abs(r.modes.shapes(tip_uz, i)) > 1e-3 && std::abs(r.modes.shapes(tip_uz, flap)) <= 1e-3) flap = i;
  }
  ASSERT_GT(std::abs(r.modes.shapes(tip_uz, flap)), 1e-3);
  const double w0_sq = r.modes.modal_stiffness(flap);
  const double spin = 0.1 * std::sqrt(w0_sq);
  // Rayleigh quotient of the flapwise mode under ω = Ω e_z (the projected problem couples the
  // modes only at second order, so the diagonal term is the Southwell slope).
  const double slope = r.geometric.centrifugal[2](flap, flap);
  EXPECT_NEAR(slope, 1.1933, 2e-3);
  std::printf("Southwell coefficient of the first flapwise mode: %.5f\n", slope);
  // And the loaded eigenvalue: ω² = ω0² + K_S Ω² to the coupling's O(Ω⁴) term.
  Eigen::MatrixXd k = r.modes.modal_stiffness.asDiagonal();
  k += spin * spin * r.geometric.centrifugal[2];
  const Eigen::VectorXd w_sq = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
  double nearest = w_sq(0);
  for (Eigen::Index i = 0; i < w_sq.size(); ++i) {
    if (std::abs(w_sq(i) - w0_sq) < std::abs(nearest - w0_sq)) nearest = w_sq(i);
  }
  EXPECT_NEAR((nearest - w0_sq) / (spin * spin), 1.1933, 5e-3);
}

TEST(GeometricStiffness, FreeRodRigidAccelerationsCarryNoStress) {
  // Free-free: the frame's rigid acceleration fields are balanced exactly by inertia relief.
  const fe::FeModel model = rod({});
  const Reduced r = reduce(model, 5, {0, kElements});
  const double scale = r.modes.modal_stiffness.maxCoeff();
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(r.geometric.angular_acceleration[k].cwiseAbs().maxCoeff(), 1e-10 * scale);
    EXPECT_LT(r.geometric.translational_acceleration[k].cwiseAbs().maxCoeff(), 1e-10 * scale);
  }
  // Equal and opposite end forces along the rod (compression P): the sum of the two node
  // cases; the free-free rod softens (its lowest bending eigenvalue falls).
  const Eigen::MatrixXd compression = r.geometric.node_forces[0][0] - r.geometric.node_forces[1][0];
  const Eigen::MatrixXd k0 = r.modes.modal_stiffness.asDiagonal();
  EXPECT_LT(lowest_eigenvalue(k0 + 1000.0 * compression), lowest_eigenvalue(k0));
  // Spinning about its own axis x stresses nothing axially: no stiffening.
  EXPECT_LT(r.geometric.centrifugal[0].cwiseAbs().maxCoeff(), 1e-10);
}

TEST(GeometricStiffness, SimplySupportedPlateBucklesAtTheClassicalLoad) {
  // 1 m x 1 m steel plate, 10 mm, 16 x 16 shells. w = 0 on the four edges; in plane, u = 0
  // on x = 0 and v = 0 at its middle node (free Poisson expansion). A uniform compression N
  // [N/m] on x = 1 m as consistent nodal forces (half at the corners): Nxx = −N exactly.
  constexpr int kCells = 16;
  const double a = 1.0, t = 0.01;
  fe::FeModelBuilder builder;
  fe::ShellProperty property;
  property.name = "plate";
  property.material = testing::paper_steel();
  property.thickness = t;
  fe::RectangularPlateMesh mesh;
  mesh.edge_x = a * Eigen::Vector3d::UnitX();
  mesh.edge_y = a * Eigen::Vector3d::UnitY();
  mesh.elements_x = mesh.elements_y = kCells;
  mesh.property = builder.add_shell_property(property);
  const std::vector<int> nodes = fe::add_rectangular_plate(builder, mesh);
  const auto node = [&](int i, int j) { return nodes[static_cast<std::size_t>(j * (kCells + 1) + i)]; };
  std::vector<int> loaded;
  for (int k = 0; k <= kCells; ++k) {
    for (int edge : {node(0, k), node(kCells, k), node(k, 0), node(k, kCells)}) builder.fix(edge, fe::Dof::kUz);
    builder.fix(node(0, k), fe::Dof::kUx);
    loaded.push_back(node(kCells, k));
  }
  builder.fix(node(0, kCells / 2), fe::Dof::kUy);
  const fe::FeModel model = std::move(builder).build();
  const Reduced r = reduce(model, 6, loaded);
  // K_G per unit N: −Σ_j w_j K_j,x with the edge weights w_j = a/n (half at the corners).
  Eigen::MatrixXd k_n = Eigen::MatrixXd::Zero(r.modes.shapes.cols(), r.modes.shapes.cols());
  for (int k = 0; k <= kCells; ++k) {
    const double weight = (k == 0 || k == kCells ? 0.5 : 1.0) * a / kCells;
    k_n -= weight * r.geometric.node_forces[static_cast<std::size_t>(k)][0];
  }
  const Eigen::MatrixXd k0 = r.modes.modal_stiffness.asDiagonal();
  double low = 0.0, high = 1e7;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (low + high);
    (lowest_eigenvalue(k0 + mid * k_n) > 0.0 ? low : high) = mid;
  }
  const fe::Material& steel = property.material;
  const double d = steel.youngs_modulus * t * t * t / (12.0 * (1.0 - steel.poisson_ratio * steel.poisson_ratio));
  const double n_cr = 4.0 * pi * pi * d / (a * a);
  // The unloaded (1,1) mode against Navier's ω11 = 2 π² / a² √(D / ρt): the mesh's bending.
  const double w11 = 2.0 * pi * pi / (a * a) * std::sqrt(d / (steel.density * t));
  const double w_fe = std::sqrt(r.modes.modal_stiffness(0));
  std::printf("plate buckling load %.6g N/m, classical %.6g N/m (ratio %.5f); ω11 ratio %.5f\n", low, n_cr,
              low / n_cr, w_fe / w11);
  // 16 x 16 quads: the plate element's bending and the bilinear w of K_G both converge as h²
  // (1/256 ≈ 0.4 % per unit coefficient); 1 % on ω11 (its stiffness, 2 % on ω²) and 2 % on the
  // buckling load bound the discretisation error.
  EXPECT_NEAR(w_fe / w11, 1.0, 1e-2);
  EXPECT_NEAR(low / n_cr, 1.0, 2e-2);
}

TEST(GeometricStiffness, NodeMomentOnABentFrameLoadsItsLegAxially) {
  // An L-frame in the x-y plane: leg 1 from A = (0, 0) to the corner C = (L, 0), leg 2 from C
  // to B = (L, d). In plane, A is pinned (ux uy) and B rolls along y (ux held): statically
  // determinate. A couple M_z anywhere on it is balanced by R_Bx = M/d at B and −M/d at A,
  // so leg 1 carries the axial force N1 = M/d (tension) and leg 2 none (R_By = 0). Out of
  // plane A holds uz rx ry and B uz: no in-plane load reaches them.
  constexpr int kLeg = 10;
  const double d = 0.4;
  fe::FeModelBuilder builder;
  const int property = builder.add_beam_property(testing::rod_property(false));
  fe::StraightBeamMesh leg1;
  leg1.end = kLength * Eigen::Vector3d::UnitX();
  leg1.elements = kLeg;
  leg1.orientation = Eigen::Vector3d::UnitY();
  leg1.property = property;
  const std::vector<int> nodes1 = fe::add_straight_beam(builder, leg1);
  // Leg 2 from the corner node: its own nodes after the corner.
  std::vector<int> nodes2{nodes1.back()};
  for (int i = 1; i <= kLeg; ++i) {
    nodes2.push_back(builder.add_node(100 + i, Eigen::Vector3d(kLength, d * i / kLeg, 0.0)));
    builder.add_beam({{nodes2[i - 1], nodes2[i]}, -Eigen::Vector3d::UnitX(), property});
  }
  using fe::Dof;
  for (Dof dof : {Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx, Dof::kRy}) builder.fix(nodes1.front(), dof);
  for (Dof dof : {Dof::kUx, Dof::kUz}) builder.fix(nodes2.back(), dof);
  const fe::FeModel model = std::move(builder).build();
  const int corner = nodes1.back();
  const Reduced r = reduce(model, 6, {corner, nodes1[kLeg / 2]});
  // Hand statics: K_G of leg 1 at N = 1/d per unit couple, projected on the same modes.
  const fe::BeamProperty& beam = model.beam_properties[0];
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(r.modes.shapes.cols(), r.modes.shapes.cols());
  Eigen::MatrixXd phi_e(12, r.modes.shapes.cols());
  for (const fe::BeamElement& e : model.beams) {
    const Eigen::Vector3d &p0 = model.node_positions[e.nodes[0]], &p1 = model.node_positions[e.nodes[1]];
    if (std::abs(p1.y() - p0.y()) > 0.0) continue;  // leg 2: no axial force
    for (int end = 0; end < 2; ++end) phi_e.middleRows(6 * end, 6) = r.modes.shapes.middleRows(6 * e.nodes[end], 6);
    expected += phi_e.transpose() * fe::beam_geometric_stiffness(p0, p1, e.orientation, beam, 1.0 / d) * phi_e;
  }
  // The static solve's round-off relative to the matrices' size (the FE statics are exact
  // for end loads on Hermite beams: N is constant along leg 1).
  const double scale = expected.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_LT((r.geometric.node_moments[j][2] - expected).cwiseAbs().maxCoeff(), 1e-8 * scale) << "load node " << j;
  }
  std::printf("L-frame couple: |K_T,z − K_G(N = 1/d)| / |K_G| = %.2e\n",
              (r.geometric.node_moments[0][2] - expected).cwiseAbs().maxCoeff() / scale);
  // A couple about the straight rod's own axis or across it makes no axial force there.
  const Reduced straight = reduce(rod({{0, {Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx}}, {kElements, {Dof::kUy, Dof::kUz}}}),
                                  4, {kElements / 2});
  // (Scale: the axial node force there, which does stress the rod's first half.)
  const double rod_scale = straight.geometric.node_forces[0][0].cwiseAbs().maxCoeff();
  ASSERT_GT(rod_scale, 0.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(straight.geometric.node_moments[0][k].cwiseAbs().maxCoeff(), 1e-8 * rod_scale) << "axis " << k;
  }
}

}  // namespace
}  // namespace limber::modal
