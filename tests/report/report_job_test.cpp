// Reports of known results: files, links, sections, plot pixels, escaping, failed and
// unfinished runs, comparisons, media, and bad input.
#include "report_job.h"

#include "animation_media.h"
#include "core/error.h"
#include "html.h"
#include "plot.h"
#include "plot_set.h"
#include "reaction_runs.h"
#include "report_command.h"
#include "report_test_util.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace limber::report {
namespace {

using render::testing::TestScene;
using testing::ReactionRun;

// Options for fast tests: small mode pictures.
ReportOptions options_for(std::vector<std::filesystem::path> dirs) {
  ReportOptions o;
  o.directories = std::move(dirs);
  o.mode_image_width = 240;
  o.mode_image_height = 160;
  return o;
}

// Every link of the page that is not an anchor resolves to an existing file inside the report
// folder, and none is remote.
void expect_links_resolve(const std::filesystem::path& index) {
  const std::string html = testing::read_text(index);
  int files = 0;
  for (const std::string& link : testing::links(html)) {
    ASSERT_FALSE(link.empty());
    if (link[0] == '#') continue;
    EXPECT_EQ(link.find("//"), std::string::npos) << "remote or absolute link " << link;
    EXPECT_EQ(link.find(".."), std::string::npos) << "link out of the report folder " << link;
    // Undo the percent-encoding of relative_url.
    std::string path;
    for (std::size_t k = 0; k < link.size(); ++k) {
      if (link[k] == '%' && k + 2 < link.size()) {
        path += static_cast<char>(std::stoi(link.substr(k + 1, 2), nullptr, 16));
        k += 2;
      } else {
        path += link[k];
      }
    }
    EXPECT_TRUE(std::filesystem::is_regular_file(index.parent_path() / path)) << link;
    ++files;
  }
  EXPECT_GT(files, 0);
}

class ReportJobTest : public ::testing::Test {
 protected:
  void SetUp() override { unsetenv("DISPLAY"); }
};

TEST_F(ReportJobTest, SceneReportHasSectionsAndOnlyLinksToExistingFiles) {
  const auto dir = testing::fresh_directory("scene");
  TestScene scene;
  scene.samples = 41;
  render::testing::write_test_results(dir, scene);
  const ReportSummary summary = generate_report(options_for({dir}));

  EXPECT_EQ(summary.index, dir / "report" / "index.html");
  ASSERT_TRUE(std::filesystem::is_regular_file(summary.index));
  expect_links_resolve(summary.index);
  const std::string html = testing::read_text(summary.index);
  for (const char* section : {"run1-summary", "run1-reactions", "run1-deflection",
                              "run1-animation", "run1-mode-shapes"}) {
    EXPECT_NE(html.find(std::string("id=\"") + section + "\""), std::string::npos) << section;
  }
  // Bodies with mesh sizes: plate 21 x 13 nodes, 240 quads; beam 21 nodes, 20 lines.
  EXPECT_NE(html.find("<td>plate0</td><td>flexible</td><td class=\"number\">273</td>"
                      "<td class=\"number\">0</td><td class=\"number\">240</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>beam</td><td>flexible</td><td class=\"number\">21</td>"
                      "<td class=\"number\">20</td>"),
            std::string::npos);
  // Mode table from results.h5 (frequencies 12 and 30 Hz), modes drawn (2 + 2).
  EXPECT_NE(html.find("Modes of plate0"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"number\">30</td>"), std::string::npos);
  EXPECT_EQ(summary.mode_images, 4);
  // No banner for a finished run (the plotting library is installed: install-deps.sh); the
  // only scripts are the library, the chart code and one JSON block per plot.
  ASSERT_TRUE(summary.interactive) << "libjs-dygraphs missing: run scripts/install-deps.sh";
  EXPECT_EQ(html.find("class=\"banner"), std::string::npos);
  const std::string json_open = "<script type=\"application/json\" id=\"";
  std::size_t scripts = 0, json = 0;
  for (std::size_t at = html.find("<script"); at != std::string::npos; at = html.find("<script", at + 1)) {
    ++scripts;
    if (html.compare(at, json_open.size(), json_open) == 0) ++json;
  }
  EXPECT_EQ(json, static_cast<std::size_t>(summary.plots));
  EXPECT_EQ(scripts, json + 2);
}

// A report mailed or moved elsewhere still opens: every link is relative to the report folder,
// so the page's files resolve from its new place, without the run folder beside it.
TEST_F(ReportJobTest, ReportFolderMovedElsewhereKeepsEveryLink) {
  const auto dir = testing::fresh_directory("moved_from");
  TestScene scene;
  scene.samples = 11;
  render::testing::write_test_results(dir, scene);
  generate_report(options_for({dir}));
  const auto target = testing::fresh_directory("moved_to") / "mailed_report";
  std::filesystem::rename(dir / "report", target);
  std::filesystem::remove_all(dir);
  expect_links_resolve(target / "index.html");
}

TEST_F(ReportJobTest, ModalCoordinatePlotShowsTheBeamsClosedForm) {
  const auto dir = testing::fresh_directory("scene_plot");
  TestScene scene;
  scene.samples = 41;
  render::testing::write_test_results(dir, scene);
  ReportOptions options = options_for({dir});
  options.mode_shapes = false;
  generate_report(options);

  // The beam's plot in the report; its axes from drawing the same plot again (deterministic).
  const RunData run = read_run_data(dir);
  const std::vector<NamedPlot> plots = run_plots(run, "run1_");
  const auto beam = std::find_if(plots.begin(), plots.end(),
                                 [](const NamedPlot& p) { return p.file == "run1_modal_beam.png"; });
  ASSERT_NE(beam, plots.end());
  PlotFrame frame;
  {
    ChartCanvas canvas(options.plot_width, options.plot_height);
    frame = canvas.draw(beam->spec, testing::fresh_directory("scene_plot_again") / "beam.png");
  }
  const testing::Png png(dir / "report" / "images" / "run1_modal_beam.png");
  ASSERT_EQ(png.width, options.plot_width);
  // The plot's height and, below it, the legend's two rows (eta1, eta2).
  ASSERT_EQ(png.height, options.plot_height + 2 * kLegendRowPixels + kLegendPadding);
  // eta = B (sin, cos)(2 pi f t), B = 0.05: in steps of 0.02 the axis spans [-0.06, 0.06].
  EXPECT_NEAR(frame.y_min, -0.06, 1e-15);
  EXPECT_NEAR(frame.y_max, 0.06, 1e-15);

  // Each curve's colour near the closed form at every 4th sample (plot_test.cpp's tolerances:
  // 3 px, 40 per channel).
  for (int k = 0; k < scene.samples; k += 4) {
    const double t = scene.duration * k / (scene.samples - 1);
    const Eigen::Vector2d eta = render::testing::beam_eta(scene, t);
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector2d at = frame.to_pixel(t, eta(i));
      EXPECT_TRUE(testing::color_near(png, at.x(), at.y(), kCurveColors[i]))
          << "eta" << i + 1 << " at t = " << t;
    }
  }
}

