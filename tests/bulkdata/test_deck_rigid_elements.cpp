// RBE2 and RBE3 from decks, eliminated by u = T u_r before the modal reduction
// (fe/multipoint_constraints.h, modal/constrained_matrices.h), against models without them:
//  - an RBE2 joining two coincident grids equals the model with the grids merged;
//  - an RBE2 carrying an offset mass equals a CONM1 at the independent grid holding the
//    rigidly transferred mass S^T M S, and its dependent grid moves rigidly in every mode;
//  - an RBE3 adds no stiffness or mass: frequencies unchanged, a free-free plate keeps exactly
//    six rigid modes, and the reference grid's motion in a mode is the weighted fit;
//  - the closed form of the RBE3 average (reference at the weighted centroid: translation =
//    weighted mean of the translations), and exact reproduction of rigid motion;
//  - static modes at the independent grid of a spider, attachment modes at a dependent grid.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "deck_text.h"
#include "fe/rigid_elements.h"
#include "modal/component_modes.h"
#include "modal/geometric_stiffness.h"

namespace limber::bulkdata {
namespace {

using test::FieldFormat;

fe::FeModel from_deck_text(const std::string& text, const DeckOptions& options = {}) {
  fe::FeModelBuilder builder;
  add_deck(parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf"), options, builder);
  return std::move(builder).build();
}

modal::ModalResult modes(const fe::FeModel& model, int count) {
  modal::ModeRequest request;
  request.normal_count = count;
  modal::ModalResult result = modal::compute_component_modes(model, request);
  EXPECT_EQ(result.status, modal::ModalStatus::kOk) << result.message;
  return result;
}

std::vector<double> frequencies(const modal::ModalResult& result) {
  std::vector<double> hz;
  for (const modal::ModeInfo& mode : result.mode_set.modes) hz.push_back(mode.frequency_hz);
  return hz;
}

int index_of(const fe::FeModel& model, int id) {
  return static_cast<int>(std::find(model.node_ids.begin(), model.node_ids.end(), id) -
                          model.node_ids.begin());
}

std::string card(const std::vector<std::string>& fields) { return test::card_text(FieldFormat::kFree, fields); }

// A steel cantilever 1 m along x, 20 CBARs (PBARL BAR 10 x 20 mm), clamped at grid 1 by SPC1
// set 1. With `split`, grid 11 is doubled: the beams right of it start at grid 1011 (same
// place), which `extra` may join to 11.
std::string cantilever(bool split, const std::string& extra) {
  std::string text = "BEGIN BULK\n";
  text += card({"MAT1", "1", "2.1+11", "", "0.3", "7850."});
  text += card({"PBARL", "7", "1", "", "BAR", "", "", "", "", "0.01", "0.02"});
  for (int i = 0; i <= 20; ++i) text += card({"GRID", std::to_string(i + 1), "", fmt::format("{:.2f}", i / 20.0), "0.", "0."});
  if (split) text += card({"GRID", "1011", "", "0.50", "0.", "0."});
  for (int i = 1; i <= 20; ++i) {
    const int a = split && i == 11 ? 1011 : i;
    text += card({"CBAR", std::to_string(100 + i), "7", std::to_string(a), std::to_string(i + 1), "0.", "1.", "0."});
  }
  text += card({"SPC1", "1", "123456", "1"});
  return text + extra + "ENDDATA\n";
}

DeckOptions clamped() {
  DeckOptions options;
  options.spc_set = 1;
  return options;
}

// Frequencies of nearly equal reduced problems: the eigen-solver's convergence (1e-10)
// dominates; 1e-8 bounds it (as in test_deck_cross_check.cpp).
constexpr double kFrequencyTolerance = 1e-8;

void expect_same_frequencies(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], kFrequencyTolerance * b[i]) << "mode " << i;
}

TEST(DeckRigidElements, Rbe2JoiningCoincidentGridsEqualsMergedGrids) {
  const fe::FeModel merged = from_deck_text(cantilever(false, ""), clamped());
  const fe::FeModel joined = from_deck_text(cantilever(true, card({"RBE2", "900", "11", "123456", "1011"})), clamped());
  EXPECT_EQ(joined.multipoint_constraints.size(), 6u);
  const modal::ModalResult a = modes(merged, 8);
  const modal::ModalResult b = modes(joined, 8);
  expect_same_frequencies(frequencies(b), frequencies(a));
  // The dependent grid carries the independent grid's motion in every mode.
  const int n11 = index_of(joined, 11), n1011 = index_of(joined, 1011);
  const Eigen::MatrixXd& phi = b.mode_set.shapes;
  EXPECT_LT((phi.middleRows(6 * n1011, 6) - phi.middleRows(6 * n11, 6)).cwiseAbs().maxCoeff(),
            1e-14 * phi.cwiseAbs().maxCoeff());
}

TEST(DeckRigidElements, GeometricStiffnessThroughAnRbe2EqualsMergedGrids) {
  // The centrifugal and tip-force geometric stiffness of the split cantilever (static solves
  // with the RBE2 eliminated) equals the merged one's. Diagonal entries phi_i^T K_G phi_i do
  // not depend on the modes' signs (the frequencies are distinct).
  const fe::FeModel merged = from_deck_text(cantilever(false, ""), clamped());
  const fe::FeModel joined = from_deck_text(cantilever(true, card({"RBE2", "900", "11", "123456", "1011"})), clamped());
  const auto stiffness = [](const fe::FeModel& model) {
    const modal::ModalResult result = modes(model, 4);
    const std::vector<int> tip = {index_of(model, 21)};
    return modal::compute_modal_geometric_stiffness(model, fe::assemble(model), result.mode_set.shapes, tip);
  };
  const modal::ModalGeometricStiffnessResult a = stiffness(merged);
  const modal::ModalGeometricStiffnessResult b = stiffness(joined);
  ASSERT_EQ(a.status, modal::ModalStatus::kOk);
  ASSERT_EQ(b.status, modal::ModalStatus::kOk) << b.message;
  const auto expect_same_diagonal = [](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    // Static solves and modes to ~1e-10; 1e-8 of the largest entry bounds their products.
    EXPECT_LT((x.diagonal() - y.diagonal()).cwiseAbs().maxCoeff(), 1e-8 * y.cwiseAbs().maxCoeff());
    EXPECT_GT(y.cwiseAbs().maxCoeff(), 0.0);
  };
  // Spin about y and z (about x, the beam axis, nothing loads the beam).
  for (int c = 1; c < 3; ++c) expect_same_diagonal(b.stiffness.centrifugal[static_cast<std::size_t>(c)], a.stiffness.centrifugal[static_cast<std::size_t>(c)]);
  expect_same_diagonal(b.stiffness.node_forces[0][0], a.stiffness.node_forces[0][0]);
}

// u_q = S u_p for a point q at offset d from p (rigid_elements.h).
Eigen::Matrix<double, 6, 6> transfer(const Eigen::Vector3d& d) {
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Identity();
  Eigen::Matrix3d d_cross;
  d_cross << 0.0, -d.z(), d.y(), d.z(), 0.0, -d.x(), -d.y(), d.x(), 0.0;
  s.topRightCorner<3, 3>() = -d_cross;
  return s;
}

TEST(DeckRigidElements, Rbe2OffsetMassEqualsTheTransferredMassAndMovesRigidly) {
  // 2 kg with inertia at grid 50, offset from the tip grid 21 and held to it by an RBE2.
  const Eigen::Vector3d d(0.1, 0.2, 0.05);
  const double m = 2.0;
  Eigen::Matrix3d inertia;
  inertia << 0.02, -0.001, 0.0, -0.001, 0.03, 0.002, 0.0, 0.002, 0.04;
  std::string spider = card({"GRID", "50", "", "1.1", "0.2", "0.05"});
  spider += card({"CONM2", "500", "50", "", "2.", "", "", "", "", "0.02", "0.001", "0.03", "0.", "-0.002", "0.04"});
  spider += card({"RBE2", "900", "21", "123456", "50"});
  const fe::FeModel with_spider = from_deck_text(cantilever(false, spider), clamped());

  // The same mass as a CONM1 at the tip: S^T blockdiag(m I, J) S, lower triangle by rows.
  Eigen::Matrix<double, 6, 6> point = Eigen::Matrix<double, 6, 6>::Zero();
  point.topLeftCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  point.bottomRightCorner<3, 3>() = inertia;
  const Eigen::Matrix<double, 6, 6> tip = transfer(d).transpose() * point * transfer(d);
  // NASTRAN field numbers (M11 in field 5, M33 in field 12, ...), markers as blanks.
  std::vector<std::string> fields = {"CONM1", "501", "21", "0"};
  int field = 5;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j <= i; ++j, ++field) {
      if (field % 10 == 0) field += 2;
      while (static_cast<int>(fields.size()) < field - 1) fields.push_back("");
      fields.push_back(fmt::format("{:.17e}", tip(i, j)));
    }
  }
  // Field numbers count the markers (10, 11, ...); card_text's fields do not: drop them.
  std::vector<std::string> data;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const int number = static_cast<int>(k) + 1;
    if (number > 1 && (number % 10 == 0 || number % 10 == 1)) continue;
    data.push_back(fields[k]);
  }
  const fe::FeModel with_conm1 = from_deck_text(cantilever(false, card(data)), clamped());

  const modal::ModalResult a = modes(with_spider, 8);
  const modal::ModalResult b = modes(with_conm1, 8);
  expect_same_frequencies(frequencies(a), frequencies(b));
  // The same link as a chain of two RBE2s through a grid half-way (substituted through T).
  std::string chain = card({"GRID", "50", "", "1.1", "0.2", "0.05"}) + card({"GRID", "49", "", "1.05", "0.1", "0.025"});
  chain += card({"CONM2", "500", "50", "", "2.", "", "", "", "", "0.02", "0.001", "0.03", "0.", "-0.002", "0.04"});
  chain += card({"RBE2", "901", "49", "123456", "50"}) + card({"RBE2", "900", "21", "123456", "49"});
  expect_same_frequencies(frequencies(modes(from_deck_text(cantilever(false, chain), clamped()), 8)), frequencies(b));
  // Grid 50 moves rigidly with the tip in every mode: u_50 = S u_21.
  const Eigen::MatrixXd& phi = a.mode_set.shapes;
  const int tip_node = index_of(with_spider, 21), mass_node = index_of(with_spider, 50);
  const Eigen::MatrixXd rigid = transfer(d) * phi.middleRows(6 * tip_node, 6);
  EXPECT_LT((phi.middleRows(6 * mass_node, 6) - rigid).cwiseAbs().maxCoeff(), 1e-13 * phi.cwiseAbs().maxCoeff());
  // The first bending mode is lowered by the mass (a sanity check that it acts at all).
  EXPECT_LT(frequencies(a)[0], frequencies(modes(from_deck_text(cantilever(false, ""), clamped()), 1))[0] * 0.5);
}

