// Constraint and attachment modes against direct static solutions of the full model
// (dense, second method) and beam closed forms.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "modal/dof_selection.h"
#include "modal/rigid_body_modes.h"
#include "modal/static_modes.h"
#include "modal_test_support.h"

namespace limber::modal {
namespace {

using fe::Dof;
using fe::FeModel;

int dof(int node, Dof d) { return FeModel::dof_index(node, d); }

// Largest entry difference relative to the largest entry of `reference`.
double relative_difference(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

// Tolerance of dense-vs-sparse static solutions: both backward stable, forward error up to
// ~eps cond(K) with cond ~ 1e9 for these 20-element rods (axial vs bending stiffness):
// 1e-6 bounds the difference with margin (measured ~1e-10).
constexpr double kStaticTolerance = 1e-6;

// Imposed displacements d at DOFs c, everything else but the held DOFs free and unloaded:
// the direct solution of K_vv u_v = -K_vc d, or, when that is singular, with the rigid
// motion Psi_N (vanishing on the held DOFs) removed by the bordered system
//   [K_vv  B; B^T 0] [u_v; mu] = [-K_vc d; -Psi_N(v)^T M_vc d],   B = M_vv Psi_N(v).
Eigen::VectorXd imposed_displacement(const fe::StructuralMatrices& mats, const Eigen::MatrixXd& psi_n,
                                     const std::vector<int>& v, const std::vector<int>& c,
                                     const Eigen::VectorXd& d) {
  const Eigen::MatrixXd k_vv = Eigen::MatrixXd(submatrix(mats.stiffness, v, v));
  const Eigen::MatrixXd k_vc = Eigen::MatrixXd(submatrix(mats.stiffness, v, c));
  const Eigen::MatrixXd m_vv = Eigen::MatrixXd(submatrix(mats.mass, v, v));
  const Eigen::MatrixXd m_vc = Eigen::MatrixXd(submatrix(mats.mass, v, c));
  const Eigen::MatrixXd psi_v = gather_rows(psi_n, v);
  const Eigen::Index nv = k_vv.rows();
  const Eigen::Index r = psi_n.cols();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(nv + r, nv + r);
  a.topLeftCorner(nv, nv) = k_vv;
  a.topRightCorner(nv, r) = m_vv * psi_v;
  a.bottomLeftCorner(r, nv) = (m_vv * psi_v).transpose();
  Eigen::VectorXd b(nv + r);
  b.head(nv) = -k_vc * d;
  b.tail(r) = -psi_v.transpose() * m_vc * d;
  const Eigen::VectorXd solution = a.fullPivLu().solve(b);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mats.stiffness.rows());
  for (std::size_t i = 0; i < v.size(); ++i) u[v[i]] = solution[static_cast<Eigen::Index>(i)];
  for (std::size_t i = 0; i < c.size(); ++i) u[c[i]] = d[static_cast<Eigen::Index>(i)];
  return u;
}

TEST(ConstraintModes, ReproduceImposedDisplacementsOfCantilever) {
  // Cantilever rod (node 0 clamped), 20 elements; constraint DOFs at the tip and mid-span.
  const FeModel model = testing::rod_model(20, true, {0});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const std::vector<int> free = fe::free_dofs(model);
  const std::vector<int> chosen = {dof(20, Dof::kUz), dof(20, Dof::kUx), dof(20, Dof::kRy),
                                   dof(10, Dof::kUy)};
  const StaticModes modes =
      compute_constraint_modes(mats.stiffness, mats.mass, rigid_body_modes(model), free, chosen);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;
  ASSERT_EQ(modes.shapes.cols(), 4);

  // Unit value at its own DOF, zero at the other chosen ones and at the clamp (exact).
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      EXPECT_EQ(modes.shapes(chosen[i], static_cast<Eigen::Index>(j)), i == j ? 1.0 : 0.0);
    }
  }
  EXPECT_EQ(modes.shapes.topRows(6).cwiseAbs().maxCoeff(), 0.0);

