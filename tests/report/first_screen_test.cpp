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

// The first screen of the satellite's report (issue 28): in chromium at 1400 px width, the
// status badge, the events (the root latches at 2.97 s) and the peak reactions with their units
// end within the first 1000 px. The run stops at 3.05 s, past the root latch-up.
TEST(FirstScreen, SatelliteSummaryFitsTheFirst1000Pixels) {
  const std::string chromium = testing::find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh --tests)";
  const std::filesystem::path run =
      run_case(std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml", "first_screen", "--t-end 3.05");
  const auto root = testing::fresh_directory("first_screen_report");
  ReportOptions options;
  options.directories = {run};
  options.output = root / "report";
  options.mode_shapes = false;
  const std::filesystem::path index = generate_report(options).index;

  // A copy of the page whose last script writes where the summary's parts end [px from the top].
  std::string page = testing::read_text(index);
  const std::string probe = R"(<pre id="layout"></pre><script>
(function () {
  function bottom(selector) {
    var e = document.querySelector(selector);
    return e ? e.getBoundingClientRect().bottom + window.scrollY : -1;
  }
  document.getElementById("layout").textContent = [bottom("#summary .badge"),
      bottom("#summary .summary-grid > div:first-child table"), bottom("#summary table.peaks"),
      bottom("#summary .peaks-line")].join(" ");
})();
</script>
</body>)";
  page.replace(page.rfind("</body>"), 7, probe);
  const std::filesystem::path probed = root / "report" / "probe.html";
  std::ofstream(probed) << page;
  testing::run_chromium(chromium, root / "profile", "--window-size=1400,1300 --dump-dom", probed, root / "dom.html",
                        root / "dom.err");
  const std::vector<double> ends = testing::numbers_on_line(testing::pre_text(testing::read_text(root / "dom.html"), "layout"), 0);
  ASSERT_EQ(ends.size(), 4u) << testing::read_text(root / "dom.err");
  const char* what[] = {"status badge", "events table", "peak reactions table", "deflection, stress, energy line"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(ends[k], 0.0) << what[k] << " missing";
    EXPECT_LE(ends[k], 1000.0) << what[k] << " ends below the first 1000 px";
  }
  // The events hold the root latches, the reactions their unit.
  const std::string html = testing::read_text(index);
  const std::size_t nav = html.find("<nav>");
  EXPECT_LT(html.find("latch_R3 locks"), nav);
  EXPECT_LT(html.find("peak |F| [N]"), nav);
}

}  // namespace
}  // namespace limber::report
