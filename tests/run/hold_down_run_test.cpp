// Hold-downs (joint `release`) and the static start (run.start: statics) through the run
// driver: a bar hinged to ground and held at its tip, released mid-run under gravity and at
// t = 0 from a preloaded spring, against closed forms and an independent integration; and
// the case-file errors of a release.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "falling_bar.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/redundancy.h"
#include "multibody/released_joints.h"
#include "multibody/state.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

constexpr double kLength = 1.0, kMass = 2.0, kGravity = 9.81;

// A uniform bar along x from a hinge at the origin (axis y: a positive angle turns x towards
// −z), held at its tip by a spherical hold-down (`hold_down`: its extra keys), with gravity
// g along −z, the sections `more` and the run settings `run`.
std::string bar_case(double g, const std::string& hold_down, const std::string& more, const std::string& run) {
  return "title: hinged bar held at its tip\n"
         "gravity: [0, 0, " + std::to_string(-g) + "]\n"
         "bodies:\n"
         "  bar: {mass: 2.0, inertia: [1.0e-6, 0.16666666666666666, 0.16666666666666666],\n"
         "        center_of_mass: [0.5, 0, 0], position: [0, 0, 0]}\n"
         "joints:\n"
         "  R: {type: revolute, body_i: ground, body_j: bar, position: [0, 0, 0],\n"
         "      orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}\n"
         "  HD: {type: spherical, body_i: ground, body_j: bar, position: [1, 0, 0]" + hold_down + "}\n" +
         more + "run: {" + run + "}\n";
}

struct Recorded {
  RunSummary summary;
  std::vector<double> time, angle, hold_down_z;
};

Recorded run_text(const std::string& name, const std::string& text) {
  const std::string path = test::write_case(name, text);
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  const int bar = model.find_body("bar"), hold_down = model.find_joint("HD");
  Recorded out;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    // The bar's angle about y from its x axis in ground: atan2(−x_z, x_x).
    const Eigen::Vector4d p = sample.q.segment<4>(model.bodies[bar].q_offset + 3);
    const Eigen::Quaterniond rotation(p(0), p(1), p(2), p(3));
    const Eigen::Vector3d x = rotation.toRotationMatrix().col(0);
    out.time.push_back(sample.t);
    out.angle.push_back(std::atan2(-x.z(), x.x()));
    out.hold_down_z.push_back(record.joints[static_cast<std::size_t>(hold_down)].force_ground.z());
  };
  out.summary = run_mechanism(model, built.assembly, built.run, hooks);
  return out;
}

// The bar's fall from rest (falling_bar.h), the second method.
double falling_bar_angle(double duration) { return test::falling_bar_angle(duration, kLength, kGravity); }

// Held for 0.1 s, then let fall: still and carrying half the weight at the tip until the
// release, free after it, and falling as the bar alone from there.
TEST(HoldDown, ReleasedMidRunTheBarFallsAsTheClosedFormSays) {
  const double release = 0.1, t_end = 0.4;
  for (const std::string run : {"integrator: ida, rtol: 1.0e-9, atol: 1.0e-11, t_end: 0.4, sample_interval: 0.01",
                                "integrator: galpha, step: 1.0e-4, t_end: 0.4, sample_interval: 0.01"}) {
    SCOPED_TRACE(run);
    const Recorded r = run_text("hold_down_mid_run", bar_case(kGravity, ", release: 0.1", "", run));
    ASSERT_TRUE(r.summary.ok) << r.summary.message;
    ASSERT_EQ(r.summary.releases.size(), 1u);
    EXPECT_DOUBLE_EQ(r.summary.releases[0].t, release);
    EXPECT_EQ(r.summary.releases[0].joints, std::vector<std::string>{"HD"});
    for (std::size_t k = 0; k < r.time.size(); ++k) {
      if (r.time[k] <= release + 1e-12) {
        // Moment balance about the hinge: the tip carries m g / 2 (determinate: no other row
        // has a moment about the hinge axis). Rounding and the integrator's drift: 1e-6.
        EXPECT_NEAR(r.angle[k], 0.0, 1e-8) << "t = " << r.time[k];
        EXPECT_NEAR(r.hold_down_z[k], 0.5 * kMass * kGravity, 1e-6) << "t = " << r.time[k];
      } else {
        EXPECT_EQ(r.hold_down_z[k], 0.0) << "t = " << r.time[k];
      }
    }
    // IDA at rtol 1e-9 and generalized-α's O(h²) at 1e-4 s: both within 1e-5 rad of the RK4
    // angle of 0.53 rad after 0.3 s of fall.
    EXPECT_NEAR(r.angle.back(), falling_bar_angle(t_end - release), 1e-5);
  }
}

