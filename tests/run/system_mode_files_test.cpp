// System modes as results files for `limber render` (run/system_mode_files.h): a pendulum
// about its hanging equilibrium gives one file, whose samples are one period of the swing at
// the closed-form frequency with the amplitude rule of the header, read back from results.h5.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "../multibody/linear_test_models.h"
#include "../results/h5_test_read.h"
#include "multibody/model_builder.h"
#include "run/linearize_run.h"
#include "run/system_mode_files.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

// The hanging pendulum of linearization_test.cpp (pivot at the body origin, centre of mass l
// below) with a marker at the centre of mass, the point that moves most. Its one mode swings
// at f = √(m g l / J_pivot)/2π; the amplitude rule makes that marker move 5 % of the markers'
// and origins' bounding box (its diagonal is l), i.e. a swing of 0.05 l / l = 0.05 rad, below
// the 0.2 rad cap. Tolerances: 1e-9 on the frequency (the linearization's, 8e-14 measured), 1e-12
// on angles read back (the writer stores float64).
TEST(SystemModeFiles, PendulumSwingsOnePeriodAtItsFrequency) {
  const double m = 2.0, l = 0.5, g = 9.81, Jy = 0.2;
  multibody::ModelBuilder builder = multibody::testing::pendulum_builder(m, Jy, g, -l);
  builder.add_marker_at("bob_center", "bob", Eigen::Vector3d(0, 0, -l));
  const multibody::Model model = builder.build();
  LinearizeSettings settings;
  settings.statics = true;
  const LinearizeSummary summary = linearize_mechanism(model, {}, settings);
  ASSERT_TRUE(summary.ok) << summary.message;

  const std::filesystem::path directory = test::fresh_directory("system_modes");
  SystemModeFileOptions options;  // six asked, one elastic mode there
  const std::vector<std::filesystem::path> files =
      write_system_mode_files(model, summary, directory, "pendulum", "pendulum.yaml", options);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], directory / "system_modes" / "mode_01" / "results.h5");

  const hid_t file = H5Fopen(files[0].c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<double> time = results::testing::read_doubles(file, "/time");
  const std::vector<double> q = results::testing::read_doubles(file, "/bodies/bob/orientation");
  const std::vector<double> p = results::testing::read_doubles(file, "/bodies/bob/position");
  H5Fclose(file);
  ASSERT_EQ(time.size(), static_cast<std::size_t>(options.frames + 1));
  ASSERT_EQ(q.size(), 4 * time.size());
  const double f = std::sqrt(m * g * l / (Jy + m * l * l)) / (2.0 * std::numbers::pi);
  EXPECT_NEAR(time.back() * f, 1.0, 1e-9);
  // The swing: a rotation about y of 0.05 sin(2π f t) (either sign: the shape's is free), the
  // pivot at rest; the sign from the quarter period, where the swing is largest.
  const auto angle_at = [&](std::size_t i) { return 2.0 * std::atan2(q[4 * i + 2], q[4 * i]); };
  const double sign = angle_at(static_cast<std::size_t>(options.frames / 4)) > 0.0 ? 1.0 : -1.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double expected = 0.05 * std::sin(2.0 * std::numbers::pi * f * time[i]);
    EXPECT_NEAR(angle_at(i), sign * expected, 1e-12) << "sample " << i;
    EXPECT_NEAR(q[4 * i + 1], 0.0, 1e-15);
    EXPECT_NEAR(q[4 * i + 3], 0.0, 1e-15);
    EXPECT_NEAR(Eigen::Vector3d(p[3 * i], p[3 * i + 1], p[3 * i + 2]).norm(), 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace limber::run
