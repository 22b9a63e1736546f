// Stability extremes (issue 14): the shipped slider-cranks pushed to extreme settings. Every
// run must end in one of three ways - accurate (its own check passes) and close to a reference,
// finished but flagged by its own accuracy check (status ok_inaccurate), or failed with a
// message saying where and why, samples kept - and never with a non-finite sample or a hang
// (every run has a wall-clock budget). Measured numbers: docs/extremes.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

const std::string kRigid = std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml";
const std::string kFlexible = std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml";
constexpr double kA = 0.05, kB = 1.0;  // crank, rod [m]
// [s] per run: a hang fails the test instead of CI. A guard, not a speed test: the slowest
// runs take seconds alone and tripped a 20 s budget with other builds loading the machine.
constexpr double kWallBudget = 120.0;
const std::string kRamp =
    "motion: {type: ramp, initial: 0, speed: 125.66370614359172, duration: 0.1, shape: quintic}";

// `text` with every occurrence of `from` replaced by `to` (throws when there is none).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("replaced: '" + from + "' not found");
  while (at != std::string::npos) {
    text.replace(at, from.size(), to);
    at = text.find(from, at + to.size());
  }
  return text;
}

// The crank at constant speed `speed` [rad/s] from t = 0 instead of the spin-up.
std::string at_constant_speed(const std::string& text, double speed) {
  char motion[128];
  std::snprintf(motion, sizeof motion, "motion: {type: constant_speed, initial: 0, speed: %.17g}", speed);
  return replaced(text, kRamp, motion);
}

// The flexible case with its rod meshed by 20 beams (mid-span node 11) and `modes` as its
// `normal:` request.
std::string coarse_flexible(const std::string& modes) {
  std::string text = test::read_text(kFlexible);
  text = replaced(text, "elements: 100", "elements: 20");
  text = replaced(text, "R3: [101]", "R3: [21]");
  text = replaced(text, "node: 51", "node: 11");
  return replaced(text, "      normal: 5\n", "      normal: " + modes + "\n");
}

struct Outcome {
  RunSummary summary;
  std::vector<results::Sample> samples;
  multibody::State start;  // assembled
  int assembly_iterations = 0;
  int slider_q = -1;       // q offset of the slider's origin
  std::vector<double> slider_x;
  std::string label;
};

std::string label_of(const char* what, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%s %g", what, value);
  return text;
}

// Runs `text` with its run settings edited by `edit`; a wall-clock budget on every run.
Outcome run_text(const std::string& text, const std::string& label,
                 const std::function<void(io::RunSettings&)>& edit) {
  const io::Case input = io::read_case_text(text, label + ".yaml");
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  edit(settings);
  settings.integrator.max_wall_seconds = kWallBudget;
  const multibody::Model& model = built.model;
  Outcome outcome;
  outcome.label = label;
  outcome.slider_q = model.bodies[model.find_body("slider")].q_offset;
  RunHooks hooks;
  hooks.on_start = [&](const PreparedStart& start) {
    outcome.start = start.state;
    outcome.assembly_iterations = start.assembly.iterations;
  };
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    outcome.samples.push_back(record);
    outcome.slider_x.push_back(sample.q(outcome.slider_q));
  };
  outcome.summary = run_mechanism(model, built.assembly, settings, hooks);
  const RunSummary& s = outcome.summary;
  std::printf("  %-34s %-13s t %.4g/%.4g s, %d samples, energy %.2e local %.2e drift %.2e, %.2f s%s%s\n",
              label.c_str(), s.ok ? (s.accurate() ? "accurate" : "flagged") : "FAILED", s.t_reached,
              s.t_end, s.samples, s.accuracy.energy_relative, s.accuracy.local_error,
              s.accuracy.drift_relative, s.wall_seconds, s.ok ? "" : (" " + s.message).c_str(),
              s.warnings.empty() ? "" : (" warning: " + s.warnings.front()).c_str());
  return outcome;
}

std::function<void(io::RunSettings&)> galpha(double step, double t_end, double interval = 1e-3) {
  return [=](io::RunSettings& s) {
    s.integrator.method = integrate::Method::kGeneralizedAlpha;
    s.integrator.step = step;
    s.t_end = t_end;
    s.sample_interval = interval;
  };
}

std::function<void(io::RunSettings&)> ida(double rtol, double t_end, double interval = 1e-3) {
  return [=](io::RunSettings& s) {
    s.integrator.method = integrate::Method::kIda;
    s.integrator.rtol = rtol;
    s.integrator.atol = rtol / 100;
    s.t_end = t_end;
    s.sample_interval = interval;
  };
}

