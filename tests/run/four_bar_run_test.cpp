// The four-bar with a flexible coupler (cases/four_bar.yaml): the rocker against the rigid
// four-bar's closed-form position analysis (Freudenstein's equation), the coupler's chord and
// deflection, the redundant equations of the all-revolute 3D model with and without an
// out-of-plane mode, and the energy balance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

// Crank a, coupler b, rocker c, ground link d [m] (cases/four_bar.yaml).
constexpr double kA = 0.1, kB = 0.4, kC = 0.3, kD = 0.4;

const std::string kFourBar = std::string(LIMBER_CASES_DIR) + "/four_bar.yaml";

// Angle of a body's x axis in the plane of motion, from ground x towards ground z [rad].
double planar_angle(const Eigen::Quaterniond& q_WB) {
  const Eigen::Vector3d x_W = q_WB * Eigen::Vector3d::UnitX();
  return std::atan2(x_W.z(), x_W.x());
}

// Freudenstein's equation K1 cos t4 − K2 cos t2 + K3 = cos(t2 − t4) solved for the rocker
// angle t4 of the rigid four-bar (Norton, Design of Machinery, §4.5), on the branch nearest to
// `previous` (a crank-rocker never changes branch: the discriminant stays positive).
double freudenstein_rocker_angle(double t2, double previous) {
  const double k1 = kD / kA, k2 = kD / kC, k3 = (kA * kA - kB * kB + kC * kC + kD * kD) / (2 * kA * kC);
  const double a = std::cos(t2) - k1 - k2 * std::cos(t2) + k3;
  const double b = -2 * std::sin(t2);
  const double c = k1 - (k2 + 1) * std::cos(t2) + k3;
  const double root = std::sqrt(b * b - 4 * a * c);
  const double t4_open = 2 * std::atan2(-b + root, 2 * a), t4_crossed = 2 * std::atan2(-b - root, 2 * a);
  // Each root taken within ±π of `previous`.
  const auto near = [&](double t4) { return previous + std::remainder(t4 - previous, 2 * std::numbers::pi); };
  const double open = near(t4_open), crossed = near(t4_crossed);
  return std::abs(open - previous) < std::abs(crossed - previous) ? open : crossed;
}

struct FourBarRun {
  RunSummary summary;
  std::vector<results::Sample> samples;
};

FourBarRun run_four_bar(const std::string& path, double t_end) {
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;  // generalized-α, h = 2e-4 s, as shipped
  settings.t_end = t_end;
  FourBarRun run;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) { run.samples.push_back(record); };
  run.summary = run_mechanism(built.model, built.assembly, settings, hooks);
  return run;
}

// Out-of-plane equations of revolutes about ground y: translation along y (z), tilts (rot_x,
// rot_y).
bool out_of_plane(const std::string& name) {
  const std::string direction = name.substr(name.find('.') + 1);
  return direction == "z" || direction == "rot_x" || direction == "rot_y";
}

