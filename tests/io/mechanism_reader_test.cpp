// The mechanism sections of a case: values land in the multibody::Model and the run settings;
// every bad-input class gives file:line:col and an expected/got message.
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "input_error_matchers.h"
#include "multibody/model_builder.h"
#include "multibody/rotation.h"
#include "multibody/state.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

// A pendulum on a revolute, a slider on a translational with a TSDA, one of each other
// element type, held coordinates and run settings.
const std::string kMechanism = R"(title: mechanism
gravity: [0, 0, -9.81]
bodies:
  arm:
    mass: 2.0
    inertia: [0.2, 0.3, 0.4, 0.01, 0.0, -0.02]
    center_of_mass: [0.5, 0, 0]
    position: [0, 0, 0]
    orientation: {axis: [0, 0, 1], angle: 0.5}
    angular_velocity: [0, 0, 1]
    shapes:
      - {type: box, size: [1, 0.1, 0.1], position: [0.5, 0, 0], color: [1, 0, 0]}
      - {type: cylinder, radius: 0.05, length: 0.2, orientation: {z_axis: [0, 1, 0]}}
      - {type: sphere, radius: 0.1}
  block:
    mass: 1.0
    inertia: [1e-3, 1e-3, 1e-3]
    position: [2, 0, 0]
    orientation: {quaternion: [1, 0, 0, 0]}
    velocity: [0.1, 0, 0]
markers:
  tip: {body: arm, position: [1, 0, 0]}
  anchor: {body: ground, position: [3, 0, 0], frame: ground}
  face: {body: block, position: [2, 0, 0], orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}, frame: ground}
joints:
  hinge: {type: revolute, body_i: ground, body_j: arm, position: [0, 0, 0],
          orientation: {z_axis: [0, 0, 1], x_axis: [1, 0, 0]}}
  rail: {type: translational, body_i: ground, body_j: block, position: [2, 0, 0],
         orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}}
drivers:
  spin: {joint: hinge, motion: {type: ramp, speed: 10, duration: 0.5, shape: cubic}}
forces:
  spring: {type: tsda, marker_i: anchor, marker_j: face, stiffness: 100, damping: 2, free_length: 0.8}
  motor: {type: rsda, marker_i: hinge.i, marker_j: hinge.j, damping: 0.1, actuator: 2.5}
  push: {type: point_load, marker: tip, force: [0, 1, 0], frame: marker,
         scale: {type: table, x: [0, 1], y: [0, 2]}}
assembly:
  held: [{body: block, component: x}]
  tolerance: 1e-12
run:
  integrator: galpha
  step: 2e-4
  event_step: 5e-5
  event_window: 0.1
  rho_inf: 0.9
  newton_matrix: structured
  t_end: 0.5
  sample_interval: 0.01
  max_steps: 1000
)";