  // Phi_c d is the static response to the imposed displacements d.
  const Eigen::Vector4d d(0.01, -0.003, 0.02, 0.005);
  std::vector<int> c = chosen;
  std::sort(c.begin(), c.end());
  Eigen::VectorXd d_sorted(4);
  for (int i = 0; i < 4; ++i) {
    d_sorted[std::find(c.begin(), c.end(), chosen[static_cast<std::size_t>(i)]) - c.begin()] = d[i];
  }
  const Eigen::VectorXd direct = imposed_displacement(mats, Eigen::MatrixXd(model.dof_count(), 0),
                                                      set_difference(free, c), c, d_sorted);
  EXPECT_LT(relative_difference(modes.shapes * d, direct), kStaticTolerance);
}

TEST(ConstraintModes, FreeRodWithTooFewHeldDofsLosesItsRigidMotion) {
  // Free rod; transverse uz held at both ends and at mid-span: only 2 rigid motions
  // (uz translation, ry rotation) are prevented, 4 remain free.
  const FeModel model = testing::rod_model(20, true, {});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const std::vector<int> free = fe::free_dofs(model);
  const Eigen::MatrixXd psi = rigid_body_modes(model);
  const std::vector<int> chosen = {dof(0, Dof::kUz), dof(10, Dof::kUz), dof(20, Dof::kUz)};
  const StaticModes modes = compute_constraint_modes(mats.stiffness, mats.mass, psi, free, chosen);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;
  const Eigen::MatrixXd psi_n = unrestrained_rigid_motion(psi, chosen);
  ASSERT_EQ(psi_n.cols(), 4);

  // Mid-span mode: three-point bending shape with the free rigid motion M-orthogonalised
  // away, as given by the bordered direct solution.
  const std::vector<int> c = chosen;  // already ascending
  const Eigen::VectorXd direct = imposed_displacement(mats, psi_n, set_difference(free, c), c,
                                                      Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_LT(relative_difference(modes.shapes.col(1), direct), kStaticTolerance);
  // No rigid motion left: Psi_N^T M phi = 0 relative to ||M Psi_N|| ||phi|| (round-off).
  const Eigen::MatrixXd m_psi_n = mats.mass * psi_n;
  const double scale = m_psi_n.norm() * modes.shapes.norm();
  EXPECT_LT((m_psi_n.transpose() * modes.shapes).cwiseAbs().maxCoeff() / scale, 1e-13);
  // The held values survive the rigid-motion removal (Psi_N vanishes there; round-off of
  // the null-space basis only).
  EXPECT_NEAR(modes.shapes(chosen[1], 1), 1.0, 1e-12);
  EXPECT_NEAR(modes.shapes(chosen[0], 1), 0.0, 1e-12);
}

TEST(ConstraintModes, SingleHeldDofOfFreeRodGivesRigidTranslation) {
  // Unit ux at node 0 of a free rod, nothing else held: the static response is the rigid
  // translation along x, which no strain resists.
  const FeModel model = testing::rod_model(20, true, {});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const Eigen::MatrixXd psi = rigid_body_modes(model);
  const StaticModes modes = compute_constraint_modes(mats.stiffness, mats.mass, psi,
                                                     fe::free_dofs(model), {dof(0, Dof::kUx)});
  ASSERT_EQ(modes.status, ModalStatus::kOk);
  const Eigen::VectorXd phi = modes.shapes.col(0);
  // Exactly psi's x translation up to solver round-off.
  EXPECT_LT((phi - psi.col(0)).cwiseAbs().maxCoeff(), 1e-9);
}

// A free rod of 4 elements from the origin along `axis` (unit), section local y along R e_y
// where R turns e_x onto `axis`: the rod along x turned by R.
FeModel turned_rod(const Eigen::Matrix3d& rotation) {
  fe::FeModelBuilder builder;
  fe::StraightBeamMesh mesh;
  mesh.end = rotation * Eigen::Vector3d::UnitX();
  mesh.elements = 4;
  mesh.orientation = rotation * Eigen::Vector3d::UnitY();
  mesh.property = builder.add_beam_property(testing::rod_property(true));
  fe::add_straight_beam(builder, mesh);
  return std::move(builder).build();
}

TEST(ConstraintModes, FreeRodHeldAtBothEndsAlongASkewAxisIsTheTurnedRod) {
  // Translations held at both ends leave the rotation about the rod's axis free; a rotational
  // DOF must stop it. Along a skew axis that rotation moves the nodes by round-off (~1e-17), and
  // a translation with that coefficient was once taken as the support: the stiffness left was
  // singular ("not positive definite", found by the mechanism fuzz, docs/fuzzing.md). The
  // modes' stiffness Phi^T K Phi over the 6 held translations is that of the rod along x turned
  // by R (blockdiag(R, R) K_c blockdiag(R, R)^T): the support chosen differs, the modes (free of
  // rigid motion) do not. Tolerance kStaticTolerance: both are static solutions of the rod.
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(),
                                         Eigen::Vector3d(-0.2423, -0.0131, 0.9702))
          .toRotationMatrix();
  const auto held_stiffness = [](const FeModel& model) {
    const fe::StructuralMatrices mats = fe::assemble(model);
    const std::vector<int> chosen = {dof(0, Dof::kUx), dof(0, Dof::kUy), dof(0, Dof::kUz),
                                     dof(4, Dof::kUx), dof(4, Dof::kUy), dof(4, Dof::kUz)};
    const StaticModes modes = compute_constraint_modes(mats.stiffness, mats.mass, rigid_body_modes(model),
                                                       fe::free_dofs(model), chosen);
    EXPECT_EQ(modes.status, ModalStatus::kOk) << modes.message;
    return Eigen::MatrixXd(modes.shapes.transpose() * mats.stiffness * modes.shapes);
  };
  const Eigen::MatrixXd along_x = held_stiffness(turned_rod(Eigen::Matrix3d::Identity()));
  const Eigen::MatrixXd skew = held_stiffness(turned_rod(turn));
  ASSERT_EQ(skew.rows(), 6);
  Eigen::MatrixXd both_ends = Eigen::MatrixXd::Zero(6, 6);
  both_ends.topLeftCorner(3, 3) = turn;
  both_ends.bottomRightCorner(3, 3) = turn;
  EXPECT_LT(relative_difference(skew, both_ends * along_x * both_ends.transpose()), kStaticTolerance);
}