// A spring on the hinge preloaded to τ0 = k θf at θ = 0, held shut by the hold-down: the
// static start holds the bar still with τ0 / L at the tip (t = 0 sample), and released at
// t = 0 it swings as θ = θf (1 − cos ω t), ω² = k / I (no gravity, no damping).
TEST(HoldDown, StaticStartThenReleaseAtZeroFollowsTheSpringClosedForm) {
  const double k = 4.0, free_angle = 0.5, inertia = kMass * kLength * kLength / 3.0;
  const std::string spring =
      "forces:\n  spring: {type: rsda, marker_i: R.i, marker_j: R.j, stiffness: 4.0, free_angle: 0.5}\n";
  const Recorded r = run_text(
      "hold_down_static_start",
      bar_case(0.0, ", release: 0.0", spring,
               "integrator: ida, rtol: 1.0e-9, atol: 1.0e-11, t_end: 0.5, sample_interval: 0.01, start: statics"));
  ASSERT_TRUE(r.summary.ok) << r.summary.message;
  ASSERT_TRUE(r.summary.statics.has_value());
  EXPECT_EQ(r.summary.statics->status, multibody::StaticsStatus::kOk);
  // The spring turns the bar towards −z; the hold-down pulls its tip up with τ0 / L.
  EXPECT_NEAR(r.hold_down_z.front(), k * free_angle / kLength, 1e-9);
  EXPECT_EQ(r.hold_down_z[1], 0.0);
  const double omega = std::sqrt(k / inertia);
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    // IDA at rtol 1e-9 on an angle of order 1: 1e-6 rad.
    EXPECT_NEAR(r.angle[i], free_angle * (1.0 - std::cos(omega * r.time[i])), 1e-6) << "t = " << r.time[i];
  }
}

// θ of the preloaded, held bar released at t = 0 over d (fading_loads.h): the hold-down's
// reaction, τ0 / L at the tip, frozen in the bar's axes, keeps a moment s(t) τ0 about the hinge,
// s = 1 − t / d, so I θ̈ = −k (θ − θf) − s(t) k θf from rest at θ = 0. With φ = θ − θf and
// ω² = k / I: for t ≤ d, θ = (θf / d) (t − sin(ω t) / ω); after d, the free oscillation about θf
// from θ(d) and θ̇(d) = (θf / d) (1 − cos ω d).
double fading_release_angle(double t, double k, double free_angle, double inertia, double d) {
  const double omega = std::sqrt(k / inertia);
  if (t <= d) return free_angle / d * (t - std::sin(omega * t) / omega);
  const double offset = -free_angle * std::sin(omega * d) / (omega * d);
  const double rate = free_angle / d * (1.0 - std::cos(omega * d));
  return free_angle + offset * std::cos(omega * (t - d)) + rate / omega * std::sin(omega * (t - d));
}

