// Mode-shape animations: the amplitude rule, the one-period Results drawn for a mode, and
// render's own modes.h5 reader cross-checked with the solver's (io::read_modes_file) on a file
// written by `limber modes`.
#include "mode_animation.h"
#include "modes_reader.h"

#include "core/error.h"
#include "io/modes_file.h"
#include "test_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace limber::render {
namespace {

// Three nodes spanning a 2 x 1 x 0 box (diagonal sqrt(5)); one mode moving node 2 by (0, 0, 4)
// and node 1 by (0, 3, 0); a two-element beam.
BodyModeShapes three_node_body() {
  BodyModeShapes body;
  body.name = "bar";
  body.mesh.nodes.resize(3, 3);
  body.mesh.nodes << 0, 0, 0, 1, 0, 0, 2, 1, 0;
  body.mesh.lines.resize(2, 2);
  body.mesh.lines << 0, 1, 1, 2;
  body.mesh.mode_translations.setZero(9, 1);
  body.mesh.mode_translations(4, 0) = 3.0;
  body.mesh.mode_translations(8, 0) = 4.0;
  body.mesh.frequencies_hz = Eigen::VectorXd::Constant(1, 50.0);
  body.kinds = {"normal"};
  body.labels = {"normal 1"};
  return body;
}

TEST(ModeAnimation, AmplitudeMovesThePeakNodeByTheFractionOfTheSize) {
  const BodyModeShapes body = three_node_body();
  // Peak |phi| = 4 at node 2: A = 0.1 sqrt(5) / 4.
  EXPECT_DOUBLE_EQ(mode_amplitude(body.mesh, 0, 0.1), 0.1 * std::sqrt(5.0) / 4.0);
  FlexibleMesh still = body.mesh;
  still.mode_translations.setZero();
  EXPECT_EQ(mode_amplitude(still, 0, 0.1), 0.0);
}

TEST(ModeAnimation, OnePeriodOfTheModeAtRestAtTheOrigin) {
  const BodyModeShapes body = three_node_body();
  ModeAnimationOptions options;
  options.frames_per_cycle = 24;
  const Results results = mode_results(body, 0, options);

  // 25 samples over T = 1/50 s; eta = A sin(2 pi k / 24), peak A at k = 6.
  ASSERT_EQ(results.sample_count(), 25);
  EXPECT_DOUBLE_EQ(results.time(24), 1.0 / 50.0);
  ASSERT_EQ(results.bodies.size(), 1u);
  const BodyTrack& track = results.bodies[0];
  const double A = mode_amplitude(body.mesh, 0, 0.1);
  EXPECT_NEAR(track.modal_coordinates(6, 0), A, 1e-15);
  EXPECT_NEAR(track.modal_coordinates(0, 0), 0.0, 1e-15);
  EXPECT_TRUE(track.position.isZero());
  EXPECT_EQ(track.orientation.row(3), Eigen::RowVector4d(1, 0, 0, 0));
  // Beams drawn as tubes of 1 % of the size; the title states the amplitude.
  EXPECT_DOUBLE_EQ(track.mesh.beam_radius, 0.01 * std::sqrt(5.0));
  EXPECT_NE(results.title.find("mode 1/1: normal 1, 50 Hz"), std::string::npos) << results.title;
  EXPECT_NE(results.title.find("eta = "), std::string::npos) << results.title;
}

TEST(ModeAnimation, BadOptionsAndMissingFileAreInputErrors) {
  const auto dir = testing::fresh_directory("mode_animation_bad");
  ModeAnimationOptions options;
  EXPECT_THROW(animate_modes(dir / "modes.h5", dir, options), InputError);
  options.amplitude_fraction = -1.0;
  EXPECT_THROW(animate_modes(dir / "modes.h5", dir, options), InputError);
}

TEST(ModesReader, AgreesWithTheSolversReader) {
  // modes.h5 of the cantilever plate case, written by `limber modes`.
  const auto dir = testing::fresh_directory("modes_reader");
  const std::string command = std::string(LIMBER_EXE) + " modes " + LIMBER_CASES_DIR +
                              "/plate_modes.yaml --no-animation -o " + dir.string() +
                              " >/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const ModeShapes shapes = read_mode_shapes(dir / "modes.h5");
  const io::ModesFile expected = io::read_modes_file((dir / "modes.h5").string());

  EXPECT_EQ(shapes.title, expected.title);
  ASSERT_EQ(shapes.bodies.size(), expected.bodies.size());
  for (std::size_t b = 0; b < shapes.bodies.size(); ++b) {
    const BodyModeShapes& body = shapes.bodies[b];
    const io::BodyModes& other = expected.bodies[b];
    EXPECT_EQ(body.name, other.name);
    ASSERT_EQ(body.mesh.nodes.rows(), static_cast<Eigen::Index>(other.nodes.size()));
    EXPECT_EQ(body.mesh.quads.rows(), static_cast<Eigen::Index>(other.quads.size()));
    const auto nm = static_cast<Eigen::Index>(other.mode_set.modes.size());
    ASSERT_EQ(body.mesh.mode_translations.cols(), nm);
    for (Eigen::Index i = 0; i < nm; ++i) {
      const auto k = static_cast<std::size_t>(i);
      EXPECT_EQ(body.labels[k], other.mode_set.modes[k].label);
      EXPECT_EQ(body.mesh.frequencies_hz(i), other.mode_set.modes[k].frequency_hz);
      // Same stored doubles: exact equality.
      for (Eigen::Index n = 0; n < body.mesh.nodes.rows(); ++n) {
        for (int c = 0; c < 3; ++c) {
          EXPECT_EQ(body.mesh.mode_translations(3 * n + c, i), other.translations[k](n, c));
        }
      }
    }
  }
}

}  // namespace
}  // namespace limber::render
