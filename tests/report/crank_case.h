// The crank at constant speed without gravity (tests/report/data/crank_constant_speed.yaml), whose
// pin force is the centripetal m r w^2 in closed form, and a joint of a run looked up by name:
// shared by the report tests on frames (frame_reaction_test.cpp) and configs
// (report_config_test.cpp).
#pragma once

#include <numbers>
#include <stdexcept>
#include <string>

#include "run_data.h"

namespace limber::report::testing {

inline const std::string kCrankCase =
    std::string(LIMBER_TEST_DATA_DIR) + "/crank_constant_speed.yaml";
constexpr double kMass = 0.3, kRadius = 0.025;      // crank mass [kg], pin to CoM [m]
constexpr double kOmega = 10.0 * std::numbers::pi;  // 5 rev/s [rad/s]

inline const JointReactions& joint_named(const RunData& run, const std::string& name) {
  for (const JointReactions& joint : run.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

}  // namespace limber::report::testing