TEST(DeckRigidElements, Rbe3AddsNoStiffnessAndItsReferenceFollowsTheFit) {
  // Reference grid 60 beside the beam, averaging grids 15-21 (translations, weight 1 and 2).
  std::string rbe3 = card({"GRID", "60", "", "0.8", "0.05", "0.02"});
  rbe3 += card({"RBE3", "901", "", "60", "123456", "1.0", "123", "15", "16", "17", "18", "19", "2.0", "1234", "20", "21"});
  const fe::FeModel plain = from_deck_text(cantilever(false, ""), clamped());
  const fe::FeModel averaged = from_deck_text(cantilever(false, rbe3), clamped());
  const modal::ModalResult a = modes(plain, 8);
  const modal::ModalResult b = modes(averaged, 8);
  expect_same_frequencies(frequencies(b), frequencies(a));

  // The reference's motion in each mode is the weighted least-squares rigid fit.
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  const Eigen::Vector3d x_ref = averaged.node_positions[static_cast<std::size_t>(index_of(averaged, 60))];
  const Eigen::MatrixXd& phi = b.mode_set.shapes;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(6, phi.cols());
  // The rotational weight's length: the mean distance of the grids from the reference.
  double length = 0.0;
  for (int id = 15; id <= 21; ++id) length += (averaged.node_positions[static_cast<std::size_t>(index_of(averaged, id))] - x_ref).norm() / 7.0;
  for (int id = 15; id <= 21; ++id) {
    const int n = index_of(averaged, id);
    const double w = id >= 20 ? 2.0 : 1.0;
    const Eigen::Matrix<double, 6, 6> s = transfer(averaged.node_positions[static_cast<std::size_t>(n)] - x_ref);
    const int rows = id >= 20 ? 4 : 3;  // group 2 also averages the rotation about x
    for (int r = 0; r < rows; ++r) {
      const double weight = r < 3 ? w : w * length * length;
      normal += weight * s.row(r).transpose() * s.row(r);
      rhs += weight * s.row(r).transpose() * phi.row(6 * n + r);
    }
  }
  const Eigen::MatrixXd fit = normal.ldlt().solve(rhs);
  const int ref = index_of(averaged, 60);
  EXPECT_LT((phi.middleRows(6 * ref, 6) - fit).cwiseAbs().maxCoeff(), 1e-10 * phi.cwiseAbs().maxCoeff());
}

