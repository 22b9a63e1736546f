// The run driver on the seed slider-crank read from its case files: slider motion against the
// closed form and against a non-redundant model of the same mechanism, determinate reactions
// of both models, the energy balance of the results, a joint that does not close, and a run
// stopped by its step budget that keeps its samples on disk.
#include "run/run_driver.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>
#include <vector>

#include "../results/h5_test_read.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

constexpr double kA = 0.05, kB = 1.0;                      // crank, rod [m]
constexpr double kOmega = 2.0 * std::numbers::pi * 20.0;    // 20 rev/s
constexpr double kRampTime = 0.1;                           // quintic spin-up [s]

// Slider x for the crank at angle theta: a cos(theta) + sqrt(b^2 - a^2 sin^2(theta)).
double slider_x_at(double theta) {
  const double s = std::sin(theta);
  return kA * std::cos(theta) + std::sqrt(kB * kB - kA * kA * s * s);
}

// Crank at constant speed from t = 0 (the seed's start, constant_speed_variant below).
double closed_form_slider_x(double t) { return slider_x_at(kOmega * t); }

// The shipped case's crank angle: the integral of the quintic ramp's speed
// omega (10 tau^3 - 15 tau^4 + 6 tau^5), tau = t / T, then constant speed.
double ramp_theta(double t) {
  if (t >= kRampTime) return kOmega * (0.5 * kRampTime + (t - kRampTime));
  const double tau = t / kRampTime;
  return kOmega * kRampTime * std::pow(tau, 4) * (2.5 - 3.0 * tau + tau * tau);
}

// The case at `path` with its quintic spin-up replaced by the seed's start at full speed
// (both slider-crank files carry the same driver line), written under `name`.
std::string constant_speed_variant(const std::string& path, const std::string& name) {
  return test::write_case(
      name, test::edited_case(path,
                              "motion: {type: ramp, initial: 0, speed: 125.66370614359172, duration: 0.1, shape: quintic}",
                              "motion: {type: constant_speed, initial: 0, speed: 125.66370614359172}"));
}

// One run of a case, every sample kept in memory.
struct Recorded {
  RunSummary summary;
  std::vector<double> time, slider_x;
  std::vector<results::Sample> samples;
};

Recorded run_case(const std::string& path, double t_end, double rtol, double atol) {
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.integrator.method = integrate::Method::kIda;
  settings.integrator.rtol = rtol;
  settings.integrator.atol = atol;
  settings.t_end = t_end;
  settings.sample_interval = 5e-4;
  const multibody::Model& model = built.model;
  const int slider = model.find_body("slider");
  Recorded recorded;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    recorded.time.push_back(sample.t);
    recorded.slider_x.push_back(sample.q(model.bodies[slider].q_offset));
    recorded.samples.push_back(record);
  };
  recorded.summary = run_mechanism(model, built.assembly, settings, hooks);
  return recorded;
}