TEST(MechanismReader, ValuesLandInTheModelAndSettings) {
  const Case input = read_case_text(kMechanism, "test.yaml");
  ASSERT_TRUE(input.mechanism.has_value());
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  EXPECT_EQ(model.gravity_W, Eigen::Vector3d(0, 0, -9.81));

  // Bodies: ground + 2, inertia tensor with products, pose from axis-angle.
  ASSERT_EQ(model.bodies.size(), 3u);
  const multibody::Body& arm = model.bodies[model.find_body("arm")];
  EXPECT_EQ(arm.mass, 2.0);
  EXPECT_EQ(arm.inertia_com_B(0, 1), 0.01);
  EXPECT_EQ(arm.inertia_com_B(2, 1), -0.02);
  EXPECT_EQ(arm.com_B, Eigen::Vector3d(0.5, 0, 0));
  // Quaternion of 0.5 rad about z: (cos 0.25, 0, 0, sin 0.25), exact to round-off.
  EXPECT_NEAR(arm.initial_pose.orientation(0), std::cos(0.25), 1e-15);
  EXPECT_NEAR(arm.initial_pose.orientation(3), std::sin(0.25), 1e-15);
  EXPECT_EQ(arm.initial_angular_velocity_B, Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(arm.shapes.size(), 3u);
  EXPECT_EQ(arm.shapes[1].type, multibody::ShapeType::kCylinder);
  EXPECT_EQ(arm.shapes[1].size, Eigen::Vector3d(0.05, 0.05, 0.2));
  EXPECT_EQ(arm.shapes[2].size, Eigen::Vector3d::Constant(0.1));
  EXPECT_EQ(model.bodies[model.find_body("block")].initial_velocity_W, Eigen::Vector3d(0.1, 0, 0));

  // Markers: 3 named + 2 per inline joint; a ground-frame marker expressed in the body frame.
  EXPECT_EQ(model.markers.size(), 7u);
  for (const multibody::Marker& marker : model.markers) {
    if (marker.name == "tip") {
      EXPECT_EQ(marker.p_BM, Eigen::Vector3d(1, 0, 0));
    }
    if (marker.name == "face") {
      EXPECT_NEAR(marker.p_BM.norm(), 0.0, 1e-15);  // at the block's origin
      EXPECT_NEAR(marker.R_BM.col(2).dot(Eigen::Vector3d::UnitX()), 1.0, 1e-15);
    }
  }

  // Joints and equations: revolute 5 + translational 5 + 1 driver.
  ASSERT_EQ(model.joints.size(), 2u);
  EXPECT_EQ(model.joints[1].type, multibody::JointType::kTranslational);
  EXPECT_EQ(model.num_equations(), 11);
  ASSERT_EQ(model.drivers.size(), 1u);
  EXPECT_EQ(model.drivers[0].coordinate, multibody::DriverCoordinate::kRotation);
  // Cubic ramp to 10 rad/s over 0.5 s: at the end f = ω T / 2 (the mean speed is ω/2).
  const multibody::FunctionValue end = model.drivers[0].motion.evaluate(0.5);
  EXPECT_NEAR(end.value, 10 * 0.5 / 2, 1e-12);
  EXPECT_NEAR(end.first, 10.0, 1e-12);

  // Forces in file order, with their values.
  ASSERT_EQ(model.forces.size(), 3u);
  const auto& tsda = std::get<multibody::Tsda>(model.forces[0]);
  EXPECT_EQ(tsda.stiffness, 100.0);
  EXPECT_EQ(tsda.free_length, 0.8);
  const auto& rsda = std::get<multibody::Rsda>(model.forces[1]);
  EXPECT_EQ(rsda.actuator.evaluate(3.0).value, 2.5);
  const auto& load = std::get<multibody::PointLoad>(model.forces[2]);
  EXPECT_EQ(load.frame, multibody::LoadFrame::kMarker);
  EXPECT_NEAR(load.scale.evaluate(0.25).value, 0.5, 1e-15);  // linear table

  // Assembly and run settings.
  const io::Mechanism& mechanism = built;
  ASSERT_EQ(mechanism.assembly.held.size(), 1u);
  EXPECT_EQ(mechanism.assembly.held[0].body, model.find_body("block"));
  EXPECT_EQ(mechanism.assembly.held[0].component, 0);
  EXPECT_EQ(mechanism.assembly.tolerance, 1e-12);
  EXPECT_EQ(mechanism.run.integrator.method, integrate::Method::kGeneralizedAlpha);
  EXPECT_EQ(mechanism.run.integrator.step, 2e-4);
  EXPECT_EQ(mechanism.run.integrator.event_step, 5e-5);
  EXPECT_EQ(mechanism.run.integrator.event_window, 0.1);
  EXPECT_EQ(mechanism.run.integrator.rho_inf, 0.9);
  EXPECT_EQ(mechanism.run.integrator.ida_newton_matrix, integrate::IdaNewtonMatrix::kStructured);
  EXPECT_EQ(mechanism.run.integrator.max_steps, 1000);
  EXPECT_EQ(mechanism.run.t_end, 0.5);
  EXPECT_EQ(mechanism.run.sample_interval, 0.01);
}

TEST(MechanismReader, DefaultsWithoutRunSection) {
  const std::string text = R"(bodies:
  b: {mass: 1, inertia: [1, 1, 1]}
)";
  const Case input = read_case_text(text, "test.yaml");
  ASSERT_TRUE(input.mechanism.has_value());
  EXPECT_EQ(input.mechanism->run.integrator.method, integrate::Method::kIda);
  EXPECT_EQ(input.mechanism->run.t_end, 1.0);
  EXPECT_EQ(input.mechanism->run.sample_interval, 1e-2);
  EXPECT_EQ(io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies)).model.gravity_W, Eigen::Vector3d::Zero());
  // A case without mechanism sections has no mechanism.
  EXPECT_FALSE(read_case_text("title: nothing\n", "test.yaml").mechanism.has_value());
}

// Replaces the first `from` in the mechanism text by `to`.
std::string edited(const std::string& from, const std::string& to) { return test::replaced(kMechanism, from, to); }

