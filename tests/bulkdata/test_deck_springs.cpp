// Springs, bushings, rods and general masses from decks against closed forms:
//  - CELAS2 to ground with a CONM2: f = sqrt(k/m) / 2 pi;
//  - CELAS1 (PELAS) between two CMASS1/CMASS2 masses plus a grounded CELAS2: the two
//    frequencies of the 2-DOF chain;
//  - CELAS2 on a grid whose CD system is rotated: the spring acts along CD's axis;
//  - CBUSH to ground with CONM1, both in the same rotated CORD2R: six frequencies
//    sqrt(K_i / M_ii), which any mismatch of the two rotations would mix;
//  - a fixed-free CROD chain: the exact frequencies of the consistent-mass discrete rod,
//    omega^2 = 6 E / (rho h^2) (1 - cos kh) / (2 + cos kh), kL = (2n - 1) pi / 2 (and the
//    continuum (2n - 1) c / 4L to O((kh)^2));
//  - bad cards: CBUSH between separate grids, without CID, an unknown PBUSH, scalar points.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "deck_text.h"
#include "modal/component_modes.h"

namespace limber::bulkdata {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string card(const std::vector<std::string>& fields) {
  return test::card_text(test::FieldFormat::kFree, fields);
}

fe::FeModel from_deck_text(const std::string& text, std::optional<int> spc = std::nullopt) {
  DeckOptions options;
  options.spc_set = spc;
  fe::FeModelBuilder builder;
  add_deck(parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf"), options, builder);
  return std::move(builder).build();
}

std::vector<double> frequencies(const fe::FeModel& model, int count) {
  modal::ModeRequest request;
  request.normal_count = count;
  const modal::ModalResult result = modal::compute_component_modes(model, request);
  EXPECT_EQ(result.status, modal::ModalStatus::kOk) << result.message;
  EXPECT_TRUE(result.mode_set.rigid_modes.empty());
  std::vector<double> hz;
  for (const modal::ModeInfo& mode : result.mode_set.modes) hz.push_back(mode.frequency_hz);
  return hz;
}

// A few-DOF eigenproblem solved by ARPACK over CHOLMOD: converged to 1e-10 relative, so the
// frequencies to 1e-9.
constexpr double kTolerance = 1e-9;

TEST(DeckSprings, GroundedCelas2WithAPointMass) {
  // 2.5 kg on a 4000 N/m spring along x; the other DOFs held by the grid's PS.
  const std::string text = card({"GRID", "1", "", "0.", "0.", "0.", "", "23456"}) +
                           card({"CELAS2", "10", "4000.", "1", "1"}) +
                           card({"CONM2", "20", "1", "", "2.5"});
  const std::vector<double> f = frequencies(from_deck_text(text), 1);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(f[0], std::sqrt(4000.0 / 2.5) / kTwoPi, kTolerance * f[0]);
}

TEST(DeckSprings, TwoMassChainOfCelas1AndCelas2) {
  // ground -k1- m1 -k2- m2 along z: masses by CMASS2 (m1) and CMASS1/PMASS (m2), k2 by
  // CELAS1/PELAS. det([k1 + k2 - w2 m1, -k2; -k2, k2 - w2 m2]) = 0.
  const double k1 = 3000.0, k2 = 1500.0, m1 = 2.0, m2 = 0.5;
  const std::string text = card({"GRID", "1", "", "0.", "0.", "0.", "", "12456"}) +
                           card({"GRID", "2", "", "1.", "0.", "0.", "", "12456"}) +
                           card({"CELAS2", "10", "3000.", "1", "3"}) +
                           card({"CELAS1", "11", "7", "1", "3", "2", "3"}) +
                           card({"PELAS", "7", "1500."}) +
                           card({"CMASS2", "20", "2.", "1", "3"}) +
                           card({"CMASS1", "21", "8", "2", "3"}) +
                           card({"PMASS", "8", "0.5"});
  const std::vector<double> f = frequencies(from_deck_text(text), 2);
  ASSERT_EQ(f.size(), 2u);
  // w^4 m1 m2 - w^2 ((k1 + k2) m2 + k2 m1) + k1 k2 = 0.
  const double b = (k1 + k2) * m2 + k2 * m1, disc = std::sqrt(b * b - 4.0 * m1 * m2 * k1 * k2);
  const double w1 = std::sqrt((b - disc) / (2.0 * m1 * m2)), w2 = std::sqrt((b + disc) / (2.0 * m1 * m2));
  EXPECT_NEAR(f[0], w1 / kTwoPi, kTolerance * f[0]);
  EXPECT_NEAR(f[1], w2 / kTwoPi, kTolerance * f[1]);
}

// A CORD2R rotated about z by 30 degrees, then about its new x by 20 degrees: B on its z axis,
// C in its x-z plane.
std::string rotated_system(int id) {
  const double a = 30.0 * std::numbers::pi / 180.0, b = 20.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d ex(std::cos(a), std::sin(a), 0.0);
  const Eigen::Vector3d ey0(-std::sin(a), std::cos(a), 0.0);
  const Eigen::Vector3d ez = std::cos(b) * Eigen::Vector3d::UnitZ() - std::sin(b) * ey0;
  const auto r = [](double x) { return fmt::format("{:.17e}", x); };
  return card({"CORD2R", std::to_string(id), "", "0.", "0.", "0.", r(ez.x()), r(ez.y()), r(ez.z()),
               r(ex.x()), r(ex.y()), r(ex.z())});
}

TEST(DeckSprings, Celas2ActsAlongTheGridsDisplacementSystem) {
  // Springs on components 1, 2, 3 of a grid whose CD is the rotated system and an isotropic
  // mass: each CD axis is a mode, sqrt(k_i / m) along CD's axis i.
  const std::string text = rotated_system(5) + card({"GRID", "1", "", "0.", "0.", "0.", "5", "456"}) +
                           card({"CELAS2", "10", "1000.", "1", "1"}) + card({"CELAS2", "11", "2000.", "1", "2"}) +
                           card({"CELAS2", "12", "4000.", "1", "3"}) + card({"CONM2", "20", "1", "", "1."});
  const std::vector<double> f = frequencies(from_deck_text(text), 3);
  ASSERT_EQ(f.size(), 3u);
  const double k[] = {1000.0, 2000.0, 4000.0};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[static_cast<std::size_t>(i)], std::sqrt(k[i]) / kTwoPi, kTolerance * f[static_cast<std::size_t>(i)]);
  // The first mode moves along CD's x axis only.
  const fe::FeModel model = from_deck_text(text);
  modal::ModeRequest request;
  request.normal_count = 1;
  const modal::ModalResult result = modal::compute_component_modes(model, request);
  const Eigen::Vector3d u = result.mode_set.shapes.col(0).head<3>().normalized();
  const double a = 30.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(std::abs(u.dot(Eigen::Vector3d(std::cos(a), std::sin(a), 0.0))), 1.0, 1e-12);
}

TEST(DeckSprings, GroundedCbushAndConm1InOneRotatedSystem) {
  // K1-K6 and a diagonal CONM1 M11..M66, both in CID 5: six modes sqrt(K_i / M_ii).
  const double k[] = {1.0e4, 2.0e4, 3.5e4, 500.0, 800.0, 1200.0};
  const double m[] = {2.0, 2.0 * 1.3, 2.0 * 1.7, 0.01, 0.012, 0.02};
  std::string text = rotated_system(5) + card({"GRID", "1", "", "0.1", "0.2", "0.3"});
  text += card({"CBUSH", "10", "3", "1", "", "", "", "", "5"});
  text += card({"PBUSH", "3", "K", "1.+4", "2.+4", "3.5+4", "500.", "800.", "1200."});
  // CONM1 lower triangle: M11 M21 M22 M31 M32 | M33 M41 M42 M43 M44 M51 M52 M53 | M54 M55 ...
  text += card({"CONM1", "20", "1", "5", "2.", "0.", "2.6", "0.", "0.", "3.4", "0.", "0.", "0.", "0.01", "0.",
                "0.", "0.", "0.", "0.012", "0.", "0.", "0.", "0.", "0.", "0.02"});
  const std::vector<double> f = frequencies(from_deck_text(text), 6);
  ASSERT_EQ(f.size(), 6u);
  std::vector<double> expected;
  for (int i = 0; i < 6; ++i) expected.push_back(std::sqrt(k[i] / m[i]) / kTwoPi);
  std::sort(expected.begin(), expected.end());
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(f[static_cast<std::size_t>(i)], expected[static_cast<std::size_t>(i)], kTolerance * expected[static_cast<std::size_t>(i)]) << i;
}

TEST(DeckSprings, CbushBetweenCoincidentGridsJoinsTwoParts) {
  // Two masses on coincident grids: grid 1 grounded by a CBUSH (K1 = k), grid 2 joined to it
  // by a second CBUSH (K1 = k) in basic; along x only (the rest held): the 2-DOF chain with
  // k1 = k2 = k, m1 = m2 = m: w^2 = (3 -+ sqrt 5) k / 2m.
  std::string text = card({"GRID", "1", "", "0.", "0.", "0.", "", "23456"}) + card({"GRID", "2", "", "0.", "0.", "0.", "", "23456"});
  text += card({"CBUSH", "10", "3", "1", "", "", "", "", "0"}) + card({"CBUSH", "11", "3", "1", "2", "", "", "", "0"});
  text += card({"PBUSH", "3", "K", "1.+4"});
  text += card({"CONM2", "20", "1", "", "1."}) + card({"CONM2", "21", "2", "", "1."});
  const std::vector<double> f = frequencies(from_deck_text(text), 2);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_NEAR(f[0], std::sqrt((3.0 - std::sqrt(5.0)) / 2.0 * 1.0e4) / kTwoPi, kTolerance * f[0]);
  EXPECT_NEAR(f[1], std::sqrt((3.0 + std::sqrt(5.0)) / 2.0 * 1.0e4) / kTwoPi, kTolerance * f[1]);
}

TEST(DeckSprings, FixedFreeRodChainHasTheDiscreteRodFrequencies) {
  // Steel rod 2 m along a skew axis, 20 CRODs (PROD A = 1e-4), grid 1 clamped, rotations
  // held (PS 456), the transverse translations on stiff grounded CELAS2 along CD components
  // 2 and 3 (CD x is the axis): axial, transverse and mass blocks decouple exactly, and the
  // transverse modes (~5e5 Hz) lie far above the first three axial ones (~1.3e3 Hz).
  const double e = 2.1e11, rho = 7850.0, length = 2.0;
  const int n = 20;
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  // CD system 5: x along the axis (C on x, B on z perpendicular to it).
  const Eigen::Vector3d z = Eigen::Vector3d(2.0, -1.0, 0.0).normalized();
  const auto r = [](double x) { return fmt::format("{:.17e}", x); };
  std::string text = card({"CORD2R", "5", "", "0.", "0.", "0.", r(z.x()), r(z.y()), r(z.z()), r(axis.x()), r(axis.y()), r(axis.z())});
  text += card({"MAT1", "1", "2.1+11", "", "0.3", "7850."}) + card({"PROD", "2", "1", "1.-4", "2.-9"});
  for (int i = 0; i <= n; ++i) {
    const Eigen::Vector3d p = axis * length * i / n;
    text += card({"GRID", std::to_string(i + 1), "", r(p.x()), r(p.y()), r(p.z()), "5", i == 0 ? "123456" : "456"});
    if (i == 0) continue;
    for (int c = 2; c <= 3; ++c) {
      text += card({"CELAS2", std::to_string(1000 + 10 * i + c), "1.+12", std::to_string(i + 1), std::to_string(c)});
    }
  }
  for (int i = 1; i <= n; ++i) text += card({"CROD", std::to_string(100 + i), "2", std::to_string(i), std::to_string(i + 1)});
  const std::vector<double> f = frequencies(from_deck_text(text), 3);
  ASSERT_EQ(f.size(), 3u);
  const double h = length / n;
  for (int mode = 1; mode <= 3; ++mode) {
    const double kh = (2.0 * mode - 1.0) * std::numbers::pi / 2.0 / n;
    const double omega = std::sqrt(6.0 * e / (rho * h * h) * (1.0 - std::cos(kh)) / (2.0 + std::cos(kh)));
    EXPECT_NEAR(f[static_cast<std::size_t>(mode - 1)], omega / kTwoPi, kTolerance * omega / kTwoPi) << "mode " << mode;
    // The continuum, (2n - 1) c / 4L, is approached from above by (kh)^2 / 24.
    const double continuum = (2.0 * mode - 1.0) * std::sqrt(e / rho) / (4.0 * length);
    EXPECT_NEAR(f[static_cast<std::size_t>(mode - 1)] / continuum - 1.0, kh * kh / 24.0, 0.01 * kh * kh);
  }
}

// The error of `text` starts at `location` and contains `message`.
void expect_error(const std::string& text, const std::string& location, const std::string& message) {
  try {
    from_deck_text(text);
    FAIL() << "expected an error containing: " << message;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(location, 0), 0u) << what;
    EXPECT_NE(what.find(message), std::string::npos) << what;
  }
}