TEST(RunDriver, SliderCrankMatchesClosedFormAndNonRedundantModel) {
  // The shipped case and its non-redundant twin started at full speed (the seed's start, an
  // impulsive load that the spin-up of the shipped case avoids), where the slider has the
  // closed form of a constant-speed crank. Two crank turns (0.1 s) at rtol 1e-8: IDA holds
  // g = 0 to its Newton tolerance and its global error is ~10 rtol · a ~ 5e-9 m; samples are
  // IDA's interpolants, which leave the manifold by a fraction of the local error. Measured:
  // 2.9e-10 m against the closed form, 1.9e-11 m between the models (rtol 1e-6: 5.3e-8 m).
  // Bound 1e-8 m on both, so that the check is sensitive (rtol 1e-6 fails it).
  const Recorded redundant = run_case(
      constant_speed_variant(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml", "rigid_constant_speed"),
      0.1, 1e-8, 1e-10);
  const Recorded plain = run_case(
      constant_speed_variant(std::string(LIMBER_TEST_DATA_DIR) + "/slider_crank_universal.yaml",
                             "universal_constant_speed"),
      0.1, 1e-8, 1e-10);
  ASSERT_TRUE(redundant.summary.ok) << redundant.summary.message;
  ASSERT_TRUE(plain.summary.ok) << plain.summary.message;
  EXPECT_EQ(redundant.summary.redundant.size(), 3u);
  EXPECT_TRUE(plain.summary.redundant.empty());
  ASSERT_EQ(redundant.time.size(), 201u);
  ASSERT_EQ(plain.time.size(), 201u);

  double x_error = 0.0, x_difference = 0.0;
  for (std::size_t k = 0; k < redundant.time.size(); ++k) {
    x_error = std::max(x_error, std::abs(redundant.slider_x[k] - closed_form_slider_x(redundant.time[k])));
    x_error = std::max(x_error, std::abs(plain.slider_x[k] - closed_form_slider_x(plain.time[k])));
    x_difference = std::max(x_difference, std::abs(redundant.slider_x[k] - plain.slider_x[k]));
  }
  EXPECT_LT(x_error, 1e-8) << "slider x vs a cos wt + sqrt(b^2 - a^2 sin^2 wt)";
  EXPECT_LT(x_difference, 1e-8) << "redundant vs non-redundant model";

  // Determinate reactions agree: the in-plane (x, z) force at R3 on the slider, in ground axes,
  // and the driver torque. Both come from v̇ interpolated by IDA (error ~ rtol-scaled on
  // accelerations of ~800 m/s²): bound 1e-4 of the largest value (~830 N, ~42 N m; measured
  // differences 1.1e-4 N and 1.3e-5 N m, i.e. 1.4e-7 and 3.2e-7 of them).
  const int r3 = 2;  // joints in file order: R1, R2, R3, T
  double force_scale = 0.0, force_difference = 0.0, torque_scale = 0.0, torque_difference = 0.0;
  for (std::size_t k = 0; k < redundant.samples.size(); ++k) {
    const results::JointSample& a = redundant.samples[k].joints[r3];
    const results::JointSample& b = plain.samples[k].joints[r3];
    for (int axis : {0, 2}) {
      force_scale = std::max(force_scale, std::abs(b.force_ground(axis)));
      force_difference = std::max(force_difference, std::abs(a.force_ground(axis) - b.force_ground(axis)));
    }
    torque_scale = std::max(torque_scale, std::abs(plain.samples[k].driver_efforts[0]));
    torque_difference = std::max(torque_difference, std::abs(redundant.samples[k].driver_efforts[0] -
                                                             plain.samples[k].driver_efforts[0]));
    // Redundancy flags: every joint of the redundant model is in a dependency group.
    for (const results::JointSample& joint : redundant.samples[k].joints) EXPECT_TRUE(joint.indeterminate);
    for (const results::JointSample& joint : plain.samples[k].joints) EXPECT_FALSE(joint.indeterminate);
  }
  // The largest in-plane force is the slider's inertia at theta = 0 (t = 0, 0.05, 0.1 s, all
  // samples): T carries no x force and gravity is along z, so F_x = m ẍ = −m a ω² (1 + a/b)
  // = −829.05 N exactly for the 1 kg slider; |F_z| stays below it (tan of the rod angle times
  // the rod force, plus m g). Within 1e-4, the accuracy of the reactions above.
  const double slider_inertia_load = 1.0 * kA * kOmega * kOmega * (1.0 + kA / kB);
  EXPECT_NEAR(force_scale, slider_inertia_load, 1e-4 * slider_inertia_load);
  EXPECT_LT(force_difference, 1e-4 * force_scale);
  EXPECT_LT(torque_difference, 1e-4 * torque_scale);
}

TEST(RunDriver, ShippedCaseFollowsTheClosedFormThroughItsSpinUp) {
  // The case as shipped: quintic spin-up over 0.1 s, then 20 rev/s, 0.2 s. The slider x is the
  // closed form of the crank angle, whatever theta(t) is; theta(t) is the ramp's integral
  // (ramp_theta). Measured at rtol 1e-8: 3.3e-10 m (rtol 1e-6: 4.3e-8 m); bound 1e-8 m, which
  // rtol 1e-6 would fail.
  const Recorded run = run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml", 0.2, 1e-8, 1e-10);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.time.size(), 401u);
  double x_error = 0.0;
  for (std::size_t k = 0; k < run.time.size(); ++k) {
    x_error = std::max(x_error, std::abs(run.slider_x[k] - slider_x_at(ramp_theta(run.time[k]))));
  }
  EXPECT_LT(x_error, 1e-8) << "slider x vs a cos theta + sqrt(b^2 - a^2 sin^2 theta), theta of the ramp";
  // Half-way through the spin-up (t = 0.05 s, sample 100) the crank is at
  // omega T (1/2)^4 (2.5 - 3/2 + 1/4) = omega T / 12.8 = 0.98175 rad, where a crank at constant
  // speed would be back at 0 after a whole turn.
  EXPECT_NEAR(run.slider_x[100], slider_x_at(0.98174770424681), 1e-8);
}

TEST(RunDriver, EnergyBalanceOfTheResults) {
  // T + V_gravity + V_spring + dissipated − driver_work − force_work is constant: the driver's
  // work is the only energy input. The work integral is IDA's quadrature, error-controlled
  // with atol = rtol · (energy at the start): at rtol 1e-8 the balance holds to 2.6e-7 of the
  // largest kinetic energy (~51 J at the end of the 0.1 s spin-up; measured); bound 1e-5.
  const Recorded run = run_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml", 0.1, 1e-8, 1e-10);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto balance = [](const results::Sample& s) {
    // kinetic, gravity, spring, strain, dissipated, driver, force (run/sample_record.h)
    const std::vector<double>& e = s.energies;
    return e[0] + e[1] + e[2] + e[3] + e[4] - e[5] - e[6];
  };
  double kinetic = 0.0, drift = 0.0, work = 0.0;
  for (const results::Sample& s : run.samples) {
    kinetic = std::max(kinetic, s.energies[0]);
    drift = std::max(drift, std::abs(balance(s) - balance(run.samples.front())));
    work = std::max(work, std::abs(s.energies[5]));
  }
  EXPECT_GT(kinetic, 10.0);
  EXPECT_GT(work, 1.0);  // the driver does work: the balance is not trivially zero
  EXPECT_LT(drift, 1e-5 * kinetic) << drift << " J of " << kinetic << " J";
}