TEST_F(ReportJobTest, CaseTitleWithMarkupIsEscaped) {
  const auto dir = testing::fresh_directory("escape");
  TestScene scene;
  scene.title = "<script>alert('x')</script> & co";
  scene.with_beam = false;
  render::testing::write_test_results(dir, scene);
  ReportOptions options = options_for({dir});
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("<h1>&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; co</h1>"),
            std::string::npos);
}

TEST_F(ReportJobTest, FailedRunShowsBannerAndWhatExists) {
  const auto dir = testing::fresh_directory("failed");
  ReactionRun run;
  run.status = "failed";
  run.message = "Newton failed at t = 0.5 s <step too small>";
  write_reaction_run(dir, run);
  const ReportSummary summary = generate_report(options_for({dir}));
  const std::string html = testing::read_text(summary.index);
  EXPECT_NE(html.find("<div class=\"banner failed\" role=\"alert\">This run failed: Newton failed "
                      "at t = 0.5 s &lt;step too small&gt; The report shows the 101 samples"),
            std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "report/images/run1_reaction_R3_force_ground.png"));
  ASSERT_EQ(summary.runs_not_ok.size(), 1u);
  expect_links_resolve(summary.index);
}

TEST_F(ReportJobTest, RunFailedAtAssemblyHasNoSamplesAndStillReports) {
  const auto dir = testing::fresh_directory("failed_at_assembly");
  ReactionRun run;
  run.samples = 0;
  run.status = "failed";
  run.message = "assembly did not converge";
  write_reaction_run(dir, run);
  const ReportSummary summary = generate_report(options_for({dir}));
  const std::string html = testing::read_text(summary.index);
  EXPECT_NE(html.find("This run failed: assembly did not converge No sample was written."),
            std::string::npos);
  // Nothing was sampled: the summary tables only, no plot.
  EXPECT_NE(html.find("id=\"run1-summary\""), std::string::npos);
  EXPECT_EQ(html.find("<img"), std::string::npos);
}