TEST(AttachmentModes, RestrainedCantileverGivesFlexibilityColumns) {
  const FeModel model = testing::rod_model(20, true, {0});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const std::vector<int> free = fe::free_dofs(model);
  const std::vector<int> chosen = {dof(20, Dof::kUz), dof(10, Dof::kUy)};
  const StaticModes modes =
      compute_attachment_modes(mats.stiffness, mats.mass, rigid_body_modes(model), free, chosen);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;

  // Closed form: tip deflection under a unit tip load L^3 / (3 E Iy) (Euler-Bernoulli;
  // Hermite elements are nodally exact for nodal loads).
  const fe::BeamProperty rod = testing::rod_property(true);
  const double tip = 1.0 / (3.0 * rod.material.youngs_modulus * rod.section.inertia_y);
  EXPECT_NEAR(modes.shapes(dof(20, Dof::kUz), 0) / tip, 1.0, 1e-10);

  // Second method: columns of the dense flexibility matrix K_ff^-1.
  const Eigen::MatrixXd k_ff = Eigen::MatrixXd(submatrix(mats.stiffness, free, free));
  Eigen::MatrixXd loads = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(free.size()), 2);
  for (int j = 0; j < 2; ++j) {
    loads(std::lower_bound(free.begin(), free.end(), chosen[static_cast<std::size_t>(j)]) - free.begin(), j) = 1.0;
  }
  const Eigen::MatrixXd g = scatter_rows(k_ff.ldlt().solve(loads), free, model.dof_count());
  EXPECT_LT(relative_difference(modes.shapes, g), kStaticTolerance);
}

