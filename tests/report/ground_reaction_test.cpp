// Reactions in ground axes (seed paper Figs. 4 and 5): each joint gets its ground-axes plots
// (components X, Y, Z = ground x, y, z) before its joint-frame plots, and their curves are the
// numbers stored in /joints/<joint>/force_ground and torque_ground.
#include "plot.h"
#include "plot_set.h"
#include "reaction_runs.h"
#include "report_job.h"
#include "report_test_util.h"
#include "results/results_writer.h"
#include "run_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace limber::report {
namespace {

using testing::ReactionRun;

// File names of the reaction plots, in order.
std::vector<std::string> reaction_files(const std::vector<NamedPlot>& plots) {
  std::vector<std::string> files;
  for (const NamedPlot& p : plots) {
    if (p.section == PlotSection::kReactions) files.push_back(p.file);
  }
  return files;
}

const NamedPlot& plot_named(const std::vector<NamedPlot>& plots, const std::string& file) {
  const auto it = std::find_if(plots.begin(), plots.end(), [&](const NamedPlot& p) { return p.file == file; });
  if (it == plots.end()) throw std::runtime_error("no plot " + file);
  return *it;
}

TEST(GroundReactionPlots, ComeBeforeTheJointFrameAndHoldTheStoredForces) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("ground_force");
  const ReactionRun run;
  write_reaction_run(dir, run);
  const RunData data = read_run_data(dir);
  const std::vector<NamedPlot> plots = run_plots(data, "run1_");

  // Ground axes, then joint frame; no torque plots (the torques are zero).
  EXPECT_EQ(reaction_files(plots),
            (std::vector<std::string>{"run1_reaction_R3_force_ground.png", "run1_reaction_R3_force.png"}));
  const NamedPlot& ground = plot_named(plots, "run1_reaction_R3_force_ground.png");
  EXPECT_NE(ground.caption.find("ground axes (X = ground x, Y = ground y, Z = ground z)"),
            std::string::npos)
      << ground.caption;
  EXPECT_NE(ground.caption.find("joint R3 on slider"), std::string::npos) << ground.caption;
  EXPECT_EQ(ground.spec.y_label, "force [N]");
  ASSERT_EQ(ground.spec.curves.size(), 3u);

  // Each curve is the stored force_ground column, and that is G(t) as written (exact: the
  // float64 values pass through HDF5 unchanged; 1e-12 A covers the sin/cos evaluation only).
  ASSERT_EQ(data.joints.size(), 1u);
  const RowMatrix3d& stored = data.joints[0].force_ground;
  ASSERT_EQ(stored.rows(), run.samples);
  const NamedPlot& joint_frame = plot_named(plots, "run1_reaction_R3_force.png");
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(ground.spec.curves[c].label, std::string(1, "XYZ"[c]));
    EXPECT_EQ(joint_frame.spec.curves[c].label, std::string("F") + "xyz"[c]);
    for (int k = 0; k < run.samples; ++k) {
      const double t = data.results.time(k);
      EXPECT_EQ(ground.spec.curves[c].x(k), t);
      EXPECT_EQ(ground.spec.curves[c].y(k), stored(k, c));
      EXPECT_NEAR(stored(k, c), testing::reaction_force_ground(run, t)(c), 1e-12 * run.amplitude);
      EXPECT_NEAR(joint_frame.spec.curves[c].y(k), testing::reaction_force(run, t)(c), 1e-12 * run.amplitude);
    }
  }

  // In the report: the figure with its caption, before the joint-frame one, and its Z curve
  // (drawn last, so nothing covers it) at the pixels of G_z = A sin(2 pi f t) / 20 (3 px, 40
  // per channel as in plot_test.cpp).
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  const std::size_t ground_at = html.find("src=\"images/run1_reaction_R3_force_ground.png\"");
  const std::size_t joint_at = html.find("src=\"images/run1_reaction_R3_force.png\"");
  ASSERT_NE(ground_at, std::string::npos);
  ASSERT_NE(joint_at, std::string::npos);
  EXPECT_LT(ground_at, joint_at);
  EXPECT_NE(html.find("<figcaption>Reaction force at joint R3 on slider, components in ground axes "
                      "(X = ground x, Y = ground y, Z = ground z). "
                      "<a class=\"csv\" href=\"data/run1_reaction_R3_force_ground.csv\">"),
            std::string::npos);
  PlotFrame frame;
  {
    ChartCanvas canvas(options.plot_width, options.plot_height);
    frame = canvas.draw(ground.spec, testing::fresh_directory("ground_force_again") / "ground.png");
  }
  const testing::Png png(dir / "report/images/run1_reaction_R3_force_ground.png");
  for (int k = 0; k < run.samples; k += 5) {
    const double t = data.results.time(k);
    const Eigen::Vector2d at = frame.to_pixel(t, testing::reaction_force_ground(run, t).z());
    EXPECT_TRUE(testing::color_near(png, at.x(), at.y(), kCurveColors[2])) << "Z at t = " << t;
  }
}

TEST(GroundReactionPlots, TorqueInGroundAxesWhenTheJointTransmitsOne) {
  // A fixed joint "weld" carrying force (1, 2, 3) t N and torque (4, 5, 6) t N m in ground axes,
  // other numbers in its frame.
  const auto dir = testing::fresh_directory("ground_torque");
  {
    results::ResultsWriter writer(dir, "weld", "ground_reaction_test.cpp");
    writer.add_rigid_body({"arm", {}});
    writer.add_joint({"weld", "fixed", "ground", "arm"});
    for (int k = 0; k <= 10; ++k) {
      results::Sample sample;
      sample.time = 0.1 * k;
      sample.bodies.emplace_back();
      results::JointSample weld;
      weld.force_ground = sample.time * Eigen::Vector3d(1.0, 2.0, 3.0);
      weld.torque_ground = sample.time * Eigen::Vector3d(4.0, 5.0, 6.0);
      weld.force_joint = -weld.force_ground;
      weld.torque_joint = -weld.torque_ground;
      sample.joints = {weld};
      writer.append_sample(sample);
    }
    writer.finish(results::RunStatus::kOk);
  }
  const RunData data = read_run_data(dir);
  const std::vector<NamedPlot> plots = run_plots(data, "");
  EXPECT_EQ(reaction_files(plots),
            (std::vector<std::string>{"reaction_weld_force_ground.png", "reaction_weld_torque_ground.png",
                                      "reaction_weld_force.png", "reaction_weld_torque.png"}));
  const NamedPlot& torque = plot_named(plots, "reaction_weld_torque_ground.png");
  EXPECT_EQ(torque.spec.y_label, "torque [N m]");
  EXPECT_NE(torque.caption.find("about the joint point"), std::string::npos);
  ASSERT_EQ(torque.spec.curves.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    for (Eigen::Index k = 0; k < data.sample_count(); ++k) {
      EXPECT_EQ(torque.spec.curves[c].y(k), data.joints[0].torque_ground(k, c));
      EXPECT_DOUBLE_EQ(torque.spec.curves[c].y(k), data.results.time(k) * (4.0 + c));
    }
  }
}

}  // namespace
}  // namespace limber::report
