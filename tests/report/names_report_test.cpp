// Joint, driver, energy and hinge-limit names that are not link names as they are ("R.1" is,
// "." and "latch/1" are not, "R%2E" is another's escaped form): the report's reader shows each
// name with its own series, and plot files stay distinct.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "html.h"
#include "report_test_util.h"
#include "results/results_writer.h"
#include "run_data.h"

namespace limber::report {
namespace {

// Joint j's reaction is (j, 0, 0) N, driver d's effort 10 + d, energies 20 and 21, the limit's
// angle 0.5 rad.
void write_named_run(const std::filesystem::path& dir) {
  results::ResultsWriter writer(dir, "names", "names_report_test.cpp");
  writer.add_rigid_body({"arm/left", {}});
  for (const char* joint : {"R.1", "..", "R%2E", "R~2E1"}) {
    writer.add_joint({joint, "revolute", "ground", "arm/left"});
  }
  writer.add_driver(".");
  writer.add_driver("/");
  writer.add_energy("kinetic");
  writer.add_energy("kinetic/2");
  writer.add_hinge_limit({"latch/1", "latch", "R.1", 1.0});
  for (int k = 0; k < 3; ++k) {
    results::Sample sample;
    sample.time = 0.1 * k;
    sample.bodies.resize(1);
    sample.joints.resize(4);
    for (int j = 0; j < 4; ++j) sample.joints[j].force_joint.x() = j;
    sample.driver_efforts = {10.0, 11.0};
    sample.energies = {20.0, 21.0};
    sample.hinge_limit_angles = {0.5};
    sample.hinge_limit_torques = {0.0};
    sample.hinge_limits_engaged = {0};
    writer.append_sample(sample);
  }
  writer.finish(results::RunStatus::kOk);
}

TEST(NamesReport, EveryNameWithItsOwnSeries) {
  const auto dir = testing::fresh_directory("names");
  write_named_run(dir);
  const RunData run = read_run_data(dir);
  ASSERT_EQ(run.sample_count(), 3);

  // Joints: name -> reaction x, as written.
  const std::map<std::string, double> joints = {{"R.1", 0.0}, {"..", 1.0}, {"R%2E", 2.0}, {"R~2E1", 3.0}};
  ASSERT_EQ(run.joints.size(), 4u);
  std::set<std::string> stems;
  for (const JointReactions& joint : run.joints) {
    ASSERT_EQ(joints.count(joint.name), 1u) << joint.name;
    EXPECT_EQ(joint.force_joint(2, 0), joints.at(joint.name)) << joint.name;
    stems.insert(file_stem(joint.name));
  }
  EXPECT_EQ(stems.size(), 4u);  // one plot file per joint

  std::map<std::string, double> drivers, energies;
  for (const Series& s : run.drivers) drivers[s.name] = s.values(2);
  for (const Series& s : run.energies) energies[s.name] = s.values(2);
  EXPECT_EQ(drivers, (std::map<std::string, double>{{".", 10.0}, {"/", 11.0}}));
  EXPECT_EQ(energies, (std::map<std::string, double>{{"kinetic", 20.0}, {"kinetic/2", 21.0}}));

  ASSERT_EQ(run.hinge_limits.size(), 1u);
  EXPECT_EQ(run.hinge_limits[0].name, "latch/1");
  EXPECT_EQ(run.hinge_limits[0].joint, "R.1");
  EXPECT_EQ(run.hinge_limits[0].angle(2), 0.5);
}

}  // namespace
}  // namespace limber::report