bool finite(const Eigen::Ref<const Eigen::VectorXd>& x) { return x.allFinite(); }

// Every value of every sample is finite.
::testing::AssertionResult all_finite(const Outcome& run) {
  for (const results::Sample& s : run.samples) {
    bool ok = std::isfinite(s.position_violation) && std::isfinite(s.velocity_violation);
    for (double e : s.energies) ok = ok && std::isfinite(e);
    for (double e : s.driver_efforts) ok = ok && std::isfinite(e);
    for (const results::BodySample& b : s.bodies) {
      ok = ok && finite(b.position) && finite(b.orientation.coeffs()) && finite(b.deflection) &&
           finite(b.modal_coordinates) && finite(b.modal_velocities);
    }
    for (const results::JointSample& j : s.joints) {
      ok = ok && finite(j.position) && finite(j.force_joint) && finite(j.torque_joint) &&
           finite(j.force_ground) && finite(j.torque_ground);
    }
    if (!ok) return ::testing::AssertionFailure() << run.label << ": non-finite value at t = " << s.time;
  }
  return ::testing::AssertionSuccess();
}

// One of the three allowed endings, no non-finite sample, and a failure that says when and why
// with the samples before it kept.
::testing::AssertionResult well_behaved(const Outcome& run) {
  if (auto finite_result = all_finite(run); !finite_result) return finite_result;
  const RunSummary& s = run.summary;
  if (static_cast<std::size_t>(s.samples) != run.samples.size()) {
    return ::testing::AssertionFailure() << run.label << ": " << s.samples << " samples reported, "
                                         << run.samples.size() << " delivered";
  }
  if (s.ok) {
    if (std::abs(s.t_reached - s.t_end) > 1e-12) {
      return ::testing::AssertionFailure() << run.label << ": ok but stopped at " << s.t_reached;
    }
    return ::testing::AssertionSuccess();
  }
  if (s.message.empty() || s.failure.empty()) {
    return ::testing::AssertionFailure() << run.label << ": failed without a message";
  }
  if (s.failure == "wall_clock") {
    return ::testing::AssertionFailure() << run.label << ": hit the wall-clock budget: " << s.message;
  }
  return ::testing::AssertionSuccess();
}

enum class Ending { kAccurate, kFlagged, kFailed };
Ending ending(const Outcome& run) {
  if (!run.summary.ok) return Ending::kFailed;
  return run.summary.accurate() ? Ending::kAccurate : Ending::kFlagged;
}

// Peak over the common samples of |a - b| (vectors picked by `get`), over the peak of |b|.
double relative_peak_error(const Outcome& run, const Outcome& reference,
                           const std::function<Eigen::Vector3d(const results::Sample&)>& get) {
  double error = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < std::min(run.samples.size(), reference.samples.size()); ++k) {
    error = std::max(error, (get(run.samples[k]) - get(reference.samples[k])).norm());
    scale = std::max(scale, get(reference.samples[k]).norm());
  }
  return error / scale;
}

// R2's reaction on the rod, ground axes (joints in file order R1, R2, R3, T).
Eigen::Vector3d r2_force(const results::Sample& s) { return s.joints[1].force_ground; }
// R3's reaction on the slider, ground axes.
Eigen::Vector3d r3_force(const results::Sample& s) { return s.joints[2].force_ground; }
// The rod's mid-span deflection relative to the chord R2-R3 (bodies crank, rod, slider).
Eigen::Vector3d deflection(const results::Sample& s) { return s.bodies[1].deflection; }

// Slider x for the crank at angle theta, rod b: a cos(theta) + sqrt(b^2 - a^2 sin^2(theta)).
double slider_x_at(double theta, double b = kB) {
  const double s = std::sin(theta);
  return kA * std::cos(theta) + std::sqrt(b * b - kA * kA * s * s);
}
// Its second derivative in theta: -a cos - a^2 cos 2theta / S - a^4 sin^2 cos^2 / S^3.
double slider_x_second_derivative(double theta, double b = kB) {
  const double s = std::sin(theta), c = std::cos(theta);
  const double root = std::sqrt(b * b - kA * kA * s * s);
  return -kA * c - kA * kA * std::cos(2 * theta) / root -
         std::pow(kA, 4) * s * s * c * c / std::pow(root, 3);
}

