// sweep's series of a results.h5 written by the results writer and read through the shared
// reader (results/h5_reader.h): names, values bit for bit (float64 in and out), the indeterminate
// components of the redundancy, and the fewest rows of a file whose datasets disagree.
#include <gtest/gtest.h>

#include "core/error.h"
#include "results/results_writer.h"
#include "sweep/run_series.h"

#include <filesystem>

namespace limber::sweep {
namespace {

std::filesystem::path write_run(const std::string& directory_name) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / directory_name;
  std::filesystem::remove_all(directory);
  results::ResultsWriter writer(directory, "series", "case.yaml");
  results::FlexibleBodySpec rod;
  rod.name = "rod/1";  // a name whose link name differs: the series show the name
  rod.nodes = Eigen::Matrix<double, 2, 3, Eigen::RowMajor>::Zero();
  rod.lines.resize(1, 2);
  rod.lines << 0, 1;
  rod.mode_translations = Eigen::MatrixXd::Zero(6, 1);
  rod.frequencies_hz = Eigen::VectorXd::Constant(1, 10.0);
  rod.has_deflection = true;
  writer.add_flexible_body(rod);
  writer.add_joint(results::JointSpec("R1", "revolute", "ground", "rod/1"));
  writer.set_redundant_equations({"R1.rot_x"}, {"R1.z"});
  for (int k = 0; k < 2; ++k) {
    results::Sample sample;
    sample.time = 0.5 * k;
    results::BodySample body;
    body.deflection = Eigen::Vector3d(0.0, 0.0, 1e-3 * k);
    body.modal_coordinates = body.modal_velocities = Eigen::VectorXd::Zero(1);
    sample.bodies = {body};
    results::JointSample joint;
    joint.force_joint = Eigen::Vector3d(1.0 + k, 2.0, 3.0);
    joint.torque_joint = Eigen::Vector3d(0.0, -4.0 * k, 0.0);
    sample.joints = {joint};
    writer.append_sample(sample);
  }
  writer.finish(results::RunStatus::kOk);
  return directory / results::kResultsFileName;
}

TEST(RunSeries, ReadsReactionsDeflectionsAndRedundancyAtTheLayoutsPaths) {
  const RunSeries series = read_run_series(write_run("limber_run_series_test"));
  EXPECT_EQ(series.status, "ok");
  EXPECT_EQ(series.message, "");
  ASSERT_EQ(series.time.size(), 2);
  EXPECT_EQ(series.time(1), 0.5);
  const std::vector<std::string> names = {
      "R1 force x [N]",         "R1 force y [N]",          "R1 force z [N]",
      "R1 torque x [N m]",      "R1 torque y [N m]",       "R1 torque z [N m]",
      "rod/1 deflection x [m]", "rod/1 deflection y [m]",  "rod/1 deflection z [m]"};
  EXPECT_EQ(series.names, names);
  ASSERT_EQ(series.values.rows(), 2);
  EXPECT_EQ(series.values(1, 0), 2.0);
  EXPECT_EQ(series.values(1, 4), -4.0);
  EXPECT_EQ(series.values(1, 8), 1e-3);
  EXPECT_EQ(series.indeterminate,
            (std::vector<std::string>{"R1 torque x [N m]", "R1 force z [N]"}));
}

TEST(RunSeries, MissingFileIsAnInputError) {
  EXPECT_THROW(read_run_series(std::filesystem::temp_directory_path() / "limber_no_such.h5"),
               InputError);
}

}  // namespace
}  // namespace limber::sweep
