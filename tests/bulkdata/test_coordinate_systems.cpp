// GRID positions in CORD2R / CORD2C / CORD2S systems (and chains of them) against
// coordinates transformed by hand, and orientation vectors in a grid's CD system.
#include <gtest/gtest.h>

#include <cmath>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "fe/fe_model_builder.h"

namespace limber::bulkdata {
namespace {

// The hand values are exact; the code's sines and cosines of degrees and the chained
// transforms round at ~1e-15 of the coordinates (~10 m here).
constexpr double kTolerance = 1e-12;

fe::FeModelBuilder translate(const std::string& text) {
  const Deck deck = parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf");
  fe::FeModelBuilder builder;
  add_deck(deck, {}, builder);
  return builder;
}

Eigen::Vector3d position(const fe::FeModelBuilder& builder, int id) {
  return builder.peek().node_positions[builder.node_index(id)];
}

// System 1 (CORD2C): origin (1, 2, 3), z along basic x, x along basic z (so y = -basic y).
// System 2 (CORD2S) given in system 1: A = (R 0, θ 0, z 0) -> (1, 2, 3); B = (0, 0, 1) ->
// (2, 2, 3), so its z is basic x; C = (1, 90°, 0) -> (1, 1, 3), so its x is -basic y; then
// its y = z × x = -basic z.
const char* kSystems =
    "CORD2C,1,0,1.,2.,3.,6.,2.,3.\n"
    ",2.,2.,4.\n"
    "CORD2S,2,1,0.,0.,0.,0.,0.,1.\n"
    ",1.,90.,0.\n";

TEST(CoordinateSystems, CylindricalAndSphericalGridsMatchHandTransforms) {
  // Unused elements would fail the builder's final check, not these positions.
  const std::string text = std::string(kSystems) +
                           // (R 2, θ 30°, z 0.5) in 1: local (√3, 1, 0.5) -> (1.5, 1, 3 + √3)
                           "GRID,1,1,2.,30.,0.5\n"
                           // (R 2, θ 90°, φ 0) in 2: local (2, 0, 0) -> (1, 0, 3)
                           "GRID,2,2,2.,90.,0.\n"
                           // (R 2, θ 60°, φ 90°) in 2: local (0, √3, 1) -> (2, 2, 3 - √3)
                           "GRID,3,2,2.,60.,90.\n"
                           // basic
                           "GRID,4,,1.,2.,3.\n";
  const fe::FeModelBuilder builder = translate(text);
  const double root3 = std::sqrt(3.0);
  EXPECT_LT((position(builder, 1) - Eigen::Vector3d(1.5, 1.0, 3.0 + root3)).norm(), kTolerance);
  EXPECT_LT((position(builder, 2) - Eigen::Vector3d(1.0, 0.0, 3.0)).norm(), kTolerance);
  EXPECT_LT((position(builder, 3) - Eigen::Vector3d(2.0, 2.0, 3.0 - root3)).norm(), kTolerance);
  EXPECT_LT((position(builder, 4) - Eigen::Vector3d(1.0, 2.0, 3.0)).norm(), kTolerance);
}

TEST(CoordinateSystems, RectangularChainAndOrientationInDisplacementSystem) {
  // System 5 (CORD2R) rotated 90° about basic z: local x = basic y, local y = -basic x,
  // origin (10, 0, 0). System 6 in 5, shifted by local (0, 0, 1) and not rotated.
  // A CBAR from grid 1 to 2 along basic x with X = (1, 0, 0) in GA's CD = 5 points along
  // basic y: local y of the beam is basic y.
  const std::string text =
      "CORD2R,5,,10.,0.,0.,10.,0.,1.\n,10.,1.,0.\n"
      "CORD2R,6,5,0.,0.,1.,0.,0.,2.\n,1.,0.,1.\n"
      "GRID,1,6,1.,2.,3.,5\n"  // in 6 at (1, 2, 3): in 5 (1, 2, 4): basic (10 - 2, 1, 4)
      "GRID,2,,9.,1.,4.\n"
      "MAT1,1,7.+10,,0.3,2700.\n"
      "PBAR,1,1,1.-4,2.-9,1.-9,3.-9\n"
      "CBAR,1,1,1,2,1.,0.,0.\n";
  const fe::FeModelBuilder builder = translate(text);
  EXPECT_LT((position(builder, 1) - Eigen::Vector3d(8.0, 1.0, 4.0)).norm(), kTolerance);
  const fe::BeamElement& beam = builder.peek().beams.at(0);
  EXPECT_LT((beam.orientation - Eigen::Vector3d(0.0, 1.0, 0.0)).norm(), kTolerance);
}

// Expects `text` to fail translation at `line` with `words`.
void expect_failure(const std::string& text, int line, const std::string& words) {
  try {
    translate(text);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(CoordinateSystems, UnknownReferencesCyclesAndDegenerateSystems) {
  // A GRID in an undefined system: at its CP field.
  expect_failure("GRID,1,7,0.,0.,0.\n", 1, "GRID 1, field 3 (CP): expected a defined coordinate system");
  expect_failure("GRID,1,,0.,0.,0.,8\n", 1, "GRID 1, field 7 (CD)");
  // A reference to an undefined system.
  expect_failure("CORD2R,1,4,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n", 1, "field 3 (RID)");
  // 1 -> 2 -> 3 -> 1, and a system that refers to itself.
  expect_failure(
      "CORD2R,1,2,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\nCORD2R,2,3,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n"
      "CORD2R,3,1,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n",
      5, "cycle 1 -> 2 -> 3 -> 1");
  expect_failure("CORD2R,9,9,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n", 1, "cycle 9 -> 9");
  // C on the z axis; B at A.
  expect_failure("CORD2R,1,,0.,0.,0.,0.,0.,1.\n,0.,0.,2.\n", 1, "not on one line");
  expect_failure("CORD2R,1,,1.,1.,1.,1.,1.,1.\n,0.,0.,2.\n", 1, "not on one line");
}

}  // namespace
}  // namespace limber::bulkdata