TEST(FourBarRun, RockerFollowsFreudensteinWhileTheCouplerBends) {
  // 0.3 s: the 0.1 s spin-up and 1.6 turns at 8 rev/s, 301 samples.
  const FourBarRun run = run_four_bar(kFourBar, 0.3);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.samples.size(), 301u);
  const int crank = 0, coupler = 1, rocker = 2;  // bodies in file order
  const int r2 = 1, r3 = 2;                      // joints in file order: R1, R2, R3, R4

  // Rigid four-bar: t4 from t2. Generalized-α holds the joint and driver equations at its
  // steps to the Newton tolerance, so the crank angle is the driver's and the rocker angle is
  // fixed by the loop closure: no integration error enters. What separates the flexible model
  // from the rigid closed form is the length of the coupler's chord: its bending modes move the
  // end nodes across the chord only, so the chord changes at second order, Δu² / 2b (Δu the
  // ends' relative transverse motion, ~1 mm: ~1e-6 m; measured at most 6.1e-7 m), and the
  // rocker turns by Δb / (c sin μ) with the transmission angle μ ≥ 48.2°: at most 2.7e-6 rad
  // (measured 1.4e-6 rad). Bounds 2e-6 m on the chord and 1e-5 rad on the rocker; a 1 mm error
  // in any link would move the rocker by ~4e-3 rad.
  double t4 = std::numbers::pi - std::acos(1.0 / 9.0);  // B = (11/30, sqrt(80)/30) at t2 = 0
  EXPECT_NEAR(planar_angle(run.samples.front().bodies[rocker].orientation), t4, 1e-12);
  double rocker_error = 0.0, chord_change = 0.0, deflection = 0.0, t4_min = 10.0, t4_max = -10.0;
  for (const results::Sample& sample : run.samples) {
    t4 = freudenstein_rocker_angle(planar_angle(sample.bodies[crank].orientation), t4);
    const double error = std::remainder(planar_angle(sample.bodies[rocker].orientation) - t4, 2 * std::numbers::pi);
    rocker_error = std::max(rocker_error, std::abs(error));
    chord_change = std::max(chord_change, std::abs((sample.joints[r3].position - sample.joints[r2].position).norm() - kB));
    deflection = std::max(deflection, sample.bodies[coupler].deflection.norm());
    t4_min = std::min(t4_min, t4);
    t4_max = std::max(t4_max, t4);
  }
  EXPECT_LT(chord_change, 2e-6);
  EXPECT_LT(rocker_error, 1e-5) << "rocker angle vs Freudenstein's equation";
  // The crank went round: the rocker swept its whole swing, 90° (crank and coupler in line)
  // to 131.8° (folded: |R1 B| = b − a), closed form.
  EXPECT_NEAR(t4_min, std::numbers::pi / 2, 1e-3);
  EXPECT_NEAR(t4_max, std::numbers::pi - std::acos(2.0 / 3.0), 1e-3);
  // The coupler does bend: a quasi-static estimate, its inertia load m/L a ω² (~200 N/m at
  // 8 rev/s) on a simply supported span, 5 q L⁴ / (384 E I) = 1.5 mm; measured peak 1.22 mm.
  // Bounds 0.5 mm to 3 mm: the check above is not against a body that stays straight.
  EXPECT_GT(deflection, 0.5e-3);
  EXPECT_LT(deflection, 3e-3);

  // Energy balance with strain energy and modal damping: generalized-α's quadrature of the
  // driver's power closes it to 4.8e-5 of the peak kinetic energy over 0.6 s (measured,
  // `limber run`); bound 2e-4.
  const auto balance = [](const results::Sample& s) {
    const std::vector<double>& e = s.energies;  // kinetic, gravity, spring, strain, dissipated, driver, force
    return e[0] + e[1] + e[2] + e[3] + e[4] - e[5] - e[6];
  };
  double kinetic = 0.0, drift = 0.0;
  for (const results::Sample& s : run.samples) {
    kinetic = std::max(kinetic, s.energies[0]);
    drift = std::max(drift, std::abs(balance(s) - balance(run.samples.front())));
  }
  EXPECT_GT(kinetic, 1.0);
  EXPECT_LT(drift, 2e-4 * kinetic) << drift << " J of " << kinetic << " J";
}

TEST(FourBarRun, RedundantEquationsOfTheAllRevoluteModel) {
  // Rigid count: 18 velocities, 20 + 1 equations, rank 18: 3 redundant, all out of the plane
  // (12 out-of-plane joint equations against 9 out-of-plane rigid motions). In-plane modes only
  // (normal: 2, 165 and 455 Hz) leave that count as it is.
  const FourBarRun in_plane =
      run_four_bar(test::write_case("four_bar_in_plane", test::edited_case(kFourBar, "normal: 5", "normal: 2")), 0.01);
  ASSERT_TRUE(in_plane.summary.ok) << in_plane.summary.message;
  EXPECT_EQ(in_plane.summary.redundant.size(), 3u);
  for (const RedundantEquationReport& equation : in_plane.summary.redundant) {
    EXPECT_TRUE(out_of_plane(equation.name)) << equation.description;
  }
  // The shipped 5 modes include the out-of-plane bending mode at 657 Hz: the coupler's ends
  // may tilt out of the plane relative to each other, which takes up one of the 3.
  const FourBarRun shipped = run_four_bar(kFourBar, 0.01);
  ASSERT_TRUE(shipped.summary.ok) << shipped.summary.message;
  EXPECT_EQ(shipped.summary.redundant.size(), 2u);
  for (const RedundantEquationReport& equation : shipped.summary.redundant) {
    EXPECT_TRUE(out_of_plane(equation.name)) << equation.description;
  }
  // Every joint is in a dependency group: all reactions are minimum-norm.
  for (const results::JointSample& joint : shipped.samples.back().joints) EXPECT_TRUE(joint.indeterminate);
}

}  // namespace
}  // namespace limber::run