double max_slider_error(const Outcome& run, double speed, double b = kB) {
  double error = 0.0;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    error = std::max(error, std::abs(run.slider_x[k] - slider_x_at(speed * run.samples[k].time, b)));
  }
  return error;
}


// R3's x force against the slider's inertia m ω² x''(ωt) (constant speed): the largest
// difference over the peak, and the peak [N].
std::pair<double, double> r3_inertia_error(const Outcome& run, double mass, double omega) {
  double force_error = 0.0, force_scale = 0.0;
  for (const results::Sample& s : run.samples) {
    const double expected = mass * omega * omega * slider_x_second_derivative(omega * s.time);
    force_error = std::max(force_error, std::abs(r3_force(s).x() - expected));
    force_scale = std::max(force_scale, std::abs(expected));
  }
  return {force_error / force_scale, force_scale};
}

// 1. Step and tolerance sweeps: whatever a run reports as accurate is close to the reference.
struct SweepResult {
  std::string label;
  Ending end;
  double r2_error = 0.0, deflection_error = 0.0;
};

std::vector<SweepResult> sweep(const std::string& text, const Outcome& reference, bool flexible,
                               const std::vector<double>& steps, const std::vector<double>& rtols,
                               double t_end) {
  std::vector<SweepResult> results;
  const auto record = [&](const Outcome& run) {
    EXPECT_TRUE(well_behaved(run));
    SweepResult r{run.label, ending(run)};
    r.r2_error = relative_peak_error(run, reference, r2_force);
    if (flexible) r.deflection_error = relative_peak_error(run, reference, deflection);
    std::printf("    -> R2 error %.3e, deflection error %.3e\n", r.r2_error, r.deflection_error);
    results.push_back(r);
  };
  for (double h : steps) record(run_text(text, label_of("galpha h", h), galpha(h, t_end)));
  for (double rtol : rtols) record(run_text(text, label_of("ida rtol", rtol), ida(rtol, t_end)));
  return results;
}

TEST(Extremes, RigidSliderCrankStepAndToleranceSweep) {
  const std::string text = test::read_text(kRigid);
  // The shipped spin-up, 0.2 s (the ramp and one turn). Reference: IDA at rtol 1e-10, whose
  // R2 differs from the rtol 1e-9 run by 8.9e-8 of its peak (measured): far below the bound.
  const Outcome reference = run_text(text, "reference ida 1e-10", ida(1e-10, 0.2));
  ASSERT_TRUE(reference.summary.accurate()) << reference.summary.message;
  const std::vector<SweepResult> results =
      sweep(text, reference, false, {2e-2, 5e-3, 2e-3, 1e-3, 2e-4, 5e-5, 2e-5}, {1e-2, 1e-3, 1e-4, 1e-5, 1e-7, 1e-9}, 0.2);
  // Measured: every run reported accurate has its R2 peak error at most 6.2e-3 (IDA rtol 1e-4,
  // energy measure 4.2e-3; gen-α h = 1 ms 3.0e-3); every flagged run is off by 1.2e-2 or more
  // (h = 2 ms 1.2e-2 ... h = 20 ms 2.7, rtol 1e-2 9.5). Bound 1e-2: the check's own energy
  // threshold, which the R2 error tracks (0.6 to 2.2 times the energy measure here).
  for (const SweepResult& r : results) {
    if (r.end != Ending::kAccurate) continue;
    EXPECT_LT(r.r2_error, 1e-2) << r.label << ": accurate but wrong";
  }
  // The coarse ends must be caught: h = 20 ms and rtol 1e-2 flagged, not failed or accurate.
  EXPECT_EQ(results.front().end, Ending::kFlagged);
  EXPECT_EQ(results[7].end, Ending::kFlagged);
}