// A free-free aluminium plate 0.4 x 0.3 m, 4 x 3 CQUAD4, 2 mm; with `extra` cards.
std::string free_plate(const std::string& extra) {
  std::string text = "BEGIN BULK\n";
  text += card({"MAT1", "1", "7.0+10", "", "0.33", "2700."});
  text += card({"PSHELL", "2", "1", "0.002", "1"});
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 4; ++i) {
      text += card({"GRID", std::to_string(10 * j + i + 1), "", fmt::format("{:.2f}", 0.1 * i), fmt::format("{:.2f}", 0.1 * j), "0."});
    }
  }
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      const int g = 10 * j + i + 1;
      text += card({"CQUAD4", std::to_string(100 + 10 * j + i), "2", std::to_string(g), std::to_string(g + 1),
                    std::to_string(g + 11), std::to_string(g + 10)});
    }
  }
  return text + extra + "ENDDATA\n";
}

TEST(DeckRigidElements, FreeFreePlateWithRbe3KeepsSixRigidModes) {
  std::string rbe3 = card({"GRID", "99", "", "0.2", "0.15", "0.1"});
  rbe3 += card({"RBE3", "901", "", "99", "123456", "1.0", "123", "1", "5", "31", "35"});
  const modal::ModalResult a = modes(from_deck_text(free_plate("")), 6);
  const modal::ModalResult b = modes(from_deck_text(free_plate(rbe3)), 6);
  EXPECT_EQ(a.mode_set.rigid_modes.size(), 6u);
  EXPECT_EQ(b.mode_set.rigid_modes.size(), 6u);
  expect_same_frequencies(frequencies(b), frequencies(a));
  // The invariants see the same mass and inertia (the reference grid carries none).
  EXPECT_NEAR(b.mode_set.invariants.mass, a.mode_set.invariants.mass, 1e-12 * a.mode_set.invariants.mass);
  EXPECT_LT((b.mode_set.invariants.inertia - a.mode_set.invariants.inertia).norm(), 1e-12 * a.mode_set.invariants.inertia.norm());
}

