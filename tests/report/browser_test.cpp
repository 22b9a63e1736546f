// A real browser opens a report: Debian's chromium, headless, with networking features off.
// The page must render (a screenshot with drawn pixels) and its console must stay silent
// (chromium logs console messages as "CONSOLE" lines with --enable-logging). Links to missing
// or remote files are checked by report_job_test.cpp. Skipped, saying why, only when chromium
// is not installed (scripts/install-deps.sh installs it).
#include "reaction_runs.h"
#include "report_job.h"
#include "report_test_util.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace limber::report {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 2000;

// chromium's path, or "" when it is not installed.
std::string find_chromium() {
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "/usr/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, end - start)) / "chromium";
    if (std::filesystem::is_regular_file(candidate)) return candidate.string();
    start = end + 1;
  }
  return "";
}

// Runs chromium headless on `page` with `extra` flags; stdout and stderr into files.
int run_chromium(const std::string& chromium, const std::filesystem::path& profile,
                 const std::string& extra, const std::filesystem::path& page,
                 const std::filesystem::path& out, const std::filesystem::path& err) {
  const std::string command =
      "'" + chromium + "' --headless --no-sandbox --disable-gpu --disable-extensions "
      "--no-first-run --disable-background-networking --disable-sync --disable-default-apps "
      "--user-data-dir='" + profile.string() + "' --enable-logging=stderr --v=0 " + extra +
      " 'file://" + page.string() + "' > '" + out.string() + "' 2> '" + err.string() + "'";
  return std::system(command.c_str());
}

// Lines of chromium's log that come from the page's console.
std::vector<std::string> console_lines(const std::string& log) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < log.size()) {
    const std::size_t end = std::min(log.find('\n', start), log.size());
    const std::string line = log.substr(start, end - start);
    if (line.find("CONSOLE") != std::string::npos) lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

TEST(Browser, HeadlessChromiumRendersTheReportWithoutConsoleErrors) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    GTEST_SKIP() << "chromium is not installed (Debian package 'chromium', listed in "
                    "scripts/install-deps.sh): the browser check is skipped";
  }

  // A report of the render test scene and two reaction runs (all sections, comparisons).
  const auto root = testing::fresh_directory("browser");
  render::testing::TestScene scene;
  scene.samples = 21;
  render::testing::write_test_results(root / "scene", scene);
  testing::ReactionRun run;
  testing::write_reaction_run(root / "run_a", run);
  run.amplitude = 60.0;
  testing::write_reaction_run(root / "run_b", run);
  ReportOptions options;
  options.directories = {root / "scene", root / "run_a", root / "run_b"};
  options.output = root / "report";
  const std::filesystem::path page = generate_report(options).index;

  // Screenshot.
  const std::filesystem::path shot = root / "screenshot.png";
  run_chromium(chromium, root / "profile",
               "--hide-scrollbars --window-size=" + std::to_string(kWidth) + "," +
                   std::to_string(kHeight) + " --screenshot='" + shot.string() + "'",
               page, root / "shot.out", root / "shot.err");
  ASSERT_TRUE(std::filesystem::is_regular_file(shot)) << testing::read_text(root / "shot.err");
  const testing::Png png(shot);
  EXPECT_EQ(png.width, kWidth);
  EXPECT_EQ(png.height, kHeight);
  // Drawn: text, tables and plots make well over 5 % of the pixels non-white.
  long drawn = 0;
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      const auto p = png.pixel(x, y);
      if (p[0] < 240 || p[1] < 240 || p[2] < 240) ++drawn;
    }
  }
  EXPECT_GT(drawn, static_cast<long>(0.05 * kWidth * kHeight));
  EXPECT_TRUE(console_lines(testing::read_text(root / "shot.err")).empty())
      << testing::read_text(root / "shot.err");

  // The DOM as the browser built it, and its console.
  run_chromium(chromium, root / "profile", "--dump-dom --virtual-time-budget=2000", page,
               root / "dom.html", root / "dom.err");
  const std::string dom = testing::read_text(root / "dom.html");
  EXPECT_NE(dom.find("Case summary"), std::string::npos) << testing::read_text(root / "dom.err");
  EXPECT_NE(dom.find("id=\"comparison\""), std::string::npos);
  // The charts were built: <body> marked interactive, and each plot's div holds canvases.
  EXPECT_NE(dom.find("<body class=\"interactive\">"), std::string::npos);
  std::size_t plots = 0, charts = 0;
  for (std::size_t at = dom.find("class=\"dygraph-plot\""); at != std::string::npos;
       at = dom.find("class=\"dygraph-plot\"", at + 1)) {
    ++plots;
    const std::size_t next = dom.find("class=\"plot-legend\"", at);
    if (dom.substr(at, next - at).find("<canvas") != std::string::npos) ++charts;
  }
  EXPECT_GT(plots, 10u);
  EXPECT_EQ(charts, plots);

  // Printed (PDF): the PNG figures, not the charts: one image per plot plus the mode-shape
  // pictures (the print style sheet hides the charts' canvases, which would print as images).
  const std::filesystem::path pdf = root / "report.pdf";
  run_chromium(chromium, root / "profile", "--print-to-pdf='" + pdf.string() + "'", page,
               root / "pdf.out", root / "pdf.err");
  const std::string printed = testing::read_text(pdf);
  std::size_t images = 0;
  for (std::size_t at = printed.find("/Subtype /Image"); at != std::string::npos;
       at = printed.find("/Subtype /Image", at + 1)) {
    ++images;
  }
  const std::string html = testing::read_text(page);
  std::size_t img_tags = 0;
  for (std::size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1)) ++img_tags;
  EXPECT_EQ(images, img_tags) << "charts printed, or figures missing";
  const std::vector<std::string> console = console_lines(testing::read_text(root / "dom.err"));
  EXPECT_TRUE(console.empty()) << console.front();
}

}  // namespace
}  // namespace limber::report