TEST_F(ReportJobTest, UnfinishedRunShowsRunningBanner) {
  const auto dir = testing::fresh_directory("running");
  ReactionRun run;
  run.status = "running";
  run.samples = 7;
  write_reaction_run(dir, run);
  const std::string html = testing::read_text(generate_report(options_for({dir})).index);
  EXPECT_NE(html.find("<div class=\"banner running\" role=\"alert\">This run did not finish"),
            std::string::npos);
  EXPECT_NE(html.find("The report shows the 7 samples written, up to t = 1 s."), std::string::npos);
}

TEST_F(ReportJobTest, SeveralRunsGetComparisonPlotsAndRunStatistics) {
  const auto root = testing::fresh_directory("compare");
  ReactionRun a, b;
  b.amplitude = 60.0;
  write_reaction_run(root / "normal_modes", a);
  write_reaction_run(root / "static_modes", b);
  ReportOptions options = options_for({root / "normal_modes", root / "static_modes"});
  options.output = root / "out";
  options.title = "R3 with two mode sets";
  const ReportSummary summary = generate_report(options);
  EXPECT_EQ(summary.index, root / "out" / "index.html");
  expect_links_resolve(summary.index);
  const std::string html = testing::read_text(summary.index);
  EXPECT_NE(html.find("id=\"comparison\""), std::string::npos);
  // Ground axes (the default frame) X, Y, Z.
  for (const char* c : {"x", "y", "z"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(root / "out/images" /
                                                 (std::string("compare_R3_ground_") + c + ".png")));
  }
  for (const char* s : {"run1-reactions", "run1-drivers", "run1-energy", "run1-violation",
                        "run2-reactions"}) {
    EXPECT_NE(html.find(std::string("id=\"") + s + "\""), std::string::npos) << s;
  }
  // Statistics: steps at the last sample (10 k, k = 100), largest violations 2e-10 and 2e-8.
  EXPECT_NE(html.find("<th>accepted steps</th><td>1000</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>largest position violation</th><td>2e-10</td>"), std::string::npos);
  EXPECT_NE(html.find("<th>largest velocity violation</th><td>2e-08</td>"), std::string::npos);
  EXPECT_NE(html.find("run 2: static_modes"), std::string::npos);
}

TEST_F(ReportJobTest, StillsStripAndVideoFromRenderOutputs) {
  const auto dir = testing::fresh_directory("media");
  ReactionRun run;
  write_reaction_run(dir, run);
  // Ten frames (any PNG will do) and a video, as `limber render` leaves them.
  ReportOptions first = options_for({dir});
  first.output = dir / "first";
  generate_report(first);
  std::filesystem::create_directories(dir / "frames");
  for (int k = 0; k < 10; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    std::filesystem::copy_file(dir / "first/images/run1_energy.png", dir / "frames" / name);
  }
  std::ofstream(dir / "animation.mp4") << "not a real video";

  const ReportSummary summary = generate_report(options_for({dir}));
  const std::string html = testing::read_text(summary.index);
  for (int k = 0; k < 6; ++k) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "report/images" /
                                                 ("run1_still_" + std::to_string(k) + ".png")));
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "report/images/run1_still_6.png"));
  // The video inside the report folder (zip and mail): same bytes as the run's.
  EXPECT_NE(html.find("src=\"media/run1_animation.mp4\""), std::string::npos);
  EXPECT_EQ(testing::read_text(dir / "report/media/run1_animation.mp4"), "not a real video");
  expect_links_resolve(summary.index);
}