TEST(AttachmentModes, FreeRodGivesInertiaReliefResponse) {
  // Free rod, unit loads at an end (uz) and at mid-span (ux, uy).
  const FeModel model = testing::rod_model(20, true, {});
  const fe::StructuralMatrices mats = fe::assemble(model);
  const Eigen::MatrixXd psi = rigid_body_modes(model);
  const std::vector<int> chosen = {dof(0, Dof::kUz), dof(10, Dof::kUx), dof(10, Dof::kUy)};
  const StaticModes modes = compute_attachment_modes(mats.stiffness, mats.mass, psi,
                                                     fe::free_dofs(model), chosen);
  ASSERT_EQ(modes.status, ModalStatus::kOk) << modes.message;

  // Second method: inertia relief as a bordered system (Craig & Kurdila ch. 18):
  //   [K  M Psi; Psi^T M  0] [x; a] = [f; 0]  ->  K x = f - M Psi a, Psi^T M x = 0.
  const Eigen::Index n = model.dof_count();
  const Eigen::MatrixXd m_psi = mats.mass * psi;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 6, n + 6);
  a.topLeftCorner(n, n) = Eigen::MatrixXd(mats.stiffness);
  a.topRightCorner(n, 6) = m_psi;
  a.bottomLeftCorner(6, n) = m_psi.transpose();
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(n + 6, 3);
  for (int j = 0; j < 3; ++j) f(chosen[static_cast<std::size_t>(j)], j) = 1.0;
  const Eigen::MatrixXd x = a.fullPivLu().solve(f).topRows(n);
  EXPECT_LT(relative_difference(modes.shapes, x), kStaticTolerance);

  // The modes are M-orthogonal to all rigid motion (round-off level).
  const double scale = m_psi.norm() * modes.shapes.norm();
  EXPECT_LT((m_psi.transpose() * modes.shapes).cwiseAbs().maxCoeff() / scale, 1e-13);
}

// determinate_support aborts only if the DOFs left free could not hold the rigid motion the
// held ones leave: never, by construction (rigid_body_modes.cpp). Checked on every held set of
// a two-node beam (12 DOFs, collinear: 4096 sets) and on 3000 random held sets of a skewed
// four-node shell patch (24 DOFs): the support has one DOF per free rigid motion and holds it
// (its rows of the dimensionless orthonormal basis of psi_free are invertible to the rank
// tolerance's margin). Returns the count of free rigid motions of each held set.
std::vector<Eigen::Index> expect_support_for_every_held_set(
    const std::vector<Eigen::Vector3d>& nodes, const std::vector<std::vector<int>>& held_sets) {
  const Eigen::MatrixXd psi = rigid_body_modes(nodes);
  const double length = rigid_length_scale(psi);
  const int n = static_cast<int>(psi.rows());
  std::vector<Eigen::Index> free_counts;
  for (const std::vector<int>& held : held_sets) {
    const Eigen::MatrixXd psi_free = unrestrained_rigid_motion(psi, held);
    free_counts.push_back(psi_free.cols());
    std::vector<int> candidates;
    for (int d = 0; d < n; ++d) {
      if (std::find(held.begin(), held.end(), d) == held.end()) candidates.push_back(d);
    }
    const std::vector<int> support = determinate_support(psi_free, candidates, length);
    EXPECT_EQ(static_cast<Eigen::Index>(support.size()), psi_free.cols());
    if (support.empty() || static_cast<Eigen::Index>(support.size()) != psi_free.cols()) continue;
    Eigen::MatrixXd scaled = psi_free;
    for (int node = 0; node < n / fe::kDofsPerNode; ++node) scaled.middleRows(fe::kDofsPerNode * node, 3) /= length;
    const Eigen::MatrixXd basis = Eigen::HouseholderQR<Eigen::MatrixXd>(scaled).householderQ() *
                                  Eigen::MatrixXd::Identity(n, psi_free.cols());
    Eigen::MatrixXd rows(psi_free.cols(), psi_free.cols());
    for (std::size_t i = 0; i < support.size(); ++i) rows.row(static_cast<Eigen::Index>(i)) = basis.row(support[i]);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rows);
    EXPECT_GT(svd.singularValues().minCoeff(), 1e3 * kRankTolerance * svd.singularValues().maxCoeff());
  }
  return free_counts;
}

