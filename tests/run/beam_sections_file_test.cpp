// The beams' sections in results.h5 (docs/results-format.md, "Beam sections") from a case
// file: the seed's slider-crank (cases/slider_crank.yaml) with its rod's orientation vector
// turned to [0.3, 1, 1], declared into a results file as `limber run` does and read back with
// results/beam_sections.h. The local y axis of every beam must be the part of the case's
// orientation normal to the rod (beam_element.h), and the outline the 10 x 20 mm rectangle.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "results/beam_sections.h"
#include "results/h5_reader.h"
#include "results/results_layout.h"
#include "results/results_writer.h"
#include "run/sample_record.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

TEST(BeamSectionsFile, BeamYAxesFollowTheCasesOrientationVector) {
  const std::string path = test::write_case(
      "beam_sections",
      test::edited_case(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml",
                        "orientation: [0, 1, 0], first_node_id: 1",
                        "orientation: [0.3, 1, 1], first_node_id: 1"));
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const auto dir = test::fresh_directory("beam_sections");
  {
    results::ResultsWriter writer(dir, input.title, input.file);
    declare_model(built.model, writer);
    writer.finish(results::RunStatus::kOk);
  }

  const results::H5Reader file(dir / "results.h5", "results file", "");
  const std::string mesh = results::layout::at(results::layout::at(results::layout::kBodies, "rod"),
                                               results::layout::body::kMesh);
  const results::BeamSections s = results::read_beam_sections(file, mesh, 100);
  ASSERT_EQ(s.y_axes.rows(), 100);
  // The rod runs along its body x: y is (0, 1, 1)/√2, the orientation's part normal to x.
  // Round-off of one normalisation and a cross product: 1e-15; 1e-12 leaves a margin.
  const Eigen::Vector3d expected = Eigen::Vector3d(0.0, 1.0, 1.0).normalized();
  for (Eigen::Index e = 0; e < s.y_axes.rows(); ++e) {
    EXPECT_LT((s.y_axes.row(e).transpose() - expected).norm(), 1e-12) << "beam " << e;
  }
  // One outline, the case's rectangle: 10 mm along local y, 20 mm along z, exact corners.
  ASSERT_EQ(s.outline_count(), 1);
  EXPECT_EQ(s.hollow[0], 0);
  EXPECT_EQ(s.equivalent[0], 0);
  ASSERT_EQ(s.points.rows(), 4);
  EXPECT_DOUBLE_EQ(s.points.col(0).maxCoeff() - s.points.col(0).minCoeff(), 0.01);
  EXPECT_DOUBLE_EQ(s.points.col(1).maxCoeff() - s.points.col(1).minCoeff(), 0.02);
  for (int o : s.outline) EXPECT_EQ(o, 0);
  std::filesystem::remove_all(dir);
  std::filesystem::remove(path);
}

// The rod's sections read back from a results file declared from the case text `text`.
results::BeamSections declared_sections(const std::string& name, const std::string& text) {
  const std::string path = test::write_case(name, text);
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const auto dir = test::fresh_directory(name);
  {
    results::ResultsWriter writer(dir, input.title, input.file);
    declare_model(built.model, writer);
    writer.finish(results::RunStatus::kOk);
  }
  const results::H5Reader file(dir / "results.h5", "results file", "");
  const results::BeamSections s = results::read_beam_sections(
      file,
      results::layout::at(results::layout::at(results::layout::kBodies, "rod"),
                          results::layout::body::kMesh),
      100);
  std::filesystem::remove_all(dir);
  std::filesystem::remove(path);
  return s;
}

TEST(BeamSectionsFile, GeneralSectionsGetAMarkedStandIn) {
  // The rod's 10 x 20 mm rectangle given as a general section (A, I, J): with its extreme
  // fibres the stand-in is the 2 fibre_y x 2 fibre_z rectangle, without them the square of
  // area A (side √2e-4 m); both marked equivalent. Corners ±side/2: exact to round-off.
  const std::string rectangle = "rod: {shape: rectangle, width: 0.01, height: 0.02}";
  const std::string general = "rod: {shape: general, A: 2.0e-4, Iy: 6.667e-9, Iz: 1.667e-9, J: 4.58e-9";
  const std::string case_path = std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml";
  for (const bool fibres : {true, false}) {
    const std::string closing = fibres ? ", fibre_y: 0.005, fibre_z: 0.01}" : "}";
    std::string text = test::edited_case(case_path, rectangle, general + closing);
    // Without fibres the rod's stress output is refused: drop it.
    const std::string stress = "stress: {elements: all, every: 10}";
    if (!fibres) text.replace(text.find(stress), stress.size(), "");
    const results::BeamSections s = declared_sections(fibres ? "general_fibres" : "general_square", text);
    ASSERT_EQ(s.outline_count(), 1);
    EXPECT_EQ(s.equivalent[0], 1);
    EXPECT_EQ(s.hollow[0], 0);
    ASSERT_EQ(s.points.rows(), 4);
    const double side_y = fibres ? 0.01 : std::sqrt(2.0e-4), side_z = fibres ? 0.02 : std::sqrt(2.0e-4);
    EXPECT_NEAR(s.points.col(0).maxCoeff() - s.points.col(0).minCoeff(), side_y, 1e-15);
    EXPECT_NEAR(s.points.col(1).maxCoeff() - s.points.col(1).minCoeff(), side_z, 1e-15);
  }
}

}  // namespace
}  // namespace limber::run