TEST_F(ReportJobTest, EarlierReportsFilesAreRemovedOthersKept) {
  const auto dir = testing::fresh_directory("stale");
  write_reaction_run(dir, ReactionRun{});
  // What an earlier report (another frame, another run count) left, and a file of the user's.
  std::filesystem::create_directories(dir / "report/images");
  std::filesystem::create_directories(dir / "report/data");
  std::ofstream(dir / "report/images/run1_reaction_R3_force.png") << "old";
  std::ofstream(dir / "report/data/run2_energy.csv") << "old";
  std::ofstream(dir / "report/data/notes.csv") << "mine";
  ReportOptions options = options_for({dir});
  options.mode_shapes = false;
  generate_report(options);
  EXPECT_FALSE(std::filesystem::exists(dir / "report/images/run1_reaction_R3_force.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "report/data/run2_energy.csv"));
  EXPECT_EQ(testing::read_text(dir / "report/data/notes.csv"), "mine");
  EXPECT_TRUE(std::filesystem::exists(dir / "report/data/run1_reaction_R3_force_ground.csv"));
}

TEST(PickStills, FirstAndLastIncludedEvenlySpread) {
  std::vector<std::filesystem::path> frames;
  for (int k = 0; k < 11; ++k) frames.emplace_back(std::to_string(k));
  const auto stills = pick_stills(frames, 6);  // k (10/5) = 0, 2, 4, 6, 8, 10
  ASSERT_EQ(stills.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(stills[k], std::to_string(2 * k));
  EXPECT_EQ(pick_stills({frames[0], frames[1]}, 6).size(), 2u);
}

TEST_F(ReportJobTest, DirectoryWithoutResultsIsAnInputErrorAndWritesNothing) {
  const auto dir = testing::fresh_directory("missing");
  try {
    generate_report(options_for({dir}));
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("results.h5"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "report"));
}

TEST_F(ReportJobTest, OutputNamingAnExistingFileIsAnInputError) {
  // `limber report DIR -o FILE` was an internal error (exit 3); the file stays as it was.
  const auto dir = testing::fresh_directory("output_file");
  write_reaction_run(dir, ReactionRun{});
  const auto file = dir / "not_a_folder";
  std::ofstream(file) << "keep";
  ReportOptions options = options_for({dir});
  options.output = file;
  try {
    generate_report(options);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
  EXPECT_EQ(testing::read_text(file), "keep");
}

TEST_F(ReportJobTest, CommandParsesDirectoriesOutputAndTitle) {
  const auto dir = testing::fresh_directory("command");
  ReactionRun run;
  write_reaction_run(dir, run);
  CLI::App app;
  const cli::Command command = add_report_command(app);
  const std::string out = (dir / "page").string();
  // `report --title T -o OUT DIR`; CLI11 takes a vector of arguments in reverse order.
  std::vector<std::string> args = {dir.string(), out, "-o", "My <b>report</b>", "--title", "report"};
  app.parse(args);
  ASSERT_TRUE(command.cli->parsed());
  EXPECT_EQ(command.run(), 0);
  const std::string html = testing::read_text(dir / "page" / "index.html");
  EXPECT_NE(html.find("<h1>My &lt;b&gt;report&lt;/b&gt;</h1>"), std::string::npos);

  // A directory without results: InputError, which main turns into exit code 1.
  CLI::App app2;
  const cli::Command missing = add_report_command(app2);
  std::vector<std::string> args2 = {(dir / "nothing_here").string(), "report"};
  app2.parse(args2);
  EXPECT_THROW(missing.run(), InputError);
}

}  // namespace
}  // namespace limber::report