TEST(Extremes, FlexibleSliderCrankStepAndToleranceSweep) {
  const std::string text = test::read_text(kFlexible);
  // Reference: gen-α at h = 10 µs, checked against IDA at rtol 1e-8 (another method): they
  // differ by 4.0e-5 (R2) and 9.2e-6 (deflection) of the peaks, measured; bound 1e-4, a
  // hundredth of the bounds below.
  const Outcome reference = run_text(text, "reference galpha 1e-5", galpha(1e-5, 0.2));
  ASSERT_TRUE(reference.summary.accurate()) << reference.summary.message;
  const Outcome check = run_text(text, "reference ida 1e-8", ida(1e-8, 0.2));
  ASSERT_TRUE(check.summary.accurate()) << check.summary.message;
  EXPECT_LT(relative_peak_error(check, reference, r2_force), 1e-4);
  EXPECT_LT(relative_peak_error(check, reference, deflection), 1e-4);
  const std::vector<SweepResult> results =
      sweep(text, reference, true, {2e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 5e-5, 2e-5}, {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-9}, 0.2);
  // Measured on the runs reported accurate: R2 at most 3.4e-3 and the mid-span deflection at
  // most 1.7e-2 of their peaks (both gen-α h = 1 ms, energy measure 2.7e-3: the deflection, a
  // 53-291 Hz vibration, carries gen-α's period error, ~6x the energy measure); the flagged
  // runs are off by 1.4e-2 ... 3.0 (R2) and 2.6e-2 ... 0.81 (deflection). Bounds: R2 1e-2 (the
  // energy threshold, as for the rigid rod), deflection 3e-2 (the "few per cent in a peak"
  // docs/integrators.md says a passing run may still be off).
  for (const SweepResult& r : results) {
    if (r.end != Ending::kAccurate) continue;
    EXPECT_LT(r.r2_error, 1e-2) << r.label << ": accurate but wrong";
    EXPECT_LT(r.deflection_error, 3e-2) << r.label << ": accurate but wrong";
  }
  EXPECT_EQ(results.front().end, Ending::kFlagged);
  EXPECT_EQ(results[8].end, Ending::kFlagged);
}


// 2. Stiff modes retained: every elastic mode of a 20-beam rod (up to 80 kHz).
TEST(Extremes, StiffModesRetained) {
  const Outcome stiff = run_text(coarse_flexible("{max_frequency_hz: 1.0e5}"), "modes <= 1e5 Hz", galpha(2e-4, 0.2));
  const Outcome twenty = run_text(coarse_flexible("20"), "20 modes", galpha(2e-4, 0.2));
  const Outcome five = run_text(coarse_flexible("5"), "5 modes", galpha(2e-4, 0.2));
  EXPECT_TRUE(well_behaved(stiff));
  ASSERT_FALSE(stiff.samples.empty());
  EXPECT_EQ(stiff.samples.front().bodies[1].modal_coordinates.size(), 120);
  std::printf("    vs 20 modes: deflection %.3e R2 %.3e; vs 5 modes: deflection %.3e R2 %.3e\n",
              relative_peak_error(stiff, twenty, deflection), relative_peak_error(stiff, twenty, r2_force),
              relative_peak_error(stiff, five, deflection), relative_peak_error(stiff, five, r2_force));
  // ω h up to 2π · 80 kHz · 0.2 ms = 100: gen-α's ρ∞ = 0.8 damps those modes within a few
  // steps, and the run is accurate. Against 20 modes (0.13 % rms from the unreduced rod,
  // flexible_run_test) measured 1.8e-3 (deflection) and 2.0e-4 (R2) of the peaks; 5 modes are
  // 4.4e-2 off. Bounds 5e-3 and 1e-3: tight enough that the 5-mode answer would fail.
  EXPECT_TRUE(stiff.summary.accurate());
  EXPECT_LT(relative_peak_error(stiff, twenty, deflection), 5e-3);
  EXPECT_LT(relative_peak_error(stiff, twenty, r2_force), 1e-3);
}

// 3. The crank at 100 rev/s.
constexpr double kFast = 2.0 * std::numbers::pi * 100.0;
TEST(Extremes, RigidCrankAt100RevPerSecond) {
  const std::string text = at_constant_speed(test::read_text(kRigid), kFast);
  for (const Outcome& run : {run_text(text, "100 rev/s ida 1e-6", ida(1e-6, 0.05, 2e-4)),
                             run_text(text, "100 rev/s galpha 2e-4", galpha(2e-4, 0.05, 2e-4)),
                             run_text(text, "100 rev/s galpha 5e-5", galpha(5e-5, 0.05, 2e-4))}) {
    EXPECT_TRUE(well_behaved(run));
    const auto [force_error, force_scale] = r3_inertia_error(run, 1.0, kFast);
    std::printf("    slider x error %.3e m, R3 x error %.3e of %.3e N\n", max_slider_error(run, kFast),
                force_error, force_scale);
    // Closed forms: x(θ) and the slider's inertia m ẍ = m ω² x''(θ) (20.7 kN peak), which R3
    // carries alone along x. Measured: all three accurate; x within 8.5e-8 m, R3 within 6.1e-3
    // (gen-α 0.2 ms, 16 steps a turn), 2.2e-4 (50 µs), 9.2e-5 (IDA). Bounds 1e-6 m (IDA's
    // ~10 rtol · a at rtol 1e-6) and the 1e-2 of the sweep.
    EXPECT_TRUE(run.summary.accurate()) << run.label;
    EXPECT_LT(max_slider_error(run, kFast), 1e-6) << run.label;
    EXPECT_LT(force_error, 1e-2) << run.label;
  }
}