TEST(DeckRigidElements, FreeFreePlateWithRbe2SpiderKeepsSixRigidModesAndGivesStaticModes) {
  // A hinge grid 0.1 m below the plate's edge, tied to three edge grids by an RBE2 spider.
  std::string spider = card({"GRID", "90", "", "0.2", "-0.1", "0."});
  spider += card({"RBE2", "900", "90", "123456", "2", "3", "4"});
  const modal::ModalResult free = modes(from_deck_text(free_plate(spider)), 6);
  EXPECT_EQ(free.mode_set.rigid_modes.size(), 6u);

  // Held at the far edge's middle grid (so that constraint modes at the hinge are elastic).
  const fe::FeModel model = from_deck_text(free_plate(spider + card({"SPC1", "1", "123456", "33"})), clamped());

  // Constraint modes at the independent (hinge) grid, attachment modes at a dependent grid.
  modal::ModeRequest request;
  request.normal_count = 4;
  request.constraint_sites = {{index_of(model, 90), {fe::Dof::kUz, fe::Dof::kRx}}};
  request.attachment_sites = {{index_of(model, 3), {fe::Dof::kUy, fe::Dof::kUz}}};
  const modal::ModalResult result = modal::compute_component_modes(model, request);
  ASSERT_EQ(result.status, modal::ModalStatus::kOk) << result.message;
  // A force uz at grid 3 is a force uz and a moment rx at the hinge, the loads of the two
  // constraint modes there: its static response lies in their span (Guyan), so it is dropped.
  ASSERT_EQ(result.notices.size(), 1u);
  EXPECT_EQ(result.notices[0].rfind("dropped attachment uz at node 3: dependent", 0), 0u) << result.notices[0];
  ASSERT_EQ(result.mode_set.shapes.cols(), 7);
  // Every mode satisfies the spider: grid 3 follows grid 90 rigidly.
  const Eigen::MatrixXd& phi = result.mode_set.shapes;
  const int hinge = index_of(model, 90), edge = index_of(model, 3);
  const Eigen::Vector3d d = model.node_positions[static_cast<std::size_t>(edge)] - model.node_positions[static_cast<std::size_t>(hinge)];
  EXPECT_LT((phi.middleRows(6 * edge, 6) - transfer(d) * phi.middleRows(6 * hinge, 6)).cwiseAbs().maxCoeff(),
            1e-12 * phi.cwiseAbs().maxCoeff());
  // Orthonormal in the full model's mass: Phi^T M Phi = I.
  const Eigen::MatrixXd mass(fe::assemble(model).mass);
  EXPECT_LT((phi.transpose() * mass * phi - Eigen::MatrixXd::Identity(7, 7)).cwiseAbs().maxCoeff(), 1e-9);

  // A constraint mode at a dependent DOF is refused with the reason.
  modal::ModeRequest bad;
  bad.constraint_sites = {{edge, {fe::Dof::kUz}}};
  try {
    modal::compute_component_modes(model, bad);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected an independent DOF, got uz at node 3"), std::string::npos) << e.what();
  }
}

