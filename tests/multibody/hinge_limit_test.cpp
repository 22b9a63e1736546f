// Hinge latches and stops (multibody/hinge_limit.h) through both integrators, against closed
// forms: a disk on a revolute about ground z (no gravity, inertia J about the axis).
//  - Latch: a constant torque τ turns the disk from rest, θ = τ t²/(2J), so the latch at θ_L
//    engages at t_L = sqrt(2 J θ_L / τ); locked, the disk is a damped oscillator about
//    θ_L + τ/k_L, whose response from (θ_L, τ t_L / J) is known in closed form.
//  - Stop: the disk turns freely at ω0 into a stop at θ_s with an undamped contact spring k:
//    contact begins at θ_s/ω0, lasts half a period π sqrt(J/k), and the disk leaves at −ω0.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.h"
#include "integrate/simulate.h"
#include "multibody/assembly.h"
#include "multibody/dynamics.h"
#include "multibody/multibody_system.h"
#include "multibody/redundancy.h"
#include "test_models.h"

namespace limber::multibody {
namespace {

using testing::body_spec;

constexpr double kJ = 0.5;       // disk inertia about the hinge axis [kg m²]
constexpr double kTorque = 2.0;  // driving torque [N m]

// The disk on revolute "R" about ground z at the origin, axes x from x_i towards y_i.
ModelBuilder disk_on_hinge(double initial_rate = 0.0, double torque = 0.0) {
  ModelBuilder builder;
  RigidBodySpec disk = body_spec("disk", 2.0, Eigen::Vector3d(0.25, 0.25, kJ), Eigen::Vector3d::Zero());
  disk.initial_angular_velocity_B = Eigen::Vector3d(0, 0, initial_rate);
  builder.add_rigid_body(disk);
  builder.add_marker("R.i", "ground", Eigen::Vector3d::Zero());
  builder.add_marker("R.j", "disk", Eigen::Vector3d::Zero());
  builder.add_joint("R", JointType::kRevolute, "R.i", "R.j");
  if (torque != 0.0) {
    RsdaSpec drive;
    drive.name = "drive";
    drive.marker_i = "R.i";
    drive.marker_j = "R.j";
    drive.actuator = TimeFunction::constant(torque);
    builder.add_rsda(drive);
  }
  return builder;
}

// Events and the disk's angle θ (unwrapped: |θ| < π here) at every sample of a run.
struct HingeRun {
  std::vector<HingeEvent> events;
  std::vector<double> t, theta, rate;
  bool ok = false;
};

HingeRun run(const Model& model, const integrate::IntegratorOptions& options, double t_end, double dt) {
  Workspace ws(model);
  State start = initial_state(model);
  LIMBER_DEMAND(assemble_positions(model, start, ws, {1e-12, 50, {}}).status == AssemblyStatus::kOk);
  assemble_velocities(model, start, ws);
  MultibodySystem system(model, analyse_redundancy(model, start, ws));
  HingeRun out;
  const int b = model.find_body("disk");
  const auto result = integrate::simulate(
      system, options, {0.0, start.q, start.v}, integrate::uniform_sample_times(0.0, t_end, dt),
      [&](const integrate::Sample& s) {
        const Eigen::Vector4d p = s.q.segment<4>(model.bodies[b].q_offset + 3);
        out.t.push_back(s.t);
        out.theta.push_back(2.0 * std::atan2(p(3), p(0)));  // rotation about z
        out.rate.push_back(s.v(model.bodies[b].v_offset + 5));
      });
  out.ok = result.status.ok();
  out.events = system.events();
  return out;
}

struct LatchCase {
  double angle = 1.0;      // θ_L [rad]
  double stiffness = 1e3;  // k_L [N m/rad]
  double damping = 0.2 * 2.0 * std::sqrt(1e3 * kJ);  // 20 % of critical [N m s/rad]
};

Model latch_model(const LatchCase& c) {
  ModelBuilder builder = disk_on_hinge(0.0, kTorque);
  builder.add_hinge_limit({"latch", "R", HingeLimitKind::kLatch, c.angle, c.stiffness, c.damping});
  return builder.build();
}

// Closed-form θ(t) of the latch case, before and after engagement.
double latch_theta(const LatchCase& c, double t) {
  const double t_latch = std::sqrt(2.0 * kJ * c.angle / kTorque);
  if (t <= t_latch) return 0.5 * kTorque / kJ * t * t;
  const double omega = std::sqrt(c.stiffness / kJ);
  const double zeta = c.damping / (2.0 * std::sqrt(c.stiffness * kJ));
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  // x = θ − θ_eq from x0 = −τ/k, ẋ0 = τ t_L / J.
  const double x0 = -kTorque / c.stiffness, v0 = kTorque * t_latch / kJ;
  const double s = t - t_latch;
  const double decay = std::exp(-zeta * omega * s);
  const double x = decay * (x0 * std::cos(omega_d * s) + (v0 + zeta * omega * x0) / omega_d * std::sin(omega_d * s));
  return c.angle + kTorque / c.stiffness + x;
}

void expect_latch_run(const HingeRun& r, const LatchCase& c, double time_tolerance, double angle_tolerance) {
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.events.size(), 1u);
  const double t_latch = std::sqrt(2.0 * kJ * c.angle / kTorque);
  EXPECT_NEAR(r.events[0].t, t_latch, time_tolerance);
  EXPECT_TRUE(r.events[0].engaged);
  EXPECT_NEAR(r.events[0].angle, c.angle, kTorque * t_latch / kJ * time_tolerance + 1e-12);
  double worst = 0.0;
  for (size_t k = 0; k < r.t.size(); ++k) worst = std::max(worst, std::abs(r.theta[k] - latch_theta(c, r.t[k])));
  EXPECT_LT(worst, angle_tolerance);
  // Locked: held at θ_L + τ/k_L once the ringing has decayed (e^{−ζω·1.3 s} ~ 1e-5).
  EXPECT_NEAR(r.theta.back(), c.angle + kTorque / c.stiffness, 1e-5);
}

TEST(HingeLatch, GeneralizedAlphaLocatesTheEngagementAndFollowsTheClosedForm) {
  const LatchCase c;
  auto options = integrate::IntegratorOptions::generalized_alpha(1e-4, 0.9);
  const HingeRun r = run(latch_model(c), options, 2.0, 1e-3);
  // Constant acceleration before the latch is integrated exactly by the Newmark formulas, so
  // the engagement time is off by the event tolerance (1e-9 s) and Newton's 1e-8 tolerance.
  // After it, the oscillation at ω = 44.7 rad/s (amplitude 0.063 rad) has the second-order
  // phase error (ωh)²/12 ≈ 2e-6 per radian: ~1e-4 of the amplitude over its 9 periods.
  expect_latch_run(r, c, 1e-8, 2e-5);
}

TEST(HingeLatch, IdaLocatesTheEngagementAndFollowsTheClosedForm) {
  const LatchCase c;
  const HingeRun r = run(latch_model(c), integrate::IntegratorOptions::ida(1e-9, 1e-11), 2.0, 1e-3);
  // IDA's root finding is exact to round-off; the engagement time carries the solution's
  // local error, rtol 1e-9 on θ ≈ 1 at θ̇ = 2.8 rad/s (global error a few times that).
  expect_latch_run(r, c, 1e-7, 2e-5);
}

TEST(HingeStop, BouncesOffAnElasticStopWithTheClosedFormContactTime) {
  const double omega0 = 2.0, stop_angle = 0.5, k = 2e3;
  ModelBuilder builder = disk_on_hinge(omega0);
  builder.add_hinge_limit({"stop", "R", HingeLimitKind::kStop, stop_angle, k, 0.0});
  const Model model = builder.build();
  const double t_contact = stop_angle / omega0, duration = std::numbers::pi * std::sqrt(kJ / k);
  for (const auto& options : {integrate::IntegratorOptions::generalized_alpha(1e-4, 0.9),
                              integrate::IntegratorOptions::ida(1e-10, 1e-12)}) {
    const HingeRun r = run(model, options, 0.5, 1e-3);
    ASSERT_TRUE(r.ok);
    ASSERT_EQ(r.events.size(), 2u);
    EXPECT_TRUE(r.events[0].engaged);
    EXPECT_FALSE(r.events[1].engaged);
    // Free motion is exact for both (constant velocity); the contact is a half period of
    // ω = 63 rad/s, whose period gen-α at h = 1e-4 lengthens by (ωh)²/12 = 3.3e-6 (measured
    // 3.4e-6; IDA at rtol 1e-10: below 1e-8).
    EXPECT_NEAR(r.events[0].t, t_contact, 1e-7);
    EXPECT_NEAR(r.events[1].t - r.events[0].t, duration, 5e-6 * duration);
    // Elastic: leaves at −ω0 and coasts back; the stop released, no further event.
    EXPECT_NEAR(r.rate.back(), -omega0, 1e-4 * omega0);
    EXPECT_NEAR(r.theta.back(), stop_angle - omega0 * (0.5 - t_contact - duration), 1e-4);
  }
}

TEST(HingeLatch, EnergyStoredInTheLockedLatchIsCounted) {
  // At rest on the latch with a preload: ½ k (θ − θ_L)² in the spring energy.
  const LatchCase c;
  const Model model = latch_model(c);
  Workspace ws(model);
  State state = initial_state(model);
  state.engaged.assign(model.forces.size(), 0);
  state.engaged[1] = 1;
  EXPECT_NEAR(energies(model, state, ws).spring, 0.5 * c.stiffness * c.angle * c.angle, 1e-9);
}

// The damping's ramp over damping_depth d (hinge_limit.h): share s = x² (3 − 2x), x = p / d.
TEST(HingeLimitDamping, RampsFromZeroAtContactToFullAtTheDepthAndStaysFullOnceSeated) {
  HingeLimit latch{"l", HingeLimitKind::kLatch, 0, 0, 1, 1.0, 1.0, 1e3, 10.0, 0.5, 0.01};
  const double rate = 0.3;
  // θ − angle carries the rounding of θ (1e-16), over d and times k: 1e-11 covers it.
  constexpr double kRounding = 1e-11;
  // At contact the damper adds nothing: the torque is continuous with the free hinge's zero.
  EXPECT_EQ(hinge_limit_force(latch, 1.0, rate, kLimitEngaged).torque, 0.0);
  // Half way: s = 1/4 (3 − 1) = 1/2.
  const HingeLimitForce half = hinge_limit_force(latch, 1.005, rate, kLimitEngaged);
  EXPECT_NEAR(half.torque, -1e3 * 0.005 - 0.5 * 10.0 * rate, kRounding);
  EXPECT_NEAR(half.dissipation, 0.5 * 10.0 * rate * rate, kRounding);
  // Past the depth, and seated anywhere (the latch swinging back below its angle), in full.
  EXPECT_NEAR(hinge_limit_force(latch, 1.02, rate, kLimitEngaged).torque, -1e3 * 0.02 - 10.0 * rate, kRounding);
  EXPECT_NEAR(hinge_limit_force(latch, 0.999, rate, kLatchSeated).torque, 1e3 * 0.001 - 10.0 * rate, kRounding);
  // Events: engaged, the seating at p = d; seated, none.
  EXPECT_NEAR(hinge_limit_event(latch, 1.004, kLimitEngaged), 0.004 - 0.01, kRounding);
  EXPECT_LT(hinge_limit_event(latch, 1.5, kLatchSeated), 0.0);
  EXPECT_EQ(hinge_limit_next_mode(latch, kLimitEngaged), kLatchSeated);
  // Without a depth the damping acts in full from contact, and a locked latch never switches.
  latch.damping_depth = 0.0;
  EXPECT_NEAR(hinge_limit_force(latch, 1.0, rate, kLimitEngaged).torque, -10.0 * rate, kRounding);
  EXPECT_LT(hinge_limit_event(latch, 1.5, kLimitEngaged), 0.0);
  // A stop ramps likewise while in contact and toggles.
  HingeLimit stop{"s", HingeLimitKind::kStop, 0, 0, 1, 1.0, 1.0, 1e3, 10.0, 0.5, 0.01};
  EXPECT_NEAR(hinge_limit_force(stop, 1.005, rate, kLimitEngaged).torque, -(1e3 * 0.005 + 0.5 * 10.0 * rate), kRounding);
  EXPECT_EQ(hinge_limit_next_mode(stop, kLimitEngaged), kLimitFree);
}

TEST(HingeLatch, DampingRampSeatsTheLatchSilentlyAndThenDampsInFull) {
  // The latch case with the damping ramped in over d = 0.01 rad: the locked oscillation about
  // θ_eq = θ_L + τ/k (amplitude 0.063 rad) passes p = d within its first quarter period, so
  // the latch is seated early and then rings as the closed-form oscillator with the full
  // damping: successive maxima decay by exp(−2π ζ / sqrt(1 − ζ²)) per period.
  const LatchCase c;
  ModelBuilder builder = disk_on_hinge(0.0, kTorque);
  builder.add_hinge_limit({"latch", "R", HingeLimitKind::kLatch, c.angle, c.stiffness, c.damping, 0.01});
  const Model model = builder.build();
  const double zeta = c.damping / (2.0 * std::sqrt(c.stiffness * kJ));
  const double decrement = std::exp(-2.0 * std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
  for (const auto& options : {integrate::IntegratorOptions::generalized_alpha(1e-4, 0.9),
                              integrate::IntegratorOptions::ida(1e-10, 1e-12)}) {
    const HingeRun r = run(model, options, 2.0, 1e-4);
    ASSERT_TRUE(r.ok);
    // The seating is not a switch a user sees: one event, the engagement.
    ASSERT_EQ(r.events.size(), 1u);
    const double t_latch = std::sqrt(2.0 * kJ * c.angle / kTorque);
    EXPECT_NEAR(r.events[0].t, t_latch, 1e-7);
    // The first two maxima of θ − θ_eq after the engagement (sampled every 0.1 ms: a maximum
    // is read to (ω Δt)² / 8 = 2.5e-6 of itself).
    const double theta_eq = c.angle + kTorque / c.stiffness;
    std::vector<double> maxima;
    for (size_t k = 1; k + 1 < r.t.size() && maxima.size() < 2; ++k) {
      if (r.t[k] <= t_latch) continue;
      if (r.theta[k] > r.theta[k - 1] && r.theta[k] >= r.theta[k + 1]) maxima.push_back(r.theta[k] - theta_eq);
    }
    ASSERT_EQ(maxima.size(), 2u);
    // Gen-α at ωh = 4.5e-3 damps 1e-6 per period numerically; IDA at rtol 1e-10 less.
    EXPECT_NEAR(maxima[1] / maxima[0], decrement, 1e-3 * decrement);
    EXPECT_NEAR(r.theta.back(), theta_eq, 1e-5);
  }
}

TEST(HingeLimitInput, RejectsNonRevoluteJointsAndUnreachableAngles) {
  ModelBuilder builder = disk_on_hinge();
  builder.add_marker("S.i", "ground", Eigen::Vector3d(1, 0, 0));
  builder.add_rigid_body(body_spec("ball", 1.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0, 0)));
  builder.add_marker("S.j", "ball", Eigen::Vector3d::Zero());
  builder.add_joint("S", JointType::kSpherical, "S.i", "S.j");
  EXPECT_THROW(builder.add_hinge_limit({"l1", "S", HingeLimitKind::kLatch, 1.0, 1e3, 0.0}), InputError);
  EXPECT_THROW(builder.add_hinge_limit({"l2", "R", HingeLimitKind::kLatch, 0.0, 1e3, 0.0}), InputError);
  EXPECT_THROW(builder.add_hinge_limit({"l3", "R", HingeLimitKind::kLatch, 7.0, 1e3, 0.0}), InputError);
  EXPECT_THROW(builder.add_hinge_limit({"l4", "R", HingeLimitKind::kStop, 1.0, 0.0, 0.0}), InputError);
  EXPECT_THROW(builder.add_hinge_limit({"l5", "nope", HingeLimitKind::kStop, 1.0, 1.0, 0.0}), InputError);
  EXPECT_THROW(builder.add_hinge_limit({"l6", "R", HingeLimitKind::kStop, 1.0, 1.0, 0.0, -1e-3}), InputError);
  EXPECT_NO_THROW(builder.add_hinge_limit({"ok", "R", HingeLimitKind::kLatch, -6.0, 1e3, 0.0}));
}

}  // namespace
}  // namespace limber::multibody
