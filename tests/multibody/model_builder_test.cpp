// Bad model input is rejected at the builder with an expected/got message and the
// caller's location.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace limber::multibody