// The same held sets on the same shapes scaled to 1e-12 ... 1e12 m and moved far from the frame
// origin (up to 1e6 sizes): the same count of free rigid motions, and a support for each (a
// 2.1e9 m beam once aborted on determinate_support's DEMAND: issue 31).
void expect_the_same_at_every_size(const std::vector<Eigen::Vector3d>& nodes,
                                   const std::vector<std::vector<int>>& held_sets) {
  const std::vector<Eigen::Index> reference = expect_support_for_every_held_set(nodes, held_sets);
  for (const double size : {1e-12, 1e-6, 1e6, 2.1e9, 1e12}) {
    for (const double offset : {0.0, 1e6}) {
      std::vector<Eigen::Vector3d> moved;
      for (const Eigen::Vector3d& x : nodes) moved.push_back(size * (x + Eigen::Vector3d(offset, -offset, offset)));
      EXPECT_EQ(expect_support_for_every_held_set(moved, held_sets), reference)
          << "size " << size << " m, offset " << offset << " sizes";
    }
  }
}

TEST(DeterminateSupport, ExistsForEveryHeldSetAtEverySize) {
  std::vector<std::vector<int>> beam_sets;
  for (int mask = 0; mask < (1 << 12); ++mask) {
    std::vector<int> held;
    for (int d = 0; d < 12; ++d) {
      if (mask & (1 << d)) held.push_back(d);
    }
    beam_sets.push_back(held);
  }
  expect_the_same_at_every_size({{0, 0, 0}, {1.5, 0.2, -0.1}}, beam_sets);

  std::vector<std::vector<int>> patch_sets;
  unsigned state = 12345u;  // a fixed linear congruential sequence: the same sets every run
  for (int k = 0; k < 3000; ++k) {
    std::vector<int> held;
    for (int d = 0; d < 24; ++d) {
      state = state * 1664525u + 1013904223u;
      if ((state >> 16) % 3 == 0) held.push_back(d);
    }
    patch_sets.push_back(held);
  }
  expect_the_same_at_every_size({{0, 0, 0}, {1, 0.1, 0}, {1.2, 0.9, 0.05}, {-0.1, 1, 0}}, patch_sets);
}

// A node held in all six DOFs leaves no rigid motion: the result has Psi's rows and no column.
// (The deck fuzzer's seed cantilever_free.bdf, clamped so by SPC1 123456, once took this path
// to a block of the empty matrix, a null pointer plus an offset that UndefinedBehaviorSanitizer
// reports: issue 31's deck campaign, docs/fuzzing.md. Only the sanitizer build sees that
// fault; here the shape and the partial holds' closed forms are checked.) Held translations only
// leave the three rotations about the held node: each column vanishes at the held DOFs and is
// a rigid motion, orthogonal to the translations at that node.
TEST(RigidMotion, NodeHeldInAllSixDofsLeavesNone) {
  const Eigen::MatrixXd psi = rigid_body_modes({{0, 0, 0}, {1.5, 0.2, -0.1}, {3, 0.4, -0.2}});
  const std::vector<int> clamped = {0, 1, 2, 3, 4, 5};
  const Eigen::MatrixXd none = unrestrained_rigid_motion(psi, clamped);
  EXPECT_EQ(none.rows(), psi.rows());
  EXPECT_EQ(none.cols(), 0);

  const Eigen::MatrixXd rotations = unrestrained_rigid_motion(psi, {0, 1, 2});
  ASSERT_EQ(rotations.cols(), 3);
  // Zero at the held DOFs and in Psi's span, to round-off of unit-scale orthonormal bases.
  EXPECT_LT(rotations.topRows(3).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::MatrixXd in_span = psi * psi.colPivHouseholderQr().solve(rotations);
  EXPECT_LT((in_span - rotations).cwiseAbs().maxCoeff(), 1e-12);
  // Rank 3: they rotate the node's rotational DOFs independently.
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(rotations.middleRows(3, 3)).rank(), 3);
}

}  // namespace
}  // namespace limber::modal