TEST(RigidElements, Rbe3TranslationIsTheWeightedMeanAtTheWeightedCentroid) {
  // Four grids with weights; the reference at their weighted centroid: the translational rows
  // of A decouple from the rotations, so u_ref = sum w_i u_i / sum w_i for any u.
  const std::vector<Eigen::Vector3d> grids = {{0.0, 0.0, 0.0}, {1.0, 0.2, 0.0}, {0.3, 1.1, 0.4}, {-0.5, 0.4, 0.9}};
  const std::vector<double> weights = {1.0, 2.0, 0.5, 3.0};
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < grids.size(); ++i) {
    centroid += weights[i] * grids[i];
    total += weights[i];
  }
  centroid /= total;
  std::vector<Eigen::Vector3d> positions = grids;
  positions.push_back(centroid);
  std::vector<fe::WeightedNodes> groups;
  for (int i = 0; i < 4; ++i) groups.push_back({weights[static_cast<std::size_t>(i)], {fe::Dof::kUx, fe::Dof::kUy, fe::Dof::kUz}, {i}});
  std::string error;
  const std::vector<fe::Dof> all = {fe::Dof::kUx, fe::Dof::kUy, fe::Dof::kUz, fe::Dof::kRx, fe::Dof::kRy, fe::Dof::kRz};
  const auto constraints = fe::interpolation_constraints(positions, 4, all, groups, error);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_EQ(constraints.size(), 6u);
  const auto evaluate = [&](const fe::MultipointConstraint& c, const Eigen::VectorXd& u) {
    double value = 0.0;
    for (std::size_t k = 0; k < c.independent.size(); ++k) value += c.coefficients[k] * u[c.independent[k]];
    return value;
  };
  // An arbitrary (non-rigid) displacement.
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(30, -1.0, 2.0).array().sin();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) mean += weights[static_cast<std::size_t>(i)] * u.segment<3>(6 * i);
  mean /= total;
  // Round-off of a 6x6 solve of moderate condition.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(evaluate(constraints[static_cast<std::size_t>(k)], u), mean[k], 1e-13);

  // A rigid motion (translation t, rotation w about the origin) is reproduced exactly at the
  // reference, rotations included.
  const Eigen::Vector3d t(0.3, -0.2, 0.1), w(0.05, 0.02, -0.04);
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(30);
  for (int i = 0; i < 5; ++i) {
    rigid.segment<3>(6 * i) = t + w.cross(positions[static_cast<std::size_t>(i)]);
    rigid.segment<3>(6 * i + 3) = w;
  }
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(evaluate(constraints[static_cast<std::size_t>(k)], rigid), rigid[24 + k], 1e-14);
}