TEST(Extremes, FlexibleCrankAt100RevPerSecond) {
  const std::string text = replaced(test::read_text(kFlexible), "speed: 125.66370614359172, duration",
                                    "speed: 628.3185307179586, duration");
  const Outcome galpha_run = run_text(text, "flexible 100 rev/s galpha 2e-4", galpha(2e-4, 0.2));
  const Outcome ida_run = run_text(text, "flexible 100 rev/s ida 1e-5", ida(1e-5, 0.2));
  double peak = 0.0;
  for (const results::Sample& s : ida_run.samples) peak = std::max(peak, deflection(s).norm());
  std::printf("    galpha vs ida: deflection %.3e R2 %.3e; peak deflection %.3e m\n",
              relative_peak_error(galpha_run, ida_run, deflection), relative_peak_error(galpha_run, ida_run, r2_force), peak);
  // The axial force (~25 x 2 kN) is far beyond the rod's buckling load (13.6 kN); the linear
  // modal rod deflects 0.14 m at mid-span, and the two integrators agree (1.0e-2 deflection,
  // 2.3e-2 R2: the same, physically wrong, linear answer). Both report the linear-range warning
  // (elastic rotation 0.111 rad at t = 0.051 s), and that makes the run "ok_inaccurate": it
  // finishes, but it is not reported as a good answer.
  for (const Outcome& run : {galpha_run, ida_run}) {
    EXPECT_TRUE(well_behaved(run));
    ASSERT_EQ(run.summary.warnings.size(), 1u) << run.label;
    EXPECT_NE(run.summary.warnings.front().find("leaves the linear range"), std::string::npos);
    EXPECT_TRUE(run.summary.ok);
    EXPECT_FALSE(run.summary.accurate()) << run.label;
  }
  EXPECT_GT(peak, 0.05);  // beyond the 5 % of the rod's size the warning stands for
  EXPECT_LT(relative_peak_error(galpha_run, ida_run, deflection), 5e-2);
}

// 4. Zero and critical modal damping.
TEST(Extremes, ZeroAndCriticalModalDamping) {
  const std::string base = test::read_text(kFlexible);
  const Outcome one = run_text(base, "damping 0.01", galpha(2e-4, 0.2));
  for (const char* zeta : {"0.0", "1.0"}) {
    const std::string text = replaced(base, "damping: 0.01                   #", std::string("damping: ") + zeta + " #");
    const Outcome run = run_text(text, std::string("damping ") + zeta, galpha(2e-4, 0.2));
    const Outcome fine = run_text(text, std::string("damping ") + zeta + " h 2.5e-5", galpha(2.5e-5, 0.2));
    EXPECT_TRUE(well_behaved(run));
    std::printf("    vs fine: deflection %.3e R2 %.3e; vs 1 %%: deflection %.3e R2 %.3e; dissipated %.3e J\n",
                relative_peak_error(run, fine, deflection), relative_peak_error(run, fine, r2_force),
                relative_peak_error(run, one, deflection), relative_peak_error(run, one, r2_force),
                run.samples.back().energies[4]);
    // Against the same damping at h = 25 µs, measured 7.6e-4 / 1.4e-4 (deflection, ζ = 0 / 1)
    // and 1.4e-4 / 1.2e-4 (R2): the case step's gen-α error. Bounds 5e-3 and 1e-3, those of
    // the stiff-mode test.
    EXPECT_TRUE(run.summary.accurate());
    EXPECT_LT(relative_peak_error(run, fine, deflection), 5e-3);
    EXPECT_LT(relative_peak_error(run, fine, r2_force), 1e-3);
    if (std::string(zeta) == "0.0") {
      EXPECT_EQ(run.samples.back().energies[4], 0.0);  // nothing dissipated
    } else {
      // Critical damping changes the answer (measured 0.53 of the peak deflection from 1 %)
      // and dissipates 7.9 J: the setting took effect.
      EXPECT_GT(relative_peak_error(run, one, deflection), 0.2);
      EXPECT_GT(run.samples.back().energies[4], 1.0);
    }
  }
}

