// Mode-shape animations: the amplitude rule, the one-period Results drawn for a mode, and the
// one modes.h5 reader (results/modes_reader.h) against the modal solver's own output.
#include "mode_animation.h"

#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/modes_file.h"
#include "results/modes_reader.h"
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

TEST(ModesReader, ReadsTheModalSolversOwnOutputBitForBit) {
  // The cantilever plate case reduced here (the modal solver's own output: FE model and mode
  // set), written by io's writer as `limber modes` does, read back by the one modes.h5 reader.
  // Doubles are stored as IEEE float64: every value comes back identical (tolerance 0).
  const io::Case input = io::read_case_file(std::string(LIMBER_CASES_DIR) + "/plate_modes.yaml");
  io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kAllBodies);
  std::vector<io::BodyModesRef> written;
  for (std::size_t b = 0; b < input.flexible_bodies.size(); ++b) {
    ASSERT_EQ(reduction.bodies[b].result.status, modal::ModalStatus::kOk);
    written.push_back({input.flexible_bodies[b].name, &input.flexible_bodies[b].model,
                       &reduction.bodies[b].result.mode_set});
  }
  const auto dir = testing::fresh_directory("modes_reader");
  io::write_modes_file((dir / "modes.h5").string(), input.title, input.file, written);
  const results::ModesData file = results::read_modes(dir / "modes.h5");
  const results::ModesData drawing = results::read_modes(dir / "modes.h5", results::ModesContent::kDrawing);

  EXPECT_EQ(file.title, input.title);
  EXPECT_EQ(file.case_file, input.file);
  ASSERT_EQ(file.bodies.size(), input.flexible_bodies.size());
  ASSERT_EQ(drawing.bodies.size(), file.bodies.size());
  for (std::size_t b = 0; b < file.bodies.size(); ++b) {
    const results::ModesBody& body = file.bodies[b];
    const fe::FeModel& model = input.flexible_bodies[b].model;
    const modal::ModeSet& set = reduction.bodies[b].result.mode_set;
    EXPECT_EQ(body.name, input.flexible_bodies[b].name);
    // Mesh and DOF layout.
    ASSERT_EQ(body.mesh.nodes.rows(), model.node_count());
    for (int n = 0; n < model.node_count(); ++n) {
      EXPECT_EQ(body.mesh.nodes.row(n).transpose(), model.node_positions[static_cast<std::size_t>(n)]);
    }
    EXPECT_EQ(body.mesh.node_ids, model.node_ids);
    EXPECT_EQ(body.mesh.quads.rows(), static_cast<Eigen::Index>(model.shells.size() + model.triangles.size()));
    EXPECT_EQ(body.dof_count, model.dof_count());
    EXPECT_EQ(body.fixed.rows(), static_cast<Eigen::Index>(model.fixed_dofs.size()));
    // Modes: shapes, kinds, frequencies and labels, stiffness, rigid modes, invariants.
    EXPECT_EQ(body.shapes, set.shapes);
    EXPECT_EQ(body.modal_stiffness, set.modal_stiffness);
    ASSERT_EQ(body.modes.size(), set.modes.size());
    for (std::size_t i = 0; i < set.modes.size(); ++i) {
      EXPECT_EQ(body.modes[i].kind, modal::to_string(set.modes[i].kind));
      EXPECT_EQ(body.modes[i].frequency_hz, set.modes[i].frequency_hz);
      EXPECT_EQ(body.modes[i].label, set.modes[i].label);
    }
    ASSERT_EQ(body.rigid_modes.size(), set.rigid_modes.size());
    EXPECT_EQ(body.invariants.mass, set.invariants.mass);
    EXPECT_EQ(body.invariants.inertia, set.invariants.inertia);
    EXPECT_EQ(body.invariants.rotation_coupling, set.invariants.rotation_coupling);
    ASSERT_EQ(body.invariants.inertia_second_order.size(), set.invariants.inertia_second_order.size());
    EXPECT_EQ(body.invariants.inertia_second_order.back(), set.invariants.inertia_second_order.back());
    // The translations drawn are the shapes' first three DOFs of every node, in both readings.
    const BodyModeShapes drawn = body_mode_shapes(drawing.bodies[b]);
    const auto nm = static_cast<Eigen::Index>(set.modes.size());
    ASSERT_EQ(drawn.mesh.mode_translations.cols(), nm);
    EXPECT_EQ(drawn.mesh.mode_translations, body.mesh.mode_translations);
    EXPECT_EQ(drawing.bodies[b].shapes.size(), 0);  // kDrawing leaves the full shapes out
    for (Eigen::Index i = 0; i < nm; ++i) {
      EXPECT_EQ(drawn.labels[static_cast<std::size_t>(i)], set.modes[static_cast<std::size_t>(i)].label);
      EXPECT_EQ(drawn.mesh.frequencies_hz(i), set.modes[static_cast<std::size_t>(i)].frequency_hz);
      for (Eigen::Index n = 0; n < model.node_count(); ++n) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(drawn.mesh.mode_translations(3 * n + c, i), set.shapes(6 * n + c, i));
      }
    }
  }
}

}  // namespace
}  // namespace limber::render