// The error of `text` names `location` and contains `message`.
void expect_error(const std::string& text, const std::string& location, const std::string& message,
                  const DeckOptions& options = {}) {
  try {
    from_deck_text(text, options);
    FAIL() << "expected an error containing: " << message;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(location, 0), 0u) << what;
    EXPECT_NE(what.find(message), std::string::npos) << what;
  }
}

TEST(DeckRigidElements, BadRigidElementsAreErrorsAtTheirCards) {
  // A dependent DOF held by an SPC.
  std::string text = cantilever(false, card({"RBE2", "900", "21", "123456", "1"}));
  expect_error(text, test::deck_location(text, "RBE2"), "RBE2 900: expected dependent DOFs that are not held", clamped());
  // The same DOF dependent twice.
  text = cantilever(false, card({"RBE2", "900", "20", "123", "21"}) + card({"RBE2", "901", "19", "1", "21"}));
  expect_error(text, test::deck_location(text, "RBE2,901"), "already dependent in RBE2 900");
  // A cycle of rigid elements.
  text = cantilever(true, card({"RBE2", "900", "11", "123456", "1011"}) + card({"RBE2", "901", "1011", "1", "12"}) +
                              card({"RBE2", "902", "12", "1", "11"}));
  expect_error(text, "deck.bdf", "got the cycle RBE2");
  // An RBE3 whose grids are on a line with translations only.
  text = cantilever(false, card({"GRID", "60", "", "0.8", "0.05", "0."}) +
                               card({"RBE3", "901", "", "60", "123", "1.0", "123", "15", "16", "17"}));
  expect_error(text, test::deck_location(text, "RBE3"), "RBE3 901: expected independent grids and components that fix all six");
  // UM is not supported.
  text = cantilever(false, card({"RBE3", "901", "", "21", "123", "1.0", "123", "15", "16", "17", "UM", "15", "1"}));
  expect_error(text, test::deck_location(text, "UM"), "UM");
  // An unknown dependent grid.
  text = cantilever(false, card({"RBE2", "900", "21", "123", "77"}));
  expect_error(text, test::deck_location(text, "77"), "RBE2 900, GM1: expected a defined GRID id, got 77");
}

}  // namespace
}  // namespace limber::bulkdata
