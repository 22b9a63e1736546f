// The stress parts of a report (report/stress_summary.h, run_data.h, plot_set.cpp) on a results
// file written with known stresses: the peak's value, time, element name and centre, and the
// hinge event before it come out as constructed; history rows are read back per element.
#include <gtest/gtest.h>

#include <cmath>

#include "plot_set.h"
#include "report_test_util.h"
#include "results/results_writer.h"
#include "run_data.h"
#include "stress_summary.h"

namespace limber::report {
namespace {

// A flexible "part": one beam (element 0, nodes 0-1) and two quads (elements 1, 2) on 7 nodes;
// its peak stress is 2 MPa + 1 MPa k at sample k in element k % 3, largest (12 MPa) at sample 10
// (t = 0.5 s) in element 1: quad 1, centre (1.5, 0.5, 0). A latch locks at t = 0.4 s.
void write_stress_run(const std::filesystem::path& dir) {
  results::ResultsWriter writer(dir, "stress test", "stress_report_test.cpp");
  results::FlexibleBodySpec part;
  part.name = "part";
  part.nodes.resize(7, 3);
  part.nodes << 0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 3, 0, 0, 3, 1, 0;
  part.lines.resize(1, 2);
  part.lines << 0, 1;
  part.quads.resize(2, 4);
  part.quads << 1, 2, 3, 4, 2, 5, 6, 3;
  part.mode_translations.setZero(21, 1);
  part.frequencies_hz = Eigen::VectorXd::Constant(1, 3.0);
  part.has_stress = true;
  part.stress_elements = {0, 1, 2};
  part.stress_every = 2;
  writer.add_flexible_body(part);
  writer.add_joint({"hinge", "revolute", "ground", "part"});
  writer.add_hinge_limit({"latch", "latch", "hinge", 1.0});
  for (int k = 0; k <= 12; ++k) {
    results::Sample sample;
    sample.time = 0.05 * k;
    sample.bodies.resize(1);
    results::BodySample& b = sample.bodies[0];
    b.modal_coordinates = Eigen::VectorXd::Zero(1);
    b.modal_velocities = Eigen::VectorXd::Zero(1);
    b.stress_peak = k == 10 ? 12e6 : 2e6 + 1e5 * k;
    b.stress_peak_element = k == 10 ? 1 : k % 3;
    b.stress_recorded = k % 2 == 0;
    if (b.stress_recorded) {
      b.stress_equivalent = Eigen::Vector3d(1e6 * k, 2e6 * k, 3e6 * k);
      b.stress_beam_resultants = Eigen::VectorXd::Zero(12);
      b.stress_shell_resultants = Eigen::VectorXd::Zero(16);
    }
    sample.joints.resize(1);
    sample.energies = {};
    sample.hinge_limit_angles = {0.0};
    sample.hinge_limit_torques = {0.0};
    sample.hinge_limits_engaged = {static_cast<std::int8_t>(k >= 8)};
    writer.append_sample(sample);
    if (k == 8) writer.append_event({0.4, 0, true, 1.0, 0.5});
  }
  writer.finish(results::RunStatus::kOk);
}

TEST(StressReport, PeakElementPlaceTimeAndEventAsWritten) {
  const auto dir = testing::fresh_directory("stress_report");
  write_stress_run(dir);
  const RunData run = read_run_data(dir);
  ASSERT_EQ(run.stresses.size(), 1u);
  ASSERT_TRUE(run.stresses[0].has_value());
  const render::StressTrack& track = *run.stresses[0];
  EXPECT_EQ(track.peak.size(), 13);
  EXPECT_EQ(track.time.size(), 7);  // samples 0, 2, ..., 12
  EXPECT_EQ(track.row_at(0.33), 3);  // t = 0.3 s, sample 6
  EXPECT_EQ(track.element_values(3, 3), Eigen::Vector3d(6e6, 12e6, 18e6));

  const std::vector<StressPeak> peaks = stress_peaks(run);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_EQ(peaks[0].body, "part");
  EXPECT_EQ(peaks[0].value, 12e6);
  EXPECT_DOUBLE_EQ(peaks[0].time, 0.5);
  EXPECT_EQ(peaks[0].element, 1);
  EXPECT_EQ(peaks[0].element_name, "quad 1 (element 2)");
  EXPECT_TRUE(peaks[0].centre_B.isApprox(Eigen::Vector3d(1.5, 0.5, 0.0)));
  EXPECT_EQ(peaks[0].after, "0.100 s after latch locked");

  // One plot of the peak stress per body, in MPa.
  int stress_plots = 0;
  for (const NamedPlot& plot : run_plots(run, "r_")) {
    if (plot.section != PlotSection::kStress) continue;
    ++stress_plots;
    ASSERT_EQ(plot.spec.curves.size(), 1u);
    EXPECT_DOUBLE_EQ(plot.spec.curves[0].y.maxCoeff(), 12.0);
  }
  EXPECT_EQ(stress_plots, 1);
}

}  // namespace
}  // namespace limber::report
