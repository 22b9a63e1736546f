// What a user sees first (issue 28): the report's first screen, in chromium, and every
// command's help, within 100 columns.
#include "report_job.h"

#include "chromium.h"
#include "report_test_util.h"
#include "run_case.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace limber::report {
namespace {

using testing::run_case;

// `limber --help` and every command's `--help` within 100 columns (code points), the run's
// long --json description wrapped over several lines (issue 28).
TEST(CommandLine, EveryCommandsHelpFitsIn100Columns) {
  const auto dir = testing::fresh_directory("help_width");
  for (const std::string command :
       {"", "modes", "run", "statics", "linearize", "select", "sweep", "render", "report"}) {
    const auto out = dir / ((command.empty() ? "limber" : command) + ".txt");
    ASSERT_EQ(std::system((std::string(LIMBER_EXE) + " " + command + " --help > " + out.string()).c_str()), 0);
    std::istringstream text(testing::read_text(out));
    int lines = 0, json_lines = 0;
    bool in_json = false;
    for (std::string line; std::getline(text, line); ++lines) {
      std::size_t width = 0;
      for (const char c : line) width += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      EXPECT_LE(width, 100u) << command << " --help: " << line;
      if (line.find("  --json") == 0) in_json = true;
      else if (line.find("  --") == 0) in_json = false;
      json_lines += in_json;
    }
    EXPECT_GT(lines, 10) << command;
    if (command == "run") {
      EXPECT_GE(json_lines, 10);  // 900 characters over ~70-column lines
    }
  }
}

// Where the summary's parts end in chromium at 1400 px width [px from the top], per run in page
// order: its status badge, its events, its peak reactions table and its line of peaks
// (-1 for a part a run lacks), from a copy of the page whose last script measures them.
std::vector<std::vector<double>> summary_part_ends(const std::filesystem::path& index,
                                                   const std::filesystem::path& root) {
  std::string page = testing::read_text(index);
  const std::string probe = R"(<pre id="layout"></pre><script>
(function () {
  function bottom(run, selector) {
    var e = run.querySelector(selector);
    return e ? e.getBoundingClientRect().bottom + window.scrollY : -1;
  }
  var lines = [];
  document.querySelectorAll("#summary .run-summary").forEach(function (run) {
    lines.push([bottom(run, ".badge"), bottom(run, ".summary-grid > div:first-child"),
                bottom(run, "table.peaks"), bottom(run, ".peaks-line")].join(" "));
  });
  document.getElementById("layout").textContent = lines.join("\n");
})();
</script>
</body>)";
  page.replace(page.rfind("</body>"), 7, probe);
  const std::filesystem::path probed = index.parent_path() / "probe.html";
  std::ofstream(probed) << page;
  const std::string chromium = testing::find_chromium();
  testing::run_chromium(chromium, root / "profile", "--window-size=1400,1300 --dump-dom", probed, root / "dom.html",
                        root / "dom.err");
  const std::string text = testing::pre_text(testing::read_text(root / "dom.html"), "layout");
  std::vector<std::vector<double>> ends;
  for (int k = 0; !testing::numbers_on_line(text, k).empty(); ++k) ends.push_back(testing::numbers_on_line(text, k));
  return ends;
}

// The summary's first run within the first 1000 px: status badge, events, peak reactions and
// the line of peaks; every run's badge there too.
void expect_first_screen(const std::vector<std::vector<double>>& ends, const std::filesystem::path& root) {
  ASSERT_FALSE(ends.empty()) << testing::read_text(root / "dom.err");
  const char* what[] = {"status badge", "events", "peak reactions table", "line of peaks"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(ends[0][k], 0.0) << what[k] << " missing";
    EXPECT_LE(ends[0][k], 1000.0) << what[k] << " ends below the first 1000 px";
  }
  for (std::size_t r = 1; r < ends.size(); ++r) {
    EXPECT_LE(ends[r][0], 1000.0) << "run " << r + 1 << "'s status badge ends below the first 1000 px";
  }
}

// The first screen of the satellite's report (issue 28): in chromium at 1400 px width, the
// status badge, the events (the root latches at 2.97 s) and the peak reactions with their units
// end within the first 1000 px. The run stops at 3.05 s, past the root latch-up.
TEST(FirstScreen, SatelliteSummaryFitsTheFirst1000Pixels) {
  if (testing::find_chromium().empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh --tests)";
  const std::filesystem::path run =
      run_case(std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml", "first_screen", "--t-end 3.05");
  const auto root = testing::fresh_directory("first_screen_report");
  ReportOptions options;
  options.directories = {run};
  options.output = root / "report";
  options.mode_shapes = false;
  const std::filesystem::path index = generate_report(options).index;
  expect_first_screen(summary_part_ends(index, root), root);
  // The events hold the root latches, the reactions their unit.
  const std::string html = testing::read_text(index);
  const std::size_t nav = html.find("<nav>");
  EXPECT_LT(html.find("latch_R3 locks"), nav);
  EXPECT_LT(html.find("peak |F| [N]"), nav);
  // The model line gives the masses results.h5 now stores; the system floats free: its
  // momentum drift is said.
  EXPECT_LT(html.find(" kg in all"), nav);
  EXPECT_LT(html.find("free-floating: momentum drifts by"), nav);
}

// The slider-crank report as scripts/main-job.sh writes it, three directories: the flexible
// rod, the rigid rod and `limber select`'s mode sets (0.15 s each, past the spin-up; select's
// sets one at a time). Its first screen holds the first run's status, events note, peak
// reactions with units and line of peaks, and every run's status badge.
TEST(FirstScreen, SliderCrankThreeRunSummaryFitsTheFirst1000Pixels) {
  if (testing::find_chromium().empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh --tests)";
  const std::string cases = LIMBER_CASES_DIR;
  const std::filesystem::path flexible = run_case(cases + "/slider_crank.yaml", "crank_flexible", "--t-end 0.15");
  const std::filesystem::path rigid = run_case(cases + "/slider_crank_rigid.yaml", "crank_rigid", "--t-end 0.15");
  const std::filesystem::path select = testing::fresh_directory("crank_select");
  const std::string command = std::string(LIMBER_EXE) + " select " + cases + "/slider_crank.yaml -o " +
                              select.string() + " --t-end 0.15 --jobs 1 > " + (select / "select.log").string() +
                              " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << testing::read_text(select / "select.log");
  const auto root = testing::fresh_directory("crank_first_screen");
  ReportOptions options;
  options.directories = {flexible, rigid, select};
  options.output = root / "report";
  options.mode_shapes = false;
  const std::filesystem::path index = generate_report(options).index;
  const std::vector<std::vector<double>> ends = summary_part_ends(index, root);
  ASSERT_EQ(ends.size(), 3u) << testing::read_text(root / "dom.err");
  expect_first_screen(ends, root);
  const std::string html = testing::read_text(index);
  const std::size_t nav = html.find("<nav>");
  EXPECT_LT(html.find("peak |F| [N]"), nav);
  EXPECT_LT(html.find("seed Figs. 4–5"), nav);
}

}  // namespace
}  // namespace limber::report