// 5. Slider mass 1e-4 and 1e4 kg (crank 0.3 kg, rod 1.564 kg).
TEST(Extremes, ExtremeMassRatios) {
  const std::string base = at_constant_speed(test::read_text(kRigid), 2.0 * std::numbers::pi * 20.0);
  const double omega = 2.0 * std::numbers::pi * 20.0;
  for (double mass : {1e-4, 1e4}) {
    char slider[160];
    std::snprintf(slider, sizeof slider, "mass: %g\n    inertia: [%g, %g, %g]", mass, 4.1667e-4 * mass,
                  4.1667e-4 * mass, 4.1667e-4 * mass);
    const std::string text = replaced(base, "mass: 1.0\n    inertia: [4.1667e-4, 4.1667e-4, 4.1667e-4]", slider);
    for (const Outcome& run : {run_text(text, label_of("slider mass ida 1e-6", mass), ida(1e-6, 0.1)),
                               run_text(text, label_of("slider mass galpha 2e-4", mass), galpha(2e-4, 0.1))}) {
      EXPECT_TRUE(well_behaved(run));
      const auto [force_error, force_scale] = r3_inertia_error(run, mass, omega);
      std::printf("    slider x error %.3e m, R3 x error %.3e of %.3e N\n", max_slider_error(run, omega),
                  force_error, force_scale);
      // The slider's motion is kinematic and R3 carries its inertia along x exactly: closed
      // forms at any mass. Measured: accurate, x within 8.3e-8 m, R3 (0.083 N or 8.3 MN peak)
      // within 1.6e-4 of its peak. Bounds 1e-6 m and 1e-3.
      EXPECT_TRUE(run.summary.accurate()) << run.label;
      EXPECT_LT(max_slider_error(run, omega), 1e-6) << run.label;
      EXPECT_LT(force_error, 1e-3) << run.label;
    }
  }
}

// 6. Initial poses off the constraints.
TEST(Extremes, InitialPosesOffTheConstraints) {
  const double omega = 2.0 * std::numbers::pi * 20.0;
  const std::string base = at_constant_speed(test::read_text(kRigid), omega);
  // R3 and T on markers given in the body frames, so that a misplaced slider opens them.
  const std::string joints_on_markers = replaced(replaced(base,
      R"(  R3: {type: revolute, body_i: rod, body_j: slider, position: [1.05, 0, 0],
       orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}})",
      R"(  R3: {type: revolute, marker_i: rod_end, marker_j: pin})"),
      R"(  T:  {type: translational, body_i: ground, body_j: slider, position: [1.05, 0, 0],
       orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}})",
      R"(  T:  {type: translational, marker_i: rail, marker_j: shoe}