TEST(DeckSprings, BadSpringCardsAreErrorsAtTheirFields) {
  const std::string grids = card({"GRID", "1", "", "0.", "0.", "0."}) + card({"GRID", "2", "", "1.", "0.", "0."}) +
                            card({"PBUSH", "3", "K", "1.+4"}) + card({"CONM2", "20", "1", "", "1."});
  std::string text = grids + card({"CBUSH", "10", "3", "1", "2", "", "", "", "0"});
  expect_error(text, test::deck_location(text, "CBUSH"), "CBUSH 10: expected coincident grids GA and GB");
  text = grids + card({"CBUSH", "10", "3", "1", "2", "0.", "1.", "0."});
  expect_error(text, test::deck_location(text, "0.,1."), "expected blank (element axes from an orientation vector");
  text = grids + card({"CBUSH", "10", "4", "1", "", "", "", "", "0"});
  expect_error(text, test::deck_location(text, "4,1"), "CBUSH 10, field 3 (PID): expected a defined PBUSH id, got 4");
  text = grids + card({"CELAS1", "10", "3", "1", "1"});
  expect_error(text, test::deck_location(text, "3,1,1"), "CELAS1 10, field 3 (PID): expected a defined PELAS id, got 3");
  text = grids + card({"CELAS2", "10", "1.", "1", "0"});
  expect_error(text, test::deck_location(text, "0\n"), "scalar points are not supported");
  text = grids + card({"CELAS2", "10", "-1.", "1", "1"});
  expect_error(text, test::deck_location(text, "CELAS2"), "CELAS2 10: expected a stiffness >= 0");
  text = grids + card({"CROD", "10", "9", "1", "2"});
  expect_error(text, test::deck_location(text, "9,1"), "CROD 10, field 3 (PID): expected a defined PROD id, got 9");
}

}  // namespace
}  // namespace limber::bulkdata
