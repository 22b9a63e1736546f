// Bad model input is rejected at the builder with an expected/got message and the
// caller's location.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

// Runs `f`, expecting an InputError whose message contains `fragment`.
template <class F>
void expect_input_error(F&& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no InputError for: " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ModelBuilder, RejectsBadBodies) {
  ModelBuilder b;
  const SourceLocation where{"case.yaml", 12, 3};
  expect_input_error([&] { b.add_rigid_body(body_spec("x", -1.0, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero()), where); },
                     "case.yaml:12:3: body \"x\" mass: expected > 0 kg, got -1");
  // Principal moments (1, 1, 3) violate I1 + I2 ≥ I3.
  expect_input_error([&] { b.add_rigid_body(body_spec("x", 1.0, Eigen::Vector3d(1, 1, 3), Eigen::Vector3d::Zero())); },
                     "I1 + I2 ≥ I3");
  b.add_rigid_body(body_spec("x", 1.0, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero()));
  expect_input_error([&] { b.add_rigid_body(body_spec("x", 1.0, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero())); },
                     "expected a unique name");
}

TEST(ModelBuilder, RejectsBadJointsAndDrivers) {
  ModelBuilder b;
  b.add_rigid_body(body_spec("a", 1.0, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero()));
  b.add_marker("m1", "a", Eigen::Vector3d::Zero());
  b.add_marker("m2", "a", Eigen::Vector3d::UnitX());
  b.add_marker("g", "ground", Eigen::Vector3d::Zero());
  expect_input_error([&] { b.add_marker("m3", "nobody", Eigen::Vector3d::Zero()); }, "got \"nobody\"");
  expect_input_error([&] { b.add_marker("m3", "a", Eigen::Vector3d::Zero(), 2.0 * Eigen::Matrix3d::Identity()); },
                     "expected a rotation matrix");
  expect_input_error([&] { b.add_joint("J", JointType::kRevolute, "m1", "m2"); }, "two different bodies");
  b.add_joint("S", JointType::kSpherical, "g", "m1");
  expect_input_error([&] { b.add_driver("D", "S", DriverCoordinate::kRotation, TimeFunction::constant(0)); },
                     "expected a revolute or cylindrical joint for a rotation, got spherical joint \"S\"");
  expect_input_error([&] { b.add_joint("S", JointType::kSpherical, "g", "m2"); }, "got a duplicate");
  expect_input_error([&] { b.add_tsda({"t", "g", "m1", -1.0, 0.0, 0.0, {}}); }, "k = -1");
}

// A joint is released once: by time or at an event, not both, and not twice (the message names
// the first release); an event release names a latch or stop (a spring is neither).
TEST(ModelBuilder, RejectsASecondReleaseAndAnEventThatIsNoLatch) {
  ModelBuilder b;
  b.add_rigid_body(body_spec("a", 1.0, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero()));
  b.add_marker("m1", "a", Eigen::Vector3d::Zero());
  b.add_marker("m2", "a", Eigen::Vector3d::UnitX());
  b.add_marker("g", "ground", Eigen::Vector3d::Zero());
  b.add_marker("g2", "ground", Eigen::Vector3d::UnitX());
  b.add_joint("R", JointType::kRevolute, "g", "m1");
  b.add_joint("HD", JointType::kSpherical, "g2", "m2");
  b.add_rsda({"spring", "g", "m1", 1.0, 0.0, 0.0, {}});
  b.add_hinge_limit({"lock", "R", HingeLimitKind::kLatch, 1.0});
  const SourceLocation where{"case.yaml", 7, 5};
  expect_input_error([&] { b.release_joint_after("HD", "spring", 0.0, where); },
                     "case.yaml:7:5: joint \"HD\": expected the release's 'after' to name a latch or stop, got "
                     "\"spring\"");
  expect_input_error([&] { b.release_joint_after("HD", "lock", -1.0, where); }, "expected a release delay >= 0 s");
  b.release_joint_after("HD", "lock", 0.1, where);
  expect_input_error([&] { b.release_joint("HD", 0.0, where); },
                     "joint \"HD\": expected one release, got a second (at 0 s after one after \"lock\")");
  expect_input_error([&] { b.release_joint_after("HD", "lock", 0.0, where); }, "expected one release, got a second");
  expect_input_error([&] { b.add_driver("D", "HD", DriverCoordinate::kRotation, TimeFunction::constant(0)); },
                     "expected a joint that is not released");
  const Model model = b.build();
  const Joint& hold_down = model.joints[static_cast<std::size_t>(model.find_joint("HD"))];
  EXPECT_EQ(hold_down.release_after, 1);  // model.forces: spring, lock
  EXPECT_EQ(hold_down.release_delay, 0.1);
  EXPECT_FALSE(std::isfinite(hold_down.release_time));
}

}  // namespace
}  // namespace limber::multibody