markers:
  rod_end: {body: rod, position: [1, 0, 0], orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}
  pin: {body: slider, orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}
  rail: {body: ground, position: [1.05, 0, 0], orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}}
  shoe: {body: slider, orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}})");
  const std::string slider_at = "position: [1.05, 0, 0]\n    shapes:\n      - {type: box, size: [0.1, 0.05, 0.05]";
  const auto slider_moved = [&](const std::string& text, const std::string& to) {
    return replaced(text, slider_at, replaced(slider_at, "[1.05, 0, 0]", to));
  };
  const auto crank_at = [&](double theta0) {
    char motion[128];
    std::snprintf(motion, sizeof motion, "motion: {type: constant_speed, initial: %.17g, speed:", theta0);
    return replaced(base, "motion: {type: constant_speed, initial: 0, speed:", motion);
  };
  struct Placement { const char* label; std::string text; double theta0; };
  const std::vector<Placement> placements = {
      {"markers, slider off 3 mm x 2 mm z", slider_moved(joints_on_markers, "[1.053, 0, 0.002]"), 0.0},
      {"markers, slider off 0.3 m z", slider_moved(joints_on_markers, "[1.05, 0, 0.3]"), 0.0},
      {"markers, slider at x 3 m", slider_moved(joints_on_markers, "[3.0, 0, 0]"), 0.0},
      {"markers, slider at x -0.95 m", slider_moved(joints_on_markers, "[-0.95, 0, 0]"), 0.0},
      {"points, slider at x 3 m", slider_moved(base, "[3.0, 0, 0]"), 0.0},
      {"driver 0.1 rad ahead", crank_at(0.1), 0.1},
      {"driver 1 rad ahead", crank_at(1.0), 1.0},
      {"driver 3 rad ahead", crank_at(3.0), 3.0},
  };
  for (const Placement& p : placements) {
    const Outcome run = run_text(p.text, p.label, ida(1e-6, 0.05));
    EXPECT_TRUE(well_behaved(run));
    if (!run.samples.empty()) {
      double error = 0.0;
      for (std::size_t k = 0; k < run.samples.size(); ++k) {
        error = std::max(error, std::abs(run.slider_x[k] - slider_x_at(p.theta0 + omega * run.samples[k].time)));
      }
      std::printf("    assembly %d iterations, slider x at start %.9f, error vs closed form %.3e\n",
                  run.assembly_iterations, run.slider_x.front(), error);
      if (std::string(p.label).starts_with("points")) {
        // FINDING (issue 14): joints given at ground points put their markers where the bodies
        // happen to be, so a slider placed 1.95 m off is not an assembly error: its pin marker
        // sits at (-1.95, 0, 0) in its frame, no iteration is needed, and the run is the
        // mechanism with the slider's mass 1.95 m from its pin. Expected here as it is.
        EXPECT_EQ(run.assembly_iterations, 0);
        EXPECT_NEAR(run.slider_x.front(), 3.0, 1e-12);
        continue;
      }
      // Assembly moved the slider (or crank, rod and slider for the driver) onto the closed
      // form, the right branch: measured errors <= 5.3e-8 m (IDA rtol 1e-6); bound 1e-6 m.
      EXPECT_TRUE(run.summary.accurate()) << p.label;
      EXPECT_GE(run.assembly_iterations, 1) << p.label;
      EXPECT_LT(error, 1e-6) << p.label;
    }
  }
  // Far beyond what the mechanism reaches: the rail 2 m above the slider line. Assembly fails,
  // naming the equation, its joint and the residual; no samples.
  const Outcome open = run_text(replaced(joints_on_markers, "rail: {body: ground, position: [1.05, 0, 0]",
                                         "rail: {body: ground, position: [1.05, 0, 2]"),
                                "markers, rail 2 m up", ida(1e-6, 0.05));
  EXPECT_TRUE(well_behaved(open));
  EXPECT_EQ(open.summary.failure, "assembly");
  EXPECT_NE(open.summary.message.find("(joint "), std::string::npos) << open.summary.message;
  EXPECT_NE(open.summary.message.find("does not close"), std::string::npos) << open.summary.message;
}

// 7. Dead centres and a near-singular mechanism, crank at constant speed.
TEST(Extremes, DeadCentresAndNearSingular) {
  const double omega = 2.0 * std::numbers::pi * 20.0;
  const std::string outer = at_constant_speed(test::read_text(kRigid), omega);
  std::string inner = replaced(outer, "    position: [0, 0, 0]\n    shapes:",
                               "    position: [0, 0, 0]\n    orientation: {axis: [0, 1, 0], angle: 3.141592653589793}\n    shapes:");
  inner = replaced(inner, "position: [0.05, 0, 0]", "position: [-0.05, 0, 0]");
  inner = replaced(inner, "[1.05, 0, 0]", "[0.95, 0, 0]");
  const double b_short = 1.001 * kA;
  std::string near = replaced(outer, "[1.05, 0, 0]", "[0.10005, 0, 0]");
  near = replaced(near, "center_of_mass: [0.5, 0, 0]", "center_of_mass: [0.025025, 0, 0]");
  struct Case { const char* label; std::string text; double theta0, b; };
  for (const Case& c : {Case{"outer dead centre", outer, 0.0, kB}, Case{"inner dead centre", inner, std::numbers::pi, kB},
                        Case{"rod 1.001 crank", near, 0.0, b_short}}) {
    for (const Outcome& run : {run_text(c.text, std::string(c.label) + " ida 1e-6", ida(1e-6, 0.1, 5e-4)),
                               run_text(c.text, std::string(c.label) + " galpha 2e-4", galpha(2e-4, 0.1, 5e-4))}) {
      EXPECT_TRUE(well_behaved(run));
      double error = 0.0;
      for (std::size_t k = 0; k < run.samples.size(); ++k) {
        error = std::max(error, std::abs(run.slider_x[k] - slider_x_at(c.theta0 + omega * run.samples[k].time, c.b)));
      }
      std::printf("    slider x error %.3e m\n", error);
      const bool near_singular = c.b < kB;
      if (near_singular && run.summary.integrator == "galpha") {
        // Near the lock-up (rod at 87.4° to the rail at θ = 90°) the slider's acceleration
        // peaks sharply; gen-α at 0.2 ms is flagged (energy 0.12, local error 5e-2, measured).
        EXPECT_EQ(ending(run), Ending::kFlagged);
        continue;
      }
      // Measured: accurate, x within 8.4e-8 m (IDA, 1.7e-7 near-singular), 2e-10 m (gen-α).
      // Bound 1e-6 m: IDA's ~10 rtol · a at rtol 1e-6.
      EXPECT_TRUE(run.summary.accurate()) << run.label;
      EXPECT_LT(error, 1e-6) << run.label;
    }
  }
}

