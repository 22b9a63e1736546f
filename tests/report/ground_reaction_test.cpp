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
#include <cmath>
#include <cstdlib>
#include <numbers>

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
  PlotOptions both;
  both.frames = {ReactionFrame::kGround, ReactionFrame::kJoint};
  const std::vector<NamedPlot> plots = run_plots(data, "run1_", both);

  // Ground axes, then joint frame (as asked); no torque plots (the torques are zero).
  EXPECT_EQ(reaction_files(plots),
            (std::vector<std::string>{"run1_reaction_R3_force_ground.png", "run1_reaction_R3_force.png"}));
  const NamedPlot& ground = plot_named(plots, "run1_reaction_R3_force_ground.png");
  EXPECT_NE(ground.caption.find("ground axes (X = ground x, Y = ground y, Z = ground z)"),
            std::string::npos)
      << ground.caption;
  EXPECT_NE(ground.caption.find("joint R3 on slider"), std::string::npos) << ground.caption;
  EXPECT_EQ(ground.spec.y_label, "force [N]");
  // X, Y, Z, then the magnitude |F|, the norm of each stored row.
  ASSERT_EQ(ground.spec.curves.size(), 4u);
  EXPECT_EQ(ground.spec.curves[3].label, "|F|");
  for (int k = 0; k < run.samples; ++k) {
    EXPECT_DOUBLE_EQ(ground.spec.curves[3].y(k), data.joints[0].force_ground.row(k).norm());
  }

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
  options.frames = {"ground", "joint"};
  const std::string html = testing::read_text(generate_report(options).index);
  const std::size_t ground_at = html.find("src=\"images/run1_reaction_R3_force_ground.png\"");
  const std::size_t joint_at = html.find("src=\"images/run1_reaction_R3_force.png\"");
  ASSERT_NE(ground_at, std::string::npos);
  ASSERT_NE(joint_at, std::string::npos);
  EXPECT_LT(ground_at, joint_at);
  EXPECT_NE(html.find("<figcaption>Reaction force at joint R3 on slider, components in ground axes "
                      "(X = ground x, Y = ground y, Z = ground z), and its magnitude |F|. "
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
  PlotOptions both;
  both.frames = {ReactionFrame::kGround, ReactionFrame::kJoint};
  const std::vector<NamedPlot> plots = run_plots(data, "", both);
  EXPECT_EQ(reaction_files(plots),
            (std::vector<std::string>{"reaction_weld_force_ground.png", "reaction_weld_torque_ground.png",
                                      "reaction_weld_force.png", "reaction_weld_torque.png"}));
  const NamedPlot& torque = plot_named(plots, "reaction_weld_torque_ground.png");
  EXPECT_EQ(torque.spec.y_label, "torque [N m]");
  EXPECT_NE(torque.caption.find("about the joint point"), std::string::npos);
  ASSERT_EQ(torque.spec.curves.size(), 4u);  // and |T|
  for (int c = 0; c < 3; ++c) {
    for (Eigen::Index k = 0; k < data.sample_count(); ++k) {
      EXPECT_EQ(torque.spec.curves[c].y(k), data.joints[0].torque_ground(k, c));
      EXPECT_DOUBLE_EQ(torque.spec.curves[c].y(k), data.results.time(k) * (4.0 + c));
    }
  }
}

TEST(GroundReactionPlots, NoiseIsListedAsZeroAndMinimumNormReactionsSayTheyAreIndeterminate) {
  unsetenv("DISPLAY");
  // Joint "R2": ground force (1000 sin 2πt, 1e-9 cos 2πt, 500 cos 2πt) N, flagged minimum-norm
  // at every sample, its equation x redundant with R1's x (a force equation, so the force is
  // what is indeterminate); joint "R1" not flagged: determined.
  const auto dir = testing::fresh_directory("indeterminate");
  {
    results::ResultsWriter writer(dir, "redundant", "ground_reaction_test.cpp");
    writer.add_rigid_body({"rod", {}});
    writer.add_joint({"R1", "revolute", "ground", "rod"});
    writer.add_joint({"R2", "revolute", "ground", "rod"});
    writer.set_redundant_equations({"R2.x"}, {"R1.x"});
    for (int k = 0; k <= 100; ++k) {
      results::Sample sample;
      sample.time = 0.01 * k;
      sample.bodies.emplace_back();
      const double w = 2.0 * std::numbers::pi * sample.time;
      results::JointSample r1, r2;
      r1.force_ground = r1.force_joint = Eigen::Vector3d(1.0, 2.0, 3.0);
      r2.force_ground = r2.force_joint = Eigen::Vector3d(1000.0 * std::sin(w), 1e-9 * std::cos(w), 500.0 * std::cos(w));
      r2.torque_ground = r2.torque_joint = Eigen::Vector3d(1e-6, 1e-6, 1e-6);  // noise
      r1.torque_ground = r1.torque_joint = Eigen::Vector3d(0.0, 0.0, 0.1);      // a real one
      r2.indeterminate = true;
      sample.joints = {r1, r2};
      writer.append_sample(sample);
    }
    writer.finish(results::RunStatus::kOk);
  }
  const RunData data = read_run_data(dir);
  const std::vector<NamedPlot> plots = run_plots(data, "");
  const NamedPlot& r2 = plot_named(plots, "reaction_R2_force_ground.png");
  // Y's peak is 1e-12 of X's, below the default 1e-4: listed, not drawn.
  ASSERT_EQ(r2.spec.curves.size(), 3u);
  EXPECT_EQ(r2.spec.curves[0].label, "X");
  EXPECT_EQ(r2.spec.curves[1].label, "Z");
  EXPECT_NE(r2.caption.find("Not drawn, below 0.0001 of the largest component: Y ≈ 0 (peak 1e-09 N)."),
            std::string::npos)
      << r2.caption;
  // Its CSV keeps every component, Y flagged in the comment: the columns do not depend on the
  // data (a script reading "Y [N]" finds it whether or not Y is drawn).
  ASSERT_EQ(r2.csv_curves.size(), 4u);
  EXPECT_EQ(r2.csv_curves[1].label, "Y");
  EXPECT_EQ(r2.csv_curves[1].y(0), 1e-9);
  EXPECT_EQ(r2.csv_comment, "not drawn, ≈ 0 (below 0.0001 of the largest component): Y");
  // The markers were left at identity (ground axes), so R2.x leaves only ground X undetermined
  // (report/indeterminate_components.h).
  EXPECT_NE(r2.warning.find("Indeterminate: joint R2 is in a redundant set of constraints (R2.x "
                            "depends on R1.x). The component X of its reaction force is the "
                            "minimum-norm split"),
            std::string::npos)
      << r2.warning;
  EXPECT_NE(r2.spec.title.find("minimum-norm"), std::string::npos);
  // R2's torque, 1.7e-6 N m, is below 1e-4 x its peak force 1000 N x 1 m (both joints at the
  // origin: the 1 m default lever): a line in the caption, no plot. R1's 0.1 N m is above
  // 1e-4 x 3.74 N x 1 m: plotted.
  EXPECT_NE(r2.caption.find("Reaction torque ≈ 0 (peak |T| 1.73e-06 N m, below 0.0001 × the peak "
                            "|F| 1000 N × the mechanism's size 1 m): not drawn."),
            std::string::npos)
      << r2.caption;
  EXPECT_EQ(reaction_files(plots),
            (std::vector<std::string>{"reaction_R1_force_ground.png", "reaction_R1_torque_ground.png",
                                      "reaction_R2_force_ground.png"}));
  EXPECT_TRUE(plot_named(plots, "reaction_R1_force_ground.png").warning.empty());
  // The same decision per component and frame, as the selection ranking asks it: in the rod's
  // axes (identity here) only the force x; the torque and the other joint determined.
  EXPECT_TRUE(is_indeterminate_component(data, "R2", "rod", false, 0));
  EXPECT_FALSE(is_indeterminate_component(data, "R2", "rod", false, 1));
  EXPECT_FALSE(is_indeterminate_component(data, "R2", "rod", true, 0));
  EXPECT_FALSE(is_indeterminate_component(data, "R1", "ground", false, 0));
  EXPECT_FALSE(is_indeterminate_component(data, "R9", "rod", false, 0));
  EXPECT_EQ(plot_named(plots, "reaction_R1_force_ground.png").csv_comment,
            "not drawn, ≈ 0 (below 0.0001 of the largest component): none");
  // A rotation equation in the set makes the torque, not the force, indeterminate.
  RunData rotation = data;
  rotation.redundant_equations = {{"R2.rot_x", "R1.rot_x"}};
  const Indeterminacy which = indeterminacy(rotation, rotation.joints[1]);
  EXPECT_FALSE(which.force);
  EXPECT_TRUE(which.torque);
  EXPECT_EQ(which.sets, "R2.rot_x depends on R1.rot_x");

  // On the page: the note beside the plot, and the joints table says which is which.
  ReportOptions options;
  options.directories = {dir};
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  EXPECT_NE(html.find("<p class=\"plot-warning\" role=\"note\">Indeterminate: joint R2"), std::string::npos);
  EXPECT_NE(html.find("<td>R2</td><td>revolute</td><td>ground</td><td>rod</td><td class=\"indeterminate\">"
                      "force X minimum-norm (indeterminate, ground axes; other components "
                      "determined)</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>R1</td><td>revolute</td><td>ground</td><td>rod</td><td>determined</td>"),
            std::string::npos);
}

TEST(GroundReactionPlots, AxisNamesAndDriverUnitsComeFromTheFile) {
  unsetenv("DISPLAY");
  // The case named its axes (root attribute axis_names) and the writer gave each driver its
  // unit; force (1, 2, 3) N on joint "pin", a rotation driver and a translation driver.
  const auto dir = testing::fresh_directory("axis_names");
  {
    results::ResultsWriter writer(dir, "named axes", "ground_reaction_test.cpp");
    writer.set_axis_names({"X (rail)", "Y (pin)", "Z (up)"});
    writer.add_rigid_body({"arm", {}});
    writer.add_joint({"pin", "revolute", "ground", "arm"});
    writer.add_driver("motor", "N m");
    writer.add_driver("jack", "N");
    for (int k = 0; k <= 4; ++k) {
      results::Sample sample;
      sample.time = 0.25 * k;
      sample.bodies.emplace_back();
      results::JointSample pin;
      pin.force_ground = pin.force_joint = Eigen::Vector3d(1.0, 2.0, 3.0);
      sample.joints = {pin};
      sample.driver_efforts = {1.0, 2.0};
      writer.append_sample(sample);
    }
    writer.finish(results::RunStatus::kOk);
  }
  const RunData data = read_run_data(dir);
  EXPECT_TRUE(data.axis_names_from_case);
  const std::vector<NamedPlot> plots = run_plots(data, "");
  const NamedPlot& force = plot_named(plots, "reaction_pin_force_ground.png");
  ASSERT_EQ(force.spec.curves.size(), 4u);
  EXPECT_EQ(force.spec.curves[0].label, "X (rail)");
  EXPECT_EQ(force.spec.curves[2].label, "Z (up)");
  EXPECT_NE(force.caption.find("ground axes (X (rail) = ground x, Y (pin) = ground y, Z (up) = "
                               "ground z, names from the case)"),
            std::string::npos)
      << force.caption;
  // One effort plot per unit.
  EXPECT_EQ(plot_named(plots, "driver_efforts_N_m.png").spec.y_label, "effort [N m]");
  EXPECT_EQ(plot_named(plots, "driver_efforts_N.png").spec.y_label, "effort [N]");
  EXPECT_EQ(plot_named(plots, "driver_efforts_N_m.png").spec.curves[0].label, "motor");
}

// Two runs probing the same body (the seed set-up, linear and stiffened): the probe's
// in-plane component is overlaid, one curve per run holding the stored values; its ≈ 0
// components (1e-9 of the largest) and the runs without the probe are left out.
TEST(ComparisonPlots, DeflectionProbesOfTheSameBodyAreOverlaid) {
  const Eigen::Index ns = 11;
  RunData linear, stiffened, rigid;
  for (RunData* run : {&linear, &stiffened, &rigid}) {
    run->results.time = Eigen::VectorXd::LinSpaced(ns, 0.0, 1.0);
  }
  const auto probe = [&](double amplitude) {
    DeflectionProbe p;
    p.body = "rod";
    p.values = RowMatrix3d::Zero(ns, 3);
    for (Eigen::Index k = 0; k < ns; ++k) {
      p.values(k, 0) = 1e-9 * amplitude;
      p.values(k, 2) = amplitude * std::sin(0.3 * static_cast<double>(k));
    }
    return p;
  };
  linear.deflections.push_back(probe(0.062));
  stiffened.deflections.push_back(probe(0.038));
  const std::vector<NamedPlot> plots =
      comparison_plots({linear, stiffened, rigid}, {"linear", "stiffened", "rigid"}, PlotOptions{});
  std::vector<const NamedPlot*> probes;
  for (const NamedPlot& plot : plots) {
    if (plot.file.rfind("compare_probe_", 0) == 0) probes.push_back(&plot);
  }
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0]->file, "compare_probe_rod_z.png");
  EXPECT_EQ(probes[0]->section, PlotSection::kComparison);
  ASSERT_EQ(probes[0]->spec.curves.size(), 2u);
  EXPECT_EQ(probes[0]->spec.curves[0].label, "linear");
  EXPECT_EQ(probes[0]->spec.curves[1].label, "stiffened");
  EXPECT_EQ(probes[0]->spec.curves[0].y, linear.deflections[0].values.col(2));
  EXPECT_EQ(probes[0]->spec.curves[1].y, stiffened.deflections[0].values.col(2));
}

}  // namespace
}  // namespace limber::report
