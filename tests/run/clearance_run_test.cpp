// The clearance through `limber run`'s driver: a bar driven round a hinge at the origin
// sweeps its tip through a block and away again; results.h5 holds the minimum per sample
// against the closed form, and the run summary the deepest interference, its time and pair.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../multibody/test_models.h"
#include "../results/h5_test_read.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

using results::testing::dataset_dims;
using results::testing::read_doubles;

// Bar: box 1 x 0.05 x 0.05 m from the hinge along its x, turned about ground z at 1 rev/s.
// Block: free 1 m cube centred at (1.4, 0, 0), near face x = 0.9, no gravity (stays put).
multibody::Model bar_and_block() {
  using multibody::testing::body_spec;
  multibody::ModelBuilder builder;
  multibody::RigidBodySpec bar = body_spec("bar", 1.0, multibody::testing::rod_inertia(1.0, 1.0),
                                           Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                                           Eigen::Vector3d(0.5, 0, 0));
  multibody::Shape bar_box;
  bar_box.size = Eigen::Vector3d(1.0, 0.05, 0.05);
  bar_box.offset.position = Eigen::Vector3d(0.5, 0, 0);
  bar.shapes.push_back(bar_box);
  builder.add_rigid_body(bar);
  multibody::RigidBodySpec block = body_spec("block", 1.0, Eigen::Vector3d(0.2, 0.2, 0.2), Eigen::Vector3d(1.4, 0, 0));
  block.shapes.push_back(multibody::Shape{});  // unit box at the body origin
  builder.add_rigid_body(block);
  builder.add_marker_at("R.ground", "ground", Eigen::Vector3d::Zero());
  builder.add_marker_at("R.bar", "bar", Eigen::Vector3d::Zero());
  builder.add_joint("R", multibody::JointType::kRevolute, "R.ground", "R.bar");
  builder.add_driver("D", "R", multibody::DriverCoordinate::kRotation,
                     multibody::TimeFunction::constant_speed(0.0, 2.0 * std::numbers::pi));
  return builder.build();
}

TEST(RunClearance, ResultsHoldTheMinimumPerSampleAndTheSummaryTheDeepest) {
  const multibody::Model model = bar_and_block();
  io::RunSettings settings;
  settings.integrator.method = integrate::Method::kIda;
  settings.integrator.rtol = 1e-8;
  settings.integrator.atol = 1e-10;
  settings.t_end = 0.9;  // short of a full turn: θ = 0 only at t = 0
  settings.sample_interval = 0.05;
  const auto dir = test::fresh_directory("clearance");
  RunSummary summary;
  {
    results::ResultsWriter writer(dir, "bar and block", "");
    RunHooks hooks;
    hooks.writer = &writer;
    summary = run_mechanism(model, {}, settings, hooks);
  }
  ASSERT_TRUE(summary.ok) << summary.message;

  // θ = 0 (t = 0): the bar's tip corners are 0.1 m inside the block (nearest face x = 0.9;
  // the others ≥ 0.475 m off), its deepest reach. θ = π (t = 0.5 s): its hinge-end corners face the
  // block 0.9 m away. IDA holds the driver's angle to ~rtol, moving these points by
  // ≤ 1 m · 1e-8 rad; bound 1e-6 m.
  const double tolerance = 1e-6;
  ASSERT_TRUE(summary.clearance.checked);
  EXPECT_NEAR(summary.clearance.distance, -0.1, tolerance);
  EXPECT_EQ(summary.clearance.time, 0.0);
  EXPECT_EQ(summary.clearance.body_a, "bar");
  EXPECT_EQ(summary.clearance.body_b, "block");

  const hid_t file = H5Fopen((dir / results::kResultsFileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_fixed_strings(file, "/clearance/pairs"), std::vector<std::string>{"bar, block"});
  EXPECT_EQ(dataset_dims(file, "/clearance/minimum"), std::vector<hsize_t>{19});
  EXPECT_EQ(dataset_dims(file, "/clearance/pair"), std::vector<hsize_t>{19});
  const std::vector<double> minimum = read_doubles(file, "/clearance/minimum");
  const std::vector<double> pair = read_doubles(file, "/clearance/pair");
  H5Fclose(file);
  ASSERT_EQ(minimum.size(), 19u);
  EXPECT_NEAR(minimum[0], -0.1, tolerance);
  EXPECT_NEAR(minimum[10], 0.9, tolerance);
  for (double index : pair) EXPECT_EQ(index, 0.0);
}

TEST(RunClearance, NoClearanceWithoutTwoSurfaces) {
  // The seed slider-crank built in C++ has no shapes: nothing to check, no group written.
  multibody::testing::SliderCrankParameters parameters;
  const multibody::Model model = multibody::testing::slider_crank(parameters);
  io::RunSettings settings;
  settings.t_end = 0.01;
  settings.sample_interval = 0.005;
  const auto dir = test::fresh_directory("no_clearance");
  RunSummary summary;
  {
    results::ResultsWriter writer(dir, "slider-crank", "");
    RunHooks hooks;
    hooks.writer = &writer;
    summary = run_mechanism(model, {}, settings, hooks);
  }
  ASSERT_TRUE(summary.ok) << summary.message;
  EXPECT_FALSE(summary.clearance.checked);
  const hid_t file = H5Fopen((dir / results::kResultsFileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_LE(H5Lexists(file, "/clearance", H5P_DEFAULT), 0);
  H5Fclose(file);
}

}  // namespace
}  // namespace limber::run