// 8. A long undamped run at constant speed.
TEST(Extremes, LongRunEnergyBalance) {
  const std::string text = at_constant_speed(test::read_text(kRigid), 2.0 * std::numbers::pi * 20.0);
  const Outcome run = run_text(text, "20 s galpha 2e-4", galpha(2e-4, 20.0, 1e-2));
  EXPECT_TRUE(well_behaved(run));
  const auto balance = [](const results::Sample& s) {
    const std::vector<double>& e = s.energies;
    return e[0] + e[1] + e[2] + e[3] + e[4] - e[5] - e[6];
  };
  double first = 0.0, second = 0.0;
  for (const results::Sample& s : run.samples) {
    const double d = std::abs(balance(s) - balance(run.samples.front()));
    (s.time <= 10.0 ? first : second) = std::max(s.time <= 10.0 ? first : second, d);
  }
  std::printf("    balance drift: first half %.3e J, second half %.3e J, scale %.3e J, relative %.3e\n", first,
              second, run.summary.accuracy.energy_scale, run.summary.accuracy.energy_relative);
  // 400 turns, 100 000 steps, no damping: measured 9.5e-5 of the energy scale (88 J), the
  // same in both halves (8.4e-3 J, 6.7e-3 J): a bounded oscillation, no drift (ρ∞ = 0.8 < 1,
  // docs/integrators.md). Bounds: 1e-3 relative, and the second half within twice the first.
  EXPECT_TRUE(run.summary.accurate());
  EXPECT_LT(run.summary.accuracy.energy_relative, 1e-3);
  EXPECT_LT(second, 2.0 * first);
}

// 10. A crank driven by a linear table with kinks: 0 to 6 rad in 0.05 s (120 rad/s from the
// start), held to 0.1 s, back to 0 by 0.2 s, held after; its rate jumps at 0.05, 0.1 and
// 0.2 s. Before the velocity breakpoints, IDA failed at t = 0.05 s (corrector convergence at
// h = 6e-19) and generalized-alpha ended flagged (energy balance 25 % off: the impulses' work
// was nowhere). Now both stop at each kink and restart with the velocities after it.
TEST(Extremes, LinearTableDriverWithKinks) {
  const std::string text = replaced(test::read_text(kRigid), kRamp,
                                    "motion: {type: table, x: [0, 0.05, 0.1, 0.2], y: [0, 6, 6, 0]}");
  const auto theta = [](double t) {
    if (t <= 0.05) return 120.0 * t;
    if (t <= 0.1) return 6.0;
    if (t <= 0.2) return 6.0 - 60.0 * (t - 0.1);
    return 0.0;
  };
  for (const Outcome& run : {run_text(text, "table ida 1e-6", ida(1e-6, 0.3)),
                             run_text(text, "table galpha 2e-4", galpha(2e-4, 0.3))}) {
    ASSERT_TRUE(well_behaved(run));
    double error = 0.0;
    for (std::size_t k = 0; k < run.samples.size(); ++k) {
      error = std::max(error, std::abs(run.slider_x[k] - slider_x_at(theta(run.samples[k].time))));
    }
    std::printf("    slider x error %.3e m against x(theta(t))\n", error);
    // The slider's motion is kinematic: the closed form holds through the kinks as between
    // them (bound 1e-6 m, as for the constant speeds above); measured 4e-16 (IDA), 5e-8
    // (generalized-alpha). The energy balance holds with each impulse's work counted as the
    // driver's (measured 2.5e-5 and 3.1e-3 of the energy scale): accurate.
    EXPECT_EQ(ending(run), Ending::kAccurate) << run.label;
    EXPECT_LT(error, 1e-6) << run.label;
  }
}

}  // namespace
}  // namespace limber::run