TEST(MechanismReader, BadInputNamesFileLineAndWhatWasExpected) {
  // Unknown key in a body.
  std::string text = edited("    center_of_mass:", "    centre_of_mass:");
  EXPECT_TRUE(fails_at(text, location_of(text, "centre_of_mass"),
                       "unknown key 'centre_of_mass' in 'arm'; expected one of: mass, inertia"));
  // Joint type.
  text = edited("type: revolute", "type: hinge");
  EXPECT_TRUE(fails_at(text, location_of(text, "hinge,"),
                       "expected one of revolute, translational, spherical"));
  // Missing mass: at the body's map.
  text = edited("    mass: 2.0\n", "");
  EXPECT_TRUE(fails_at(text, location_of(text, "inertia: [0.2"), "missing required key 'mass'"));
  // Inertia of the wrong size.
  text = edited("[1e-3, 1e-3, 1e-3]", "[1e-3, 1e-3]");
  EXPECT_TRUE(fails_at(text, location_of(text, "[1e-3, 1e-3]"),
                       "expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] for 'inertia', got 2 values"));
  // Not positive definite: the builder's message at the body's entry.
  text = edited("[1e-3, 1e-3, 1e-3]", "[1e-3, 1e-3, -1e-3]");
  EXPECT_TRUE(fails_at(text, location_of(text, "mass: 1.0"), "inertia"));
  // A centre of mass so far from the origin that the mass matrix about the origin loses the
  // inertia to rounding (a fuzz finding, tests/fuzz/regressions/): at the body's entry.
  text = edited("center_of_mass: [0.5, 0, 0]", "center_of_mass: [4294967296, 0, 0]");
  EXPECT_TRUE(fails_at(text, location_of(text, "mass: 2.0"), "center_of_mass: expected m |c|² / I1 ≤ 1e+10"));
  // Two orientation forms at once.
  text = edited("{axis: [0, 0, 1], angle: 0.5}", "{axis: [0, 0, 1], angle: 0.5, quaternion: [1, 0, 0, 0]}");
  EXPECT_TRUE(fails_at(text, location_of(text, "{axis: [0, 0, 1], angle"), "expected exactly one of"));
  // A z axis parallel to the x hint (from multibody::frame_from_axes, placed at x_axis).
  text = edited("{z_axis: [1, 0, 0], x_axis: [0, 1, 0]}, frame", "{z_axis: [1, 0, 0], x_axis: [2, 0, 0]}, frame");
  EXPECT_TRUE(fails_at(text, location_of(text, "[2, 0, 0]}, frame"), "parallel"));
  // A driver on a joint that does not exist: the builder's message at the driver's entry.
  text = edited("{joint: hinge,", "{joint: elbow,");
  EXPECT_TRUE(fails_at(text, location_of(text, "{joint: elbow"), "expected an existing joint, got \"elbow\""));
  // A function type.
  text = edited("type: ramp", "type: sine");
  EXPECT_TRUE(fails_at(text, location_of(text, "sine"), "expected one of constant, constant_speed, ramp, table"));
  // A table whose x does not increase (from TimeFunction::table, placed at x).
  text = edited("x: [0, 1]", "x: [1, 0]");
  EXPECT_TRUE(fails_at(text, location_of(text, "[1, 0]"), "increasing"));
  // Marker on a body that does not exist.
  text = edited("tip: {body: arm", "tip: {body: leg");
  EXPECT_TRUE(fails_at(text, location_of(text, "{body: leg"), "expected an existing body, got \"leg\""));
  // Held coordinate on ground, and a bad component.
  text = edited("{body: block, component: x}", "{body: ground, component: x}");
  EXPECT_TRUE(fails_at(text, location_of(text, "ground, component"), "ground does not move"));
  text = edited("component: x}", "component: w}");
  EXPECT_TRUE(fails_at(text, location_of(text, "w}"), "expected one of x, y, z, rx, ry, rz"));
  // Run settings out of range.
  text = edited("rho_inf: 0.9", "rho_inf: 1.5");
  EXPECT_TRUE(fails_at(text, location_of(text, "1.5"), "expected 0 <= rho_inf <= 1"));
  text = edited("  event_window: 0.1\n", "");
  EXPECT_TRUE(fails_at(text, location_of(text, "5e-5"), "expected 'event_window' beside 'event_step'"));
  text = edited("event_window: 0.1", "event_window: -1");
  EXPECT_TRUE(fails_at(text, location_of(text, "-1\n"), "expected a positive number"));
  // Settings that used to fail only in run::check_settings, without a place in the file.
  text = edited("  step: 2e-4\n", "  step: 2e-4\n  rtol: 2.0\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "2.0\n  event_step"), "expected 0 < rtol < 1"));
  text = edited("sample_interval: 0.01", "sample_interval: 1.0e-300");
  EXPECT_TRUE(fails_at(text, location_of(text, "1.0e-300"), "number of samples"));
  text = edited("integrator: galpha", "integrator: euler");
  EXPECT_TRUE(fails_at(text, location_of(text, "euler"), "expected one of ida, galpha"));
  text = edited("newton_matrix: structured", "newton_matrix: analytic");
  EXPECT_TRUE(fails_at(text, location_of(text, "analytic"), "expected one of differences, structured"));
  // Joint with both markers and a position.
  text = edited("{type: revolute, body_i: ground,", "{type: revolute, marker_i: tip, body_i: ground,");
  EXPECT_TRUE(fails_at(text, location_of(text, "{type: revolute"), "got both"));
  // Mechanism sections without bodies.
  EXPECT_TRUE(fails_at("gravity: [0, 0, -9.81]\n", "test.yaml:1:1", "missing required key 'bodies'"));
}

TEST(MechanismReader, HingeLatchesAndStops) {
  // A latch with the documented defaults and a stop with its own values land in the model.
  std::string text = edited("forces:\n", "forces:\n  lock: {type: latch, joint: hinge, angle: 1.5}\n"
                                          "  limit: {type: stop, joint: hinge, angle: -0.5, stiffness: 200, damping: 0}\n");
  const io::Case input = io::read_case_text(text, test::kCaseName);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  const auto& lock = std::get<multibody::HingeLimit>(model.forces[0]);  // in file order
  EXPECT_EQ(lock.kind, multibody::HingeLimitKind::kLatch);
  EXPECT_EQ(model.joints[lock.joint].name, "hinge");
  EXPECT_EQ(lock.angle, 1.5);
  EXPECT_EQ(lock.direction, 1.0);  // the hinge starts at 0 and travels up to the latch
  EXPECT_EQ(lock.stiffness, multibody::kDefaultHingeLimitStiffness);
  EXPECT_EQ(lock.damping, multibody::kDefaultHingeLimitDamping);
  const auto& limit = std::get<multibody::HingeLimit>(model.forces[1]);
  EXPECT_EQ(limit.kind, multibody::HingeLimitKind::kStop);
  EXPECT_EQ(limit.direction, -1.0);
  EXPECT_EQ(limit.stiffness, 200.0);
  // A latch on the translational joint, at the initial angle, or beyond one turn: errors at
  // the entry with what was expected.
  text = edited("forces:\n", "forces:\n  lock: {type: latch, joint: rail, angle: 1.5}\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "{type: latch"),
                       "latch \"lock\": expected a revolute joint, got translational joint \"rail\""));
  text = edited("forces:\n", "forces:\n  lock: {type: latch, joint: hinge, angle: 0}\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "{type: latch"), "expected an angle within one turn"));
  text = edited("forces:\n", "forces:\n  lock: {type: stop, joint: hinge, angle: 7}\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "{type: stop"), "expected an angle within one turn"));
  text = edited("forces:\n", "forces:\n  lock: {type: latch, joint: hinge, angle: 1, stiffness: 0}\n");
  EXPECT_TRUE(fails_at(text, location_of(text, "0}"), "expected a positive number"));
}

TEST(MechanismReader, ShippedCaseBuildsTheRedundantSliderCrank) {
  // cases/slider_crank_rigid.yaml: 3 moving bodies (18 velocities), 3 revolutes (5 rows
  // each) + translational (5) = 20 joint equations, + 1 driver.
  const Case input = read_case_file(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml");
  ASSERT_TRUE(input.mechanism.has_value());
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  EXPECT_EQ(model.nv, 18);
  EXPECT_EQ(model.num_equations(), 21);
  // Rod mass rho A L = 7820 * 0.01 * 0.02 * 1.
  EXPECT_NEAR(model.bodies[model.find_body("rod")].mass, 7820 * 0.01 * 0.02, 1e-12);
  // 20 rev/s at R1.
  EXPECT_NEAR(model.drivers[0].motion.evaluate(1.0).first, 2 * std::numbers::pi * 20, 1e-12);
}

}  // namespace
}  // namespace limber::io
