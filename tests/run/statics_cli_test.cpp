// `limber statics` as a user runs it (popen): the shipped satellite stowed on its hold-downs
// (a floating system: six free rigid motions, no load on them) against the wing's hand statics,
// with the equilibrium as results.h5's one sample; and a load with nothing to hold it, named
// with its body and direction (exit 2).
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "mini_json.h"
#include "run_test_support.h"

namespace limber {
namespace {

using results::testing::dataset_dims;
using results::testing::read_string_attribute;

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

// The moment of the right wing's hold-down forces about the root hinge's axis (ground x through
// (0, 0.53, 0.6)) balances the root spring's stowed torque: nothing else acts on the wing about
// that axis (the revolute carries none, the panel spring is internal). The spring turns the
// panel about +x with k θ_free = 0.509 × 3.93 = 2.0004 N m, so the hold-downs give −2.0004.
TEST(StaticsCli, StowedSatelliteHoldDownsBalanceTheRootSpring) {
  const auto dir = test::fresh_directory("statics_satellite");
  const test::CommandRun run =
      run_limber("statics " + std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml -o " + dir.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const test::JsonValue json = test::parse_json(run.out);
  EXPECT_EQ(json["status"].string(), "ok");
  ASSERT_EQ(json["free_motions"].array().size(), 6u);
  for (const test::JsonValue& free : json["free_motions"].array()) {
    EXPECT_EQ(free["motion"].string(), "the whole mechanism moves as one rigid body");
    EXPECT_LT(free["load"].number(), 1e-9);
  }
  // Hold-down points in ground (the case file): x = ±0.3, y = 0.53 (inner) or 0.57 (outer),
  // z = ±0.3.
  const std::map<std::string, std::array<double, 2>> right_wing = {
      {"HD_R1a", {0.53, 0.3}}, {"HD_R1b", {0.53, 0.3}}, {"HD_R1c", {0.53, -0.3}}, {"HD_R1d", {0.53, -0.3}},
      {"HD_R2a", {0.57, 0.3}}, {"HD_R2b", {0.57, 0.3}}, {"HD_R2c", {0.57, -0.3}}, {"HD_R2d", {0.57, -0.3}}};
  double moment_x = 0.0;
  int found = 0;
  for (const test::JsonValue& joint : json["joints"].array()) {
    const auto point = right_wing.find(joint["name"].string());
    if (point == right_wing.end()) continue;
    ++found;
    const double F_y = joint["force_ground"].array()[1].number();
    const double F_z = joint["force_ground"].array()[2].number();
    moment_x += (point->second[0] - 0.53) * F_z - (point->second[1] - 0.6) * F_y;
  }
  EXPECT_EQ(found, 8);
  // The panels deform by well under a millimetre against 0.9 m levers: 1e-3 relative.
  EXPECT_NEAR(moment_x, -0.509 * 3.93, 1e-3 * 2.0);

  // The equilibrium as the file's one sample, status ok, written by "statics".
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "status"), "ok");
  EXPECT_EQ(read_string_attribute(file, "/", "integrator"), "statics");
  EXPECT_EQ(dataset_dims(file, "/time"), std::vector<hsize_t>{1});
  H5Fclose(file);
}

// A slider pushed along its rail with nothing to push against: no equilibrium, exit 2, and
// the message names the motion.
TEST(StaticsCli, LoadThatMeetsNoStiffnessIsNamed) {
  const std::string path = test::write_case("statics_free_slider", R"(title: pushed slider
bodies:
  slider: {mass: 1.0, inertia: [0.01, 0.01, 0.01], position: [0, 0, 0]}
joints:
  T: {type: translational, body_i: ground, body_j: slider, position: [0, 0, 0],
      orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}}
forces:
  push: {type: point_load, marker: T.j, force: [5, 0, 0]}
)");
  const auto dir = test::fresh_directory("statics_free_slider");
  const test::CommandRun run = run_limber("statics " + path + " -o " + dir.string());
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("a load meets no stiffness: slider translates along [1 0 0]"), std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace limber