// A release that takes 0.2 s (`release_duration`): the hinge's motion during the ramp and
// after it against the closed form above, the hold-down's recorded reaction τ0 / L up to the
// release and zero after (the fading load is an applied load, not a reaction), and the energy
// balance closed with the fading load's work in force_work (the run is accurate).
TEST(HoldDown, ReleaseOverADurationFollowsTheRampedTorqueClosedForm) {
  const double k = 4.0, free_angle = 0.5, inertia = kMass * kLength * kLength / 3.0, duration = 0.2;
  const std::string spring =
      "forces:\n  spring: {type: rsda, marker_i: R.i, marker_j: R.j, stiffness: 4.0, free_angle: 0.5}\n";
  struct Variant {
    std::string run;
    double tolerance;  // [rad]
  };
  // IDA at rtol 1e-9 on an angle of order 1: 1e-6 rad (as the instant release above; measured
  // 1.0e-8 rad); generalized-α's O(h²) at 1e-4 s over 1 s with the ramp's kink at t = d,
  // measured 6.2e-9 rad: 1e-6 rad too. An instant release differs by 0.02 rad at t = d.
  for (const Variant& variant :
       {Variant{"integrator: ida, rtol: 1.0e-9, atol: 1.0e-11, t_end: 1.0, sample_interval: 0.01, start: statics", 1e-6},
        Variant{"integrator: galpha, step: 1.0e-4, t_end: 1.0, sample_interval: 0.01, start: statics", 1e-6}}) {
    SCOPED_TRACE(variant.run);
    const Recorded r = run_text("hold_down_duration",
                                bar_case(0.0, ", release: 0.0, release_duration: 0.2", spring, variant.run));
    ASSERT_TRUE(r.summary.ok) << r.summary.message;
    EXPECT_TRUE(r.summary.accurate()) << r.summary.accuracy.warnings.front();
    EXPECT_NEAR(r.hold_down_z.front(), k * free_angle / kLength, 1e-9);
    double largest_during_ramp = 0.0;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      if (i > 0) EXPECT_EQ(r.hold_down_z[i], 0.0) << "t = " << r.time[i];
      const double expected = fading_release_angle(r.time[i], k, free_angle, inertia, duration);
      EXPECT_NEAR(r.angle[i], expected, variant.tolerance) << "t = " << r.time[i];
      if (r.time[i] <= duration) largest_during_ramp = std::max(largest_during_ramp, std::abs(expected));
    }
    // The ramp's own motion is not negligible next to the tolerance: 0.0198 rad by t = d.
    EXPECT_GT(largest_during_ramp, 0.019);
  }
}

