// Acceleration probes through the run driver: a point of a free spinning, falling top against
// the closed form; an FE node of the flexible slider-crank's rod against central differences
// of its velocity along the run (a second method); a deploying wing's outer panel tip, whose
// spectra get a window at the latch-up and go to results.h5 and srs_<probe>.csv.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/acceleration_probe.h"
#include "multibody/time_function.h"
#include "results/results_layout.h"
#include "results/shock_spectra_file.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

io::Mechanism build(const std::string& text, const std::string& name) {
  const io::Case input = io::read_case_text(text, name);
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
}

// A free symmetric top (inertia 1, 1, 2 kg m²) spinning about its symmetry axis z at Ω and
// falling under g: torque-free about its centre of mass, so Ω stays and the point p_B = (ρ, 0, 0)
// has a = g − Ω² ρ (cos Ωt, sin Ωt, 0).
TEST(AccelerationProbeRun, PointOfAFallingSpinningTopIsGravityPlusCentripetal) {
  const double Omega = 20.0, rho = 0.5, g = 9.81;
  const std::string text = R"(title: top
gravity: [0, 0, -9.81]
bodies:
  top: {mass: 2, inertia: [1, 1, 2], angular_velocity: [0, 0, 20]}
acceleration_probes:
  rim: {body: top, position: [0.5, 0, 0]}
run: {integrator: ida, rtol: 1.0e-9, atol: 1.0e-11, t_end: 0.5, sample_interval: 1.0e-3}
)";
  const io::Mechanism built = build(text, "top.yaml");
  double worst = 0.0;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    const double t = sample.t;
    const Eigen::Vector3d expected(-Omega * Omega * rho * std::cos(Omega * t), -Omega * Omega * rho * std::sin(Omega * t), -g);
    worst = std::max(worst, (record.probe_accelerations.at(0) - expected).norm() / (Omega * Omega * rho));
  };
  const RunSummary summary = run_mechanism(built.model, built.assembly, built.run, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  // IDA at rtol 1e-9 holds the phase Ωt to about 1e-8 rad over 10 rad: 1e-6 of Ω² ρ is ample.
  EXPECT_LT(worst, 1e-6);
  std::printf("spinning top: largest acceleration error %.3g of the centripetal 200 m/s^2\n", worst);
  // Its spectra: the whole run and the start window, nothing else (no latches).
  ASSERT_TRUE(summary.shock_spectra.has_value());
  ASSERT_EQ(summary.shock_spectra->windows.size(), 2u);
  EXPECT_EQ(summary.shock_spectra->windows[1].name, "start");
}