TEST(RunDriver, JointThatDoesNotCloseIsNamedWithItsResidual) {
  // The translational joint's rail 2 m above the slider line: the crank and rod reach at most
  // 1.05 m, so assembly cannot close T; the message names an equation of T and its residual.
  const std::string path = test::write_case(
      "open_loop", test::edited_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml",
                                     R"(  T:  {type: translational, body_i: ground, body_j: slider, position: [1.05, 0, 0],
       orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}})",
                                     R"(  T:  {type: translational, marker_i: rail, marker_j: shoe}
markers:
  rail: {body: ground, position: [0, 0, 2], orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}}
  shoe: {body: slider, orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}})"));
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const auto dir = test::fresh_directory("open_loop");
  results::ResultsWriter writer(dir, input.title, input.file);
  RunHooks hooks;
  hooks.writer = &writer;
  const RunSummary summary = run_mechanism(built.model, built.assembly,
                                           built.run, hooks);
  EXPECT_FALSE(summary.ok);
  EXPECT_EQ(summary.failure, "assembly");
  // Least-squares assembly spreads the gap over the loop: the worst equation may be any
  // joint's. The loop misses by at least 2 − 1.05 = 0.95 m, shared by at most 4 joints.
  const std::regex form(R"(equation (R1|R2|R3|T)\.\w+ \(joint \1\) does not close, residual (\S+) m)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(summary.message, match, form)) << summary.message;
  EXPECT_GT(std::abs(std::stod(match[2].str())), 0.95 / 4) << summary.message;
  // Where the input is off, before any iteration: the rail (T's marker i) is 2 m above the
  // slider's shoe, and one of T's equations measures that 2 m exactly.
  const std::regex given(R"(as given, the largest gap was equation T\.\w+ \(joint T\), (\S+) m)");
  ASSERT_TRUE(std::regex_search(summary.message, match, given)) << summary.message;
  EXPECT_NEAR(std::abs(std::stod(match[1].str())), 2.0, 1e-9) << summary.message;
  EXPECT_EQ(summary.samples, 0);
  // The file says so.
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(results::testing::read_string_attribute(file, "/", "status"), "failed");
  EXPECT_EQ(results::testing::read_string_attribute(file, "/", "message"), summary.message);
  H5Fclose(file);
}

TEST(RunDriver, StepBudgetStopsTheRunAndKeepsItsSamples) {
  // 50 steps of IDA cover a few ms of the 0.1 s: the run stops with too_many_steps and every
  // sample before is in the file, rows consistent, status "failed".
  const std::string path = test::write_case(
      "budget", test::edited_case(std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml",
                                  "  t_end: 1.0 ", "  max_steps: 50\n  t_end: 0.1 "));
  const io::Case input = io::read_case_file(path);
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const auto dir = test::fresh_directory("budget");
  results::ResultsWriter writer(dir, input.title, input.file);
  RunHooks hooks;
  hooks.writer = &writer;
  const RunSummary summary = run_mechanism(built.model, built.assembly,
                                           built.run, hooks);
  EXPECT_FALSE(summary.ok);
  EXPECT_EQ(summary.failure, "too_many_steps");
  EXPECT_NE(summary.message.find("at t = "), std::string::npos) << summary.message;
  EXPECT_GT(summary.samples, 1);
  EXPECT_LT(summary.t_reached, 0.1);

  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(results::testing::read_string_attribute(file, "/", "status"), "failed");
  EXPECT_EQ(results::testing::read_string_attribute(file, "/", "message"), summary.message);
  const std::vector<double> time = results::testing::read_doubles(file, "/time");
  ASSERT_EQ(static_cast<int>(time.size()), summary.samples);
  EXPECT_DOUBLE_EQ(time.back(), summary.t_reached);
  EXPECT_EQ(results::testing::dataset_dims(file, "/bodies/slider/position"),
            (std::vector<hsize_t>{time.size(), 3}));
  // The samples kept are right: slider x against the closed form of the spin-up (rtol 1e-6 of
  // the case: 4.3e-8 m over 0.2 s, ShippedCaseFollowsTheClosedFormThroughItsSpinUp; bound
  // 1e-6 m).
  const std::vector<double> position = results::testing::read_doubles(file, "/bodies/slider/position");
  for (std::size_t k = 0; k < time.size(); ++k) {
    EXPECT_NEAR(position[3 * k], slider_x_at(ramp_theta(time[k])), 1e-6) << "t = " << time[k];
  }
  H5Fclose(file);
}

}  // namespace
}  // namespace limber::run
