// The report's acceleration probes and shock response spectra (report/shock_data.h,
// shock_plots.h) on a results file written with a known probe history and its spectra: the
// reader returns what was written, the SRS plot is log-log in g with one curve per window named
// in the legend, and the page holds the section with both plots.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plot_set.h"
#include "report_job.h"
#include "report_test_util.h"
#include "results/results_writer.h"
#include "results/shock_spectra.h"
#include "run_data.h"
#include "shock_plots.h"

namespace limber::report {
namespace {

// A 1 s run sampled at 1 ms: probe "tip" at 1 g in x throughout and a 10 ms half-sine of 20 g
// in z from the latch at 0.5 s.
results::ShockSpectra write_probe_run(const std::filesystem::path& dir) {
  const double dt = 1e-3;
  const Eigen::Index ns = 1001;
  results::ProbeHistory history{"tip", {}};
  history.acceleration.setZero(ns, 3);
  Eigen::VectorXd time(ns);
  for (Eigen::Index k = 0; k < ns; ++k) {
    time(k) = static_cast<double>(k) * dt;
    history.acceleration(k, 0) = results::kStandardGravity;
    const double s = time(k) - 0.5;
    if (s > 0.0 && s < 0.01) history.acceleration(k, 2) = 20.0 * results::kStandardGravity * std::sin(std::numbers::pi * s / 0.01);
  }
  const results::ShockSpectra spectra = results::shock_spectra(time, dt, {history}, {{"L1", 0.5}}, {});
  results::ResultsWriter writer(dir, "probe test", "shock_report_test.cpp");
  writer.add_rigid_body({"panel", {}});
  writer.add_acceleration_probe({"tip", "panel", -1, Eigen::Vector3d(1, 0, 0)});
  for (Eigen::Index k = 0; k < ns; ++k) {
    results::Sample sample;
    sample.time = time(k);
    sample.bodies.emplace_back();
    sample.probe_accelerations.push_back(history.acceleration.row(k).transpose());
    writer.append_sample(sample);
  }
  writer.set_shock_spectra(spectra);
  writer.finish(results::RunStatus::kOk);
  return spectra;
}

TEST(ShockReport, ProbesSpectraAndTheirPlots) {
  const auto dir = testing::fresh_directory("shock");
  const results::ShockSpectra written = write_probe_run(dir);
  const RunData run = read_run_data(dir);
  // The reader: history and spectra as written.
  ASSERT_EQ(run.acceleration_probes.size(), 1u);
  EXPECT_EQ(run.acceleration_probes[0].name, "tip");
  EXPECT_EQ(run.acceleration_probes[0].body, "panel");
  EXPECT_EQ(run.acceleration_probes[0].acceleration.rows(), 1001);
  ASSERT_TRUE(run.shock_spectra.has_value());
  const ShockSpectraData& spectra = *run.shock_spectra;
  EXPECT_EQ(spectra.q, 10.0);
  ASSERT_EQ(spectra.window_names, (std::vector<std::string>{"whole run", "start", "latch L1"}));
  ASSERT_EQ(spectra.probes.size(), 1u);
  EXPECT_EQ(spectra.probes[0].maximax[2][2], written.probes[0].windows[2][2].maximax);

  // The SRS plot: log-log, in g, one curve per window, each the largest of the axes: x's 1 g
  // below the pulse's, z's pulse above it (its SRS ≥ its 20 g at the top of the band).
  const std::vector<NamedPlot> plots = shock_plots(run, "run1_");
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].file, "run1_acceleration_tip.png");
  const NamedPlot& srs = plots[1];
  EXPECT_EQ(srs.file, "run1_srs_tip.png");
  EXPECT_TRUE(srs.spec.log_x && srs.spec.log_y);
  EXPECT_EQ(srs.spec.y_label, "peak absolute acceleration [g]");
  ASSERT_EQ(srs.spec.curves.size(), 3u);
  EXPECT_EQ(srs.spec.curves[0].label, "whole run (0-1 s)");
  EXPECT_EQ(srs.spec.curves[1].label, "start (0-0.3 s)");  // no pulse: the 1 g of x
  EXPECT_EQ(srs.spec.curves[2].label, "latch L1 at 0.5 s (0.5-0.8 s)");
  EXPECT_NEAR(srs.spec.curves[1].y.maxCoeff(), 1.0, 1e-9);
  EXPECT_NEAR(srs.spec.curves[1].y.minCoeff(), 1.0, 1e-9);
  const Eigen::VectorXd z_g = written.probes[0].windows[2][2].maximax / results::kStandardGravity;
  EXPECT_TRUE(srs.spec.curves[2].y.isApprox(z_g.cwiseMax(1.0), 1e-12));
  EXPECT_GT(srs.spec.curves[2].y.maxCoeff(), 20.0);

  // The page: the section and both images.
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  EXPECT_NE(html.find("Acceleration probes and shock response spectra"), std::string::npos);
  EXPECT_NE(html.find("srs_tip.png"), std::string::npos);
  EXPECT_NE(html.find("acceleration_tip.png"), std::string::npos);
}

}  // namespace
}  // namespace limber::report
