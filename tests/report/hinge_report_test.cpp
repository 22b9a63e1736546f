// The deployment parts of a report (report/hinge_summary.h, run_data.h, report_html.cpp) on a
// results file written with known hinge limits, events, reactions and energies: the model's
// order of the limits survives HDF5's name order, latch-up peaks and the energy residual come
// out as constructed, and the page lists every event.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hinge_summary.h"
#include "report_job.h"
#include "report_test_util.h"
#include "results/results_writer.h"
#include "run_data.h"

namespace limber::report {
namespace {

constexpr double kLatchTime = 0.3;  // [s]

// |F| of joint "hinge" [N]: a half sine of 100 N peaking 0.25 s after the latch, else 1 N.
double hinge_force(double t) {
  const double s = (t - kLatchTime) / 0.5;
  return s > 0.0 && s < 1.0 ? 100.0 * std::sin(std::numbers::pi * s) : 1.0;
}

// A rigid "panel" on joints "mount" (|F| = 50 N) and "hinge"; limits declared "zeta_latch"
// (on hinge) then "alpha_stop" (on mount): HDF5 lists them the other way round. Events: the
// latch locks at 0.3 s, the stop touches at 0.6 s and releases at 0.7 s. Energies whose
// balance drifts by 1e-3 t J.
void write_deployment_run(const std::filesystem::path& dir) {
  results::ResultsWriter writer(dir, "hinge test", "hinge_report_test.cpp");
  writer.add_rigid_body({"panel", {}});
  writer.add_joint({"mount", "revolute", "ground", "panel"});
  writer.add_joint({"hinge", "revolute", "panel", "tip"});
  for (const char* name : {"kinetic", "gravity", "spring", "strain", "dissipated", "driver_work", "force_work"}) {
    writer.add_energy(name);
  }
  writer.add_hinge_limit({"zeta_latch", "latch", "hinge", 1.5});
  writer.add_hinge_limit({"alpha_stop", "stop", "mount", -0.5});
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    results::Sample sample;
    sample.time = t;
    sample.bodies.emplace_back();
    results::JointSample mount, hinge;
    mount.force_ground = Eigen::Vector3d(30.0, 40.0, 0.0);
    hinge.force_ground = Eigen::Vector3d(0.0, 0.0, -hinge_force(t));
    hinge.force_joint = Eigen::Vector3d(0.0, -hinge_force(t), 0.0);  // joint y along ground −z
    sample.joints = {mount, hinge};
    // Spring energy turning into kinetic, 1 mJ/s lost to the balance.
    sample.energies = {5.0 * t, 0.0, 10.0 - 5.0 * t, 0.0, 1e-3 * t, 0.0, 0.0};
    sample.hinge_limit_angles = {std::min(5.0 * t, 1.5), 0.0};
    sample.hinge_limit_torques = {t > kLatchTime ? 20.0 * (t - kLatchTime) : 0.0, 0.0};
    sample.hinge_limits_engaged = {static_cast<std::int8_t>(t > kLatchTime), 0};
    writer.append_sample(sample);
    if (k == 30) writer.append_event({kLatchTime, 0, true, 1.5, 5.0});
    if (k == 60) writer.append_event({0.6, 1, true, -0.5, -2.0});
    if (k == 70) writer.append_event({0.7, 1, false, -0.5, 2.0});
  }
  writer.finish(results::RunStatus::kOk);
}

TEST(HingeReport, LimitsEventsPeaksAndEnergyResidualAsWritten) {
  const auto dir = testing::fresh_directory("hinges");
  write_deployment_run(dir);
  const RunData run = read_run_data(dir);
  // Model order, not name order: events refer to it.
  ASSERT_EQ(run.hinge_limits.size(), 2u);
  EXPECT_EQ(run.hinge_limits[0].name, "zeta_latch");
  EXPECT_EQ(run.hinge_limits[0].joint, "hinge");
  EXPECT_EQ(run.hinge_limits[0].limit_angle, 1.5);
  EXPECT_EQ(run.hinge_limits[1].kind, "stop");
  ASSERT_EQ(run.events.size(), 3u);
  EXPECT_EQ(run.events[0].limit, 0);
  EXPECT_EQ(run.events[2].limit, 1);
  EXPECT_FALSE(run.events[2].engaged);

  // One latch event: the hinge's half sine peaks at 100 N at 0.55 s (a sample), the latch
  // torque at 20 (0.8 − 0.3) = 10 N m at the window's end; no joint exceeds the hinge.
  const std::vector<LatchUpPeaks> peaks = latch_up_peaks(run);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_NEAR(peaks[0].latched_force, 100.0, 1e-9);
  EXPECT_NEAR(peaks[0].latched_force_time, 0.55, 1e-12);
  EXPECT_NEAR(peaks[0].latch_torque, 10.0, 1e-9);
  EXPECT_NEAR(peaks[0].latched_force_joint.y(), 100.0, 1e-9);
  EXPECT_EQ(peaks[0].latched_force_joint.x(), 0.0);
  EXPECT_EQ(peaks[0].largest_joint, "hinge");

  // The balance: 10 J stored throughout plus 1e-3 t J dissipated, so the residual is 1e-3 t.
  const std::optional<Series> residual = energy_residual(run);
  ASSERT_TRUE(residual.has_value());
  EXPECT_NEAR(residual->values(100), 1e-3, 1e-12);
  EXPECT_NEAR(residual->values(0), 0.0, 0.0);

  // The page: every event, the latch-up peak row and the hinge plots.
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  EXPECT_NE(html.find("<td>zeta_latch</td><td>latch</td><td>hinge</td><td>locked</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>alpha_stop</td><td>stop</td><td>mount</td><td>contact ends</td>"), std::string::npos);
  EXPECT_NE(html.find("Latch-up peaks"), std::string::npos);
  EXPECT_NE(html.find("hinge_angles.png"), std::string::npos);
  EXPECT_NE(html.find("energy_balance.png"), std::string::npos);
}

TEST(HingeReport, RunsWithoutHingesHaveNoHingeSection) {
  const auto dir = testing::fresh_directory("no_hinges");
  results::ResultsWriter writer(dir, "plain", "hinge_report_test.cpp");
  writer.add_rigid_body({"block", {}});
  results::Sample sample;
  sample.bodies.emplace_back();
  writer.append_sample(sample);
  writer.finish(results::RunStatus::kOk);
  const RunData run = read_run_data(dir);
  EXPECT_TRUE(run.hinge_limits.empty());
  EXPECT_TRUE(run.events.empty());
  EXPECT_TRUE(latch_up_peaks(run).empty());
  ReportOptions options;
  options.directories = {dir};
  EXPECT_EQ(testing::read_text(generate_report(options).index).find("Hinges and latches"), std::string::npos);
}

}  // namespace
}  // namespace limber::report