// A released hold-down leaves the evaluation (multibody/released_joints.h): its rows and markers
// are not written, while every other row and marker is the full evaluation's, to the bit (the
// same arithmetic); and the powers of the energy integrals without the bodies' forces
// (power_terms) are those of the full force pass, to the bit.
TEST(HoldDown, ReleasedJointsLeaveTheEvaluation) {
  const std::string spring = "forces:\n  spring: {type: rsda, marker_i: R.i, marker_j: R.j, stiffness: 4.0, "
                             "free_angle: 0.5, damping: 0.3}\n";
  const std::string path =
      test::write_case("hold_down_evaluation", bar_case(kGravity, ", release: 0.0", spring, "t_end: 0.1"));
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  const multibody::Joint& hold_down = model.joints[static_cast<std::size_t>(model.find_joint("HD"))];
  // A state off the assembly, moving: the rows and the marker kinematics are not trivial.
  multibody::State state = multibody::initial_state(model);
  const multibody::Body& bar = model.bodies[static_cast<std::size_t>(model.find_body("bar"))];
  state.q.segment<4>(bar.q_offset + 3) = Eigen::Vector4d(0.98, 0.05, 0.17, -0.02).normalized();
  state.v.segment<6>(bar.v_offset) << 0.1, -0.2, 0.3, 0.4, -1.5, 0.2;
  multibody::Workspace full(model), left_out(model);
  const multibody::ReleasedJoints released = multibody::released_joints(model, multibody::rows_released_by(model, 0.0));
  multibody::evaluate_constraints(model, state, multibody::Stage::kVelocity, full);
  multibody::evaluate_constraints(model, state, multibody::Stage::kVelocity, released, left_out);
  for (int row = 0; row < model.num_equations(); ++row) {
    const bool released_row = row >= hold_down.first_row && row < hold_down.first_row + hold_down.rows;
    // Released rows: not written (zero, as the fresh workspace holds them).
    EXPECT_EQ(left_out.g(row), released_row ? 0.0 : full.g(row)) << model.equations[row].name;
    EXPECT_EQ(left_out.gamma(row), released_row ? 0.0 : full.gamma(row)) << model.equations[row].name;
    EXPECT_TRUE(released_row ? left_out.G.row(row).isZero(0.0) : left_out.G.row(row) == full.G.row(row))
        << model.equations[row].name;
  }
  // The hold-down's markers keep their unevaluated values (zero: a fresh workspace), the
  // hinge's are evaluated.
  for (const int marker : {hold_down.marker_i, hold_down.marker_j}) {
    EXPECT_EQ(left_out.markers[static_cast<std::size_t>(marker)].p_W, Eigen::Vector3d::Zero());
  }
  EXPECT_NE(full.markers[static_cast<std::size_t>(hold_down.marker_j)].p_W, Eigen::Vector3d::Zero());
  const multibody::Joint& hinge = model.joints[static_cast<std::size_t>(model.find_joint("R"))];
  EXPECT_EQ(left_out.markers[static_cast<std::size_t>(hinge.marker_j)].p_W,
            full.markers[static_cast<std::size_t>(hinge.marker_j)].p_W);

  multibody::PowerTerms powers;
  multibody::generalized_forces(model, state, full, &powers);
  const multibody::PowerTerms reduced = multibody::power_terms(model, state, released, left_out);
  EXPECT_GT(powers.dissipation, 0.0);  // the damper turns: the comparison is not of zeros
  EXPECT_EQ(reduced.dissipation, powers.dissipation);
  EXPECT_EQ(reduced.actuators, powers.actuators);
  EXPECT_EQ(reduced.loads, powers.loads);
  EXPECT_EQ(reduced.geometric, powers.geometric);
}

// A release time that is negative (at its key, line 9), and a driver on a released joint:
// input errors.
TEST(HoldDown, BadReleasesAreLocatedErrors) {
  const auto message_of = [](const std::string& name, const std::string& text) {
    const std::string path = test::write_case(name, text);
    try {
      const io::Case input = io::read_case_file(path);
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string negative = message_of("release_negative", bar_case(kGravity, ", release: -1", "", "t_end: 0.1"));
  EXPECT_NE(negative.find(":9:"), std::string::npos) << negative;
  EXPECT_NE(negative.find("release"), std::string::npos) << negative;
  const std::string driven = message_of(
      "release_driven",
      bar_case(kGravity, ", release: 0.2",
               "drivers:\n  D: {joint: HD, motion: {type: constant_speed, initial: 0, speed: 1}}\n", "t_end: 0.1"));
  EXPECT_NE(driven.find("expected a joint that is not released, got \"HD\""), std::string::npos) << driven;
  // A release_duration without a release, or negative: at its key, on HD's line 9.
  const std::string alone = message_of("release_duration_alone", bar_case(kGravity, ", release_duration: 0.1", "", "t_end: 0.1"));
  EXPECT_NE(alone.find(":9:"), std::string::npos) << alone;
  EXPECT_NE(alone.find("expected a 'release' with 'release_duration', got none"), std::string::npos) << alone;
  const std::string negative_duration =
      message_of("release_duration_negative", bar_case(kGravity, ", release: 0.1, release_duration: -1", "", "t_end: 0.1"));
  EXPECT_NE(negative_duration.find(":9:"), std::string::npos) << negative_duration;
}

}  // namespace
}  // namespace limber::run