// The seed's flexible slider-crank (cases/slider_crank.yaml) started at full speed, which rings
// the rod: the mid-span node 51 and a point of the crank. The probe's acceleration against the
// central difference of its velocity (both from the integrator's samples, through
// probe_motion) over samples 20 µs apart: the difference's truncation error is (ω h)²/6 of a
// component at ω, 0.13 % at the rod's highest mode in the set (about 700 Hz); IDA at rtol 1e-8
// adds ~1e-6. Bound: 1 % of the run's peak acceleration.
TEST(AccelerationProbeRun, FlexibleNodeMatchesDifferencesOfItsVelocity) {
  const std::string text = test::read_text(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml") +
                           "acceleration_probes:\n  rod_mid: {body: rod, node: 51}\n"
                           "  crank_pin: {body: crank, position: [0.05, 0, 0]}\n";
  const io::Mechanism built = build(text, "slider_crank.yaml");
  multibody::Model model = built.model;
  model.drivers[0].motion = multibody::TimeFunction::constant_speed(0.0, 2.0 * std::numbers::pi * 20.0);
  io::RunSettings settings = built.run;
  settings.integrator = integrate::IntegratorOptions::ida(1e-8, 1e-10);
  settings.t_end = 0.02;
  settings.sample_interval = 2e-5;
  std::vector<double> t;
  std::vector<std::vector<multibody::PointMotion>> motions;
  double recorded_mismatch = 0.0;
  multibody::FrameKinematics frame;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    t.push_back(sample.t);
    std::vector<multibody::PointMotion> row;
    for (std::size_t p = 0; p < model.acceleration_probes.size(); ++p) {
      row.push_back(multibody::probe_motion(model, model.acceleration_probes[p], sample.q, sample.v, sample.vdot, frame));
      recorded_mismatch = std::max(recorded_mismatch, (row.back().a_W - record.probe_accelerations.at(p)).norm());
    }
    motions.push_back(row);
  };
  const RunSummary summary = run_mechanism(model, built.assembly, settings, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  EXPECT_EQ(recorded_mismatch, 0.0);  // the file holds what probe_motion gives
  for (std::size_t p = 0; p < model.acceleration_probes.size(); ++p) {
    double peak = 0.0, error = 0.0;
    for (std::size_t k = 1; k + 1 < t.size(); ++k) {
      const Eigen::Vector3d difference = (motions[k + 1][p].v_W - motions[k - 1][p].v_W) / (t[k + 1] - t[k - 1]);
      error = std::max(error, (difference - motions[k][p].a_W).norm());
      peak = std::max(peak, motions[k][p].a_W.norm());
    }
    EXPECT_LT(error, 0.01 * peak) << model.acceleration_probes[p].name;
    std::printf("%s: peak %.4g m/s^2, largest difference from d(v)/dt %.3g of it\n",
                model.acceleration_probes[p].name.c_str(), peak, error / peak);
  }
}

// One deploying wing (tests/run/data/deployment_one_wing.yaml) with a probe at the outer panel's
// far edge (node 33) and one on the bus, deploying until both latches have locked: a window
// opens at each latch, and the spectra land in results.h5 and srs_<probe>.csv.
TEST(AccelerationProbeRun, DeployingWingSpectraHaveLatchWindowsAndFiles) {
  const std::string text = test::read_text(std::string(LIMBER_TEST_DATA_DIR) + "/deployment_one_wing.yaml") +
                           "acceleration_probes:\n  tip: {body: panel_2, node: 33}\n"
                           "  bus_top: {body: bus, position: [0, 0, 0.65]}\n"
                           "shock_spectrum: {window: 0.2}\n";
  const io::Mechanism built = build(text, "deployment_one_wing.yaml");
  io::RunSettings settings = built.run;
  // Recorded at every step of 0.5 ms: the band reaches 1/(10 h) = 200 Hz (the samples, every
  // 2 ms, would have supported 50 Hz).
  settings.integrator.step = 5e-4;
  const auto dir = test::fresh_directory("acceleration_probes");
  RunSummary summary;
  {
    results::ResultsWriter writer(dir, "wing", "deployment_one_wing.yaml");
    RunHooks hooks;
    hooks.writer = &writer;
    summary = run_mechanism(built.model, built.assembly, settings, hooks);
  }
  ASSERT_TRUE(summary.ok) << summary.message;
  ASSERT_TRUE(summary.shock_spectra.has_value());
  const results::ShockSpectra& spectra = *summary.shock_spectra;
  // Whole run, start, and one window per latch that locked, at its time, 0.2 s long.
  std::vector<double> latch_times;
  for (const multibody::HingeEvent& event : summary.events) {
    if (event.engaged) latch_times.push_back(event.t);
  }
  ASSERT_EQ(latch_times.size(), 2u);
  ASSERT_EQ(spectra.windows.size(), 4u);
  for (std::size_t w = 2; w < 4; ++w) {
    EXPECT_EQ(spectra.windows[w].name.rfind("latch latch_", 0), 0u) << spectra.windows[w].name;
    EXPECT_EQ(spectra.windows[w].start, latch_times[w - 2]);
    const double next = w == 2 ? latch_times[1] : settings.t_end;
    EXPECT_NEAR(spectra.windows[w].end, std::min(latch_times[w - 2] + 0.2, next), 1e-12);
  }
  EXPECT_NEAR(spectra.frequency_hz.back(), 5.0 * std::exp2(std::floor(6.0 * std::log2(200.0 / 5.0)) / 6.0), 1e-9);
  // The record's longest step is the step (events only cut it).
  EXPECT_LE(spectra.longest_step, 5e-4 * (1.0 + 1e-9));
  EXPECT_GT(spectra.longest_step, 5e-4 * (1.0 - 1e-9));
  // The files.
  const hid_t file = H5Fopen((dir / results::kResultsFileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::string tip = results::layout::at(results::layout::kAccelerationProbes, "tip");
  EXPECT_EQ(results::testing::dataset_dims(file, results::layout::at(tip, results::layout::acceleration_probe::kAcceleration)),
            (std::vector<hsize_t>{static_cast<hsize_t>(summary.samples), 3}));
  const std::string srs = results::layout::at(
      results::layout::at(results::layout::kShockSpectra, results::layout::shock_spectra::kProbes), "tip");
  EXPECT_EQ(results::testing::dataset_dims(file, results::layout::at(srs, results::layout::shock_spectra::kMaximax)),
            (std::vector<hsize_t>{4, 3, spectra.frequency_hz.size()}));
  H5Fclose(file);
  for (const char* probe : {"tip", "bus_top"}) {
    std::ifstream csv(dir / results::shock_spectrum_csv_name(probe));
    std::size_t lines = 0;
    for (std::string line; std::getline(csv, line);) ++lines;
    EXPECT_EQ(lines, 1 + 4 * spectra.frequency_hz.size()) << probe;
  }
  // The latch-up's shock: the tip's largest latch-window value in g, printed for the docs.
  double peak = 0.0;
  for (std::size_t w = 2; w < 4; ++w) {
    for (const results::ShockSpectrum& axis : spectra.probes[0].windows[w]) peak = std::max(peak, axis.maximax.maxCoeff());
  }
  std::printf("wing tip: largest latch-window SRS %.4g g\n", peak / results::kStandardGravity);
  EXPECT_GT(peak, 0.0);
}

}  // namespace
}  // namespace limber::run
