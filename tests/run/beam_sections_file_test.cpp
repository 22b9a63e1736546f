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
                        "orientation: [0, 1, 0], first_node_id: 1", "orientation: [0.3, 1, 1], first_node_id: 1"));
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

}  // namespace
}  // namespace limber::run
