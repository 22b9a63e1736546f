// The report's first screen and its figures' legibility (issue 28): curves lying on each other
// are told apart (plot descriptions, chart JSON and PNG pixels), the summary's numbers (peak
// reactions, accuracy against thresholds, releases, the seed's figures) on a run of known
// reactions, the page order (summary before the contents and the runs), and `--frame` leaving
// the directory to the positional argument.
#include "cli/help_wrap.h"
#include "curve_export.h"
#include "curve_styles.h"
#include "decimate.h"
#include "plot.h"
#include "plot_set.h"
#include "reaction_runs.h"
#include "report_command.h"
#include "report_job.h"
#include "report_test_util.h"
#include "run_data.h"
#include "run_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace limber::report {
namespace {

using testing::fresh_directory;
using testing::read_text;

Eigen::VectorXd linspace(int n, double a, double b) { return Eigen::VectorXd::LinSpaced(n, a, b); }

// A plot of a sine and copies of it: the symmetric wings' R1 and R2.
PlotSpec sine_plot(int copies, double offset_of_last = 0.0) {
  PlotSpec plot{"hinges", "time [s]", "angle [deg]", {}, false};
  const Eigen::VectorXd t = linspace(201, 0.0, 2.0);
  const Eigen::VectorXd y = (2.0 * std::numbers::pi * t).array().sin() * 90.0;
  for (int k = 0; k < copies; ++k) {
    Eigen::VectorXd yk = y;
    if (k == copies - 1) yk.array() += offset_of_last;
    plot.curves.push_back({"R" + std::to_string(k + 1), t, yk});
  }
  return plot;
}

TEST(CurveStyles, CoincidingCurvesAreDashedAndSaid) {
  // Identical curves: the later one dashed, the note names both.
  PlotSpec plot = sine_plot(2);
  const std::string note = distinguish_coinciding_curves(plot);
  EXPECT_EQ(note, "R1 ≡ R2 (to 1e-9)");
  EXPECT_EQ(plot.curves[0].style, LineStyle::kSolid);
  EXPECT_EQ(plot.curves[1].style, LineStyle::kDashed);

  // Three on one another: solid, dashed, dotted, one group in the note.
  PlotSpec three = sine_plot(3);
  EXPECT_EQ(distinguish_coinciding_curves(three), "R1 ≡ R2 ≡ R3 (to 1e-9)");
  EXPECT_EQ(three.curves[2].style, LineStyle::kDotted);

  // 1e-10 of the 180-deg range apart coincide; 1e-5 apart (visible when zoomed, not in the
  // figure) lie within a pixel: dashed and "≈"; 1e-2 apart (6 pixels of 600) are left alone.
  PlotSpec close = sine_plot(2, 180.0 * 1e-10);
  EXPECT_EQ(distinguish_coinciding_curves(close), "R1 ≡ R2 (to 1e-9)");
  PlotSpec near = sine_plot(2, 180.0 * 1e-5);
  EXPECT_EQ(distinguish_coinciding_curves(near),
            "R1 ≈ R2 (≡ to 1e-9, ≈ to 0.001 of the plot's range: under a pixel)");
  EXPECT_EQ(near.curves[1].style, LineStyle::kDashed);
  PlotSpec apart = sine_plot(2, 180.0 * 1e-2);
  EXPECT_EQ(distinguish_coinciding_curves(apart), "");
  EXPECT_EQ(apart.curves[1].style, LineStyle::kSolid);

  // Curves at 0 beside a sine: "≡ 0".
  PlotSpec zeros = sine_plot(1);
  zeros.curves.push_back({"eta1", zeros.curves[0].x, Eigen::VectorXd::Zero(201)});
  zeros.curves.push_back({"eta3", zeros.curves[0].x, Eigen::VectorXd::Constant(201, 1e-12)});
  EXPECT_EQ(distinguish_coinciding_curves(zeros), "eta1 ≡ eta3 ≡ 0 (to 1e-9)");

  // Other sample times: not compared.
  PlotSpec shifted = sine_plot(2);
  shifted.curves[1].x.array() += 1e-3;
  EXPECT_TRUE(coinciding_curves(shifted).empty());
}

// No two curves of a plot within a pixel of each other (1e-3 of the range) are drawn in the
// same colour and line style.
void expect_told_apart(const PlotSpec& plot) {
  for (const Coincidence& c : coinciding_curves(plot, 1e-3)) {
    const Curve& a = plot.curves[c.first];
    const Curve& b = plot.curves[c.later];
    EXPECT_FALSE(curve_color(a, c.first) == curve_color(b, c.later) && a.style == b.style)
        << plot.title << ": " << a.label << " and " << b.label << " coincide and look alike";
    EXPECT_NE(a.style, b.style) << plot.title << ": " << a.label << " hides " << b.label;
  }
}

TEST(CurveStyles, ComparisonOfTwoEqualRunsDashesTheLaterRun) {
  // Two runs of one case: every comparison overlay has two coinciding curves.
  const auto dir = fresh_directory("summary_equal_runs");
  testing::ReactionRun spec;
  testing::write_reaction_run(dir / "a", spec);
  testing::write_reaction_run(dir / "b", spec);
  const std::vector<RunData> runs{read_run_data(dir / "a"), read_run_data(dir / "b")};
  const std::vector<NamedPlot> plots = comparison_plots(runs, {"run 1: a", "run 2: b"});
  ASSERT_FALSE(plots.empty());
  for (const NamedPlot& plot : plots) {
    ASSERT_EQ(plot.spec.curves.size(), 2u) << plot.file;
    EXPECT_EQ(plot.coincidence, "run 1: a ≡ run 2: b (to 1e-9)") << plot.file;
    EXPECT_EQ(plot.spec.curves[1].style, LineStyle::kDashed) << plot.file;
    expect_told_apart(plot.spec);
    // The interactive chart gets the same dash pattern.
    const std::string json = curve_json(plot.spec, curve_table(plot.spec.curves));
    EXPECT_NE(json.find("\"dashes\":[null,[10,6]]"), std::string::npos) << plot.file;
    // The earlier run drawn wider (2 px), so the later one leaves it visible when close.
    EXPECT_EQ(plot.spec.curves[0].extra_width, 2.0f) << plot.file;
    EXPECT_EQ(plot.spec.curves[1].extra_width, 0.0f) << plot.file;
    EXPECT_NE(json.find("\"widths\":[3.5,1.5]"), std::string::npos) << plot.file;
  }
  // A run's own plots: every pair of coinciding curves told apart too.
  for (const NamedPlot& plot : run_plots(runs[0], "run1_")) expect_told_apart(plot.spec);
}

TEST(CurveStyles, DashedCurveLeavesTheOneBelowVisibleInThePng) {
  // Two identical horizontal lines in blue (first) and red (second): drawn solid, red covers
  // blue; dashed, blue shows in the gaps. Counted along the line's row band.
  PlotSpec plot{"two equal lines", "time [s]", "force [N]", {}, false};
  const Eigen::VectorXd t = linspace(50, 0.0, 1.0);
  plot.curves.push_back({"R1", t, Eigen::VectorXd::Constant(50, 1.0), 0});
  plot.curves.push_back({"R2", t, Eigen::VectorXd::Constant(50, 1.0), 1});
  plot.curves.push_back({"low", t, Eigen::VectorXd::Constant(50, 0.0), 2});
  const auto dir = fresh_directory("summary_dash_pixels");
  ChartCanvas canvas(900, 500);
  const auto count = [&](const PlotSpec& spec, const std::string& name, int color) {
    const PlotFrame frame = canvas.draw(spec, dir / name);
    const testing::Png png(dir / name);
    const Eigen::Vector2d left = frame.to_pixel(0.05, 1.0), right = frame.to_pixel(0.95, 1.0);
    int n = 0;
    for (int x = static_cast<int>(left.x()); x <= static_cast<int>(right.x()); ++x) {
      for (int y = static_cast<int>(left.y()) - 3; y <= static_cast<int>(left.y()) + 3; ++y) {
        const std::array<int, 3> p = png.pixel(x, y);
        const auto& c = kCurveColors[static_cast<std::size_t>(color)];
        // Within 40 per channel: the line's centre pixels carry its exact colour (plot_test).
        if (std::abs(p[0] - c[0]) <= 40 && std::abs(p[1] - c[1]) <= 40 && std::abs(p[2] - c[2]) <= 40) ++n;
      }
    }
    return n;
  };
  const int span = static_cast<int>(canvas.width() * 0.5);  // the line spans ~700 px of 900
  EXPECT_LT(count(plot, "solid.png", 0), span / 20) << "solid: the first line should be hidden";
  PlotSpec styled = plot;
  EXPECT_EQ(distinguish_coinciding_curves(styled), "R1 ≡ R2 (to 1e-9)");
  EXPECT_GT(count(styled, "dashed.png", 0), span / 4) << "dashed: the first line shows in the gaps";
  EXPECT_GT(count(styled, "dashed.png", 1), span / 4) << "dashed: the second line shows";
}

TEST(HelpWrap, WordsWrapAtTheWidthKeepingLineBreaks) {
  EXPECT_EQ(cli::wrap_words("aaa bbb ccc", 7), "aaa bbb\nccc");
  EXPECT_EQ(cli::wrap_words("aaa\nbbb ccc", 7), "aaa\nbbb ccc");
  EXPECT_EQ(cli::wrap_words("a verylongword b", 5), "a\nverylongword\nb");  // a long word stays whole
  EXPECT_EQ(cli::wrap_words("≈ 0 (peak …)", 12), "≈ 0 (peak …)");             // code points, not bytes
}

TEST(Summary, PeaksAccuracyAndReleasesOfAKnownRun) {
  const auto dir = fresh_directory("summary_digest");
  testing::ReactionRun spec;
  testing::write_reaction_run(dir / "run", spec);
  RunData run = read_run_data(dir / "run");
  // The accuracy measures as `limber run` stores them (root attributes).
  run.solver_attributes.emplace_back("accuracy_energy_relative", "8.12e-06");
  run.solver_attributes.emplace_back("accuracy_local_error", "0.00196");
  run.solver_attributes.emplace_back("accuracy_drift_relative", "0.0025");
  const RunDigest d = digest_run(run);
  ASSERT_EQ(d.accuracy.size(), 3u);
  EXPECT_EQ(d.accuracy[1].name, "local error");
  EXPECT_DOUBLE_EQ(d.accuracy[1].value, 0.00196);
  EXPECT_DOUBLE_EQ(d.accuracy[1].threshold, 0.01);
  EXPECT_TRUE(d.accuracy[1].passed());
  EXPECT_FALSE(d.accuracy[2].passed());  // drift 0.0025 above 0.001

  // An IDA run stores its local error as 0 (IDA has no second estimate, docs/integrators.md):
  // the digest leaves that row out instead of showing 0 against the threshold.
  run.solver_attributes.emplace_back("integrator", "ida");
  const RunDigest ida = digest_run(run);
  ASSERT_EQ(ida.accuracy.size(), 2u);
  EXPECT_EQ(ida.accuracy[0].name, "energy balance");
  EXPECT_EQ(ida.accuracy[1].name, "constraint drift");
  run.solver_attributes.pop_back();

  // The joint's peak |F| is the largest |G(t_k)| over the samples, at its time.
  ASSERT_EQ(d.peaks.size(), 1u);
  double peak = 0.0, at = 0.0;
  for (int k = 0; k < spec.samples; ++k) {
    const double t = k * spec.duration / (spec.samples - 1);
    const double f = testing::reaction_force_ground(spec, t).norm();
    if (f > peak) {
      peak = f;
      at = t;
    }
  }
  EXPECT_EQ(d.peaks[0].joint, "R3");
  EXPECT_NEAR(d.peaks[0].force, peak, 1e-12 * peak);  // the stored doubles, norm rounding only
  EXPECT_DOUBLE_EQ(d.peaks[0].force_time, at);
  EXPECT_TRUE(d.releases.empty());  // loaded to the end: not released
  EXPECT_FALSE(d.acceleration_g);   // no probes

  // A probe at 1 g in x with a 3 g z-peak at sample 50: 3.1623 g (|(1, 0, 3)| g) there.
  RunData probed = run;
  AccelerationProbeTrack probe;
  probe.name = "tip";
  probe.acceleration.setZero(spec.samples, 3);
  probe.acceleration.col(0).setConstant(9.80665);
  probe.acceleration(50, 2) = 3.0 * 9.80665;
  probed.acceleration_probes.push_back(probe);
  const RunDigest a = digest_run(probed);
  ASSERT_TRUE(a.acceleration_g);
  EXPECT_NEAR(*a.acceleration_g, std::sqrt(10.0), 1e-12);
  EXPECT_DOUBLE_EQ(a.acceleration_time, probed.results.time(50));
  EXPECT_EQ(a.acceleration_probe, "tip");

  // A joint whose reaction is 0 from sample 40 on is listed as released there.
  RunData released = run;
  released.joints[0].force_ground.bottomRows(spec.samples - 40).setZero();
  released.joints[0].force_joint.bottomRows(spec.samples - 40).setZero();
  const RunDigest r = digest_run(released);
  ASSERT_EQ(r.releases.size(), 1u);
  EXPECT_DOUBLE_EQ(r.releases[0].time, released.results.time(40));
  EXPECT_EQ(r.releases[0].joints, std::vector<std::string>{"R3"});
  // ...but not while its torque still carries load.
  RunData held = released;
  held.joints[0].torque_ground.setConstant(1.0);
  EXPECT_TRUE(digest_run(held).releases.empty());

  // The section says each measure against its threshold, with the peak in newtons.
  ReportContent content;
  RunSection section;
  section.run = &run;
  section.label = "run 1: run";
  section.anchor = "run1";
  content.runs.push_back(section);
  const std::string html = summary_section(content);
  EXPECT_NE(html.find("local error 0.00196 of the allowed 0.01"), std::string::npos);
  EXPECT_NE(html.find("constraint drift 0.0025 of the allowed 0.001"), std::string::npos);
  EXPECT_NE(html.find("peak |F| [N]"), std::string::npos);
  EXPECT_NE(html.find("<td>R3</td>"), std::string::npos);
  EXPECT_NE(html.find("badge ok"), std::string::npos);
}

TEST(Summary, FailedAndInaccurateRunsGetTheirBadge) {
  const auto dir = fresh_directory("summary_badges");
  testing::ReactionRun failed;
  failed.status = "failed";
  failed.message = "Newton did not converge at t = 0.5 s";
  testing::write_reaction_run(dir / "failed", failed);
  testing::write_reaction_run(dir / "ok", {});
  RunData failed_run = read_run_data(dir / "failed");
  RunData inaccurate = read_run_data(dir / "ok");
  inaccurate.results.status = "ok_inaccurate";
  inaccurate.solver_attributes.emplace_back("accuracy_local_error", "0.013");
  inaccurate.solver_attributes.emplace_back("accuracy_warnings", "local error 1.3 % (use --step h/4)");
  ReportContent content;
  for (RunData* run : {&failed_run, &inaccurate}) {
    RunSection section;
    section.run = run;
    section.label = run == &failed_run ? "run 1: failed" : "run 2: ok";
    section.anchor = run == &failed_run ? "run1" : "run2";
    content.runs.push_back(section);
  }
  const std::string html = summary_section(content);
  EXPECT_NE(html.find("<span class=\"badge failed\">failed</span>"), std::string::npos);
  EXPECT_NE(html.find("Newton did not converge at t = 0.5 s"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"badge inaccurate\">ok_inaccurate</span>"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"fail\">local error 0.013 of the allowed 0.01</span>"), std::string::npos);
  EXPECT_NE(html.find("use --step h/4"), std::string::npos);
}

TEST(Summary, SeedFigureLinksPointAtTheirPlots) {
  const auto dir = fresh_directory("summary_seed_links");
  testing::write_reaction_run(dir / "run", {});
  RunData run = read_run_data(dir / "run");
  run.results.case_file = "cases/satellite_deployment.yaml";
  ReportContent content;
  RunSection section;
  section.run = &run;
  section.label = "run 1: sat";
  section.anchor = "run1";
  WrittenPlot r1;
  r1.plot.file = "run1_reaction_R1_force_ground.png";
  r1.plot.kind = PlotKind::kReaction;
  r1.plot.subject = "R1";
  section.plots.push_back(r1);
  content.runs.push_back(section);
  // Two overlays of R1: Fig. 10 is the dominant component's (peak 30 N against 10 N).
  const Eigen::VectorXd t = linspace(3, 0.0, 1.0);
  WrittenPlot small, large;
  small.plot.file = "compare_R1_ground_y.png";
  small.plot.spec.curves.push_back({"run 1", t, Eigen::Vector3d(0.0, -10.0, 5.0)});
  large.plot.file = "compare_R1_ground_z.png";
  large.plot.spec.curves.push_back({"run 1", t, Eigen::Vector3d(0.0, 30.0, 5.0)});
  content.comparisons.push_back(small);
  content.comparisons.push_back(large);
  const std::vector<SeedFigureLink> links = seed_figure_links(content);
  ASSERT_EQ(links.size(), 2u);
  EXPECT_EQ(links[0].figure, "Fig. 9");
  EXPECT_EQ(links[0].target, "fig-run1_reaction_R1_force_ground");
  EXPECT_EQ(links[1].figure, "Fig. 10");
  EXPECT_EQ(links[1].target, "fig-compare_R1_ground_z");
  // A case of neither scene: no links.
  run.results.case_file = "cases/four_bar.yaml";
  EXPECT_TRUE(seed_figure_links(content).empty());
}

TEST(Summary, ComesFirstAndFrameLeavesTheDirectory) {
  // `limber report --frame joint DIR`: DIR is the positional argument, not a second frame.
  const auto dir = fresh_directory("summary_cli");
  testing::write_reaction_run(dir / "run", {});
  CLI::App app{"limber"};
  const cli::Command report = add_report_command(app);
  const std::string run_dir = (dir / "run").string(), out = (dir / "out").string();
  std::vector<std::string> args{"report", "--frame", "joint", run_dir, "-o", out, "--no-mode-shapes"};
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector in reverse order
  ASSERT_NO_THROW(app.parse(args));
  ASSERT_EQ(report.run(), cli::kExitOk);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "images" / "run1_reaction_R3_force.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "images" / "run1_reaction_R3_force_ground.png"));

  // The summary before the contents, the contents before the run's sections.
  const std::string page = read_text(dir / "out" / "index.html");
  const std::size_t summary = page.find("<section id=\"summary\">");
  const std::size_t nav = page.find("<nav>");
  const std::size_t section = page.find("<section id=\"run1\">");
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(summary, nav);
  EXPECT_LT(nav, section);
  EXPECT_LT(page.find("peak |F| [N]"), nav);
}

}  // namespace
}  // namespace limber::report
