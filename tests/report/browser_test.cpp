// A real browser opens a report: Debian's chromium, headless, with networking features off.
// The page must render (a screenshot with drawn pixels) and its console must stay silent
// (chromium logs console messages as "CONSOLE" lines with --enable-logging). Links to missing
// or remote files are checked by report_job_test.cpp. Skipped, saying why, only when chromium
// is not installed (scripts/install-deps.sh installs it).
#include "curve_export.h"
#include "decimate.h"
#include "interactive.h"
#include "reaction_runs.h"
#include "report_job.h"
#include "chromium.h"
#include "report_test_util.h"
#include "run_data.h"
#include "test_results.h"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <tuple>
#include <iostream>
#include <numbers>

namespace limber::report {
namespace {

using testing::find_chromium;
using testing::numbers_on_line;
using testing::pre_text;
using testing::run_chromium;

constexpr int kWidth = 1280;
constexpr int kHeight = 2000;

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

// The samples of ascending x inside [lo, hi] and one beyond each edge: [first, last] as the
// page's windowOf, found here with the standard library's binary searches.
std::pair<Eigen::Index, Eigen::Index> window_of(const Eigen::VectorXd& x, double lo, double hi) {
  const double* begin = x.data();
  const double* end = x.data() + x.size();
  const Eigen::Index first = std::max<Eigen::Index>(std::upper_bound(begin, end, lo) - begin - 1, 0);
  const Eigen::Index last = std::min<Eigen::Index>(std::lower_bound(begin, end, hi) - begin, x.size() - 1);
  return {first, std::max(first, last)};
}

// The page's re-decimation (interactive.cpp, run by chromium) against decimate.h's m4_indices
// (C++) on the same window of the same 10^5 samples: the same indices, in order. The data go
// to the page as base64 doubles (curve_export.h): the page's decoded values equal the C++
// doubles bit for bit. Exact equality is the claim: both follow one rule in IEEE arithmetic.
TEST(Browser, PageRedecimationIsTheCppM4OnTheSameWindow) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh)";
  const auto root = testing::fresh_directory("browser_m4");
  constexpr Eigen::Index n = 100000;
  constexpr int columns = 1000;
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.0, 10.0);
  Eigen::VectorXd y(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    y(k) = std::sin(2 * std::numbers::pi * 3 * x(k)) + 0.3 * std::sin(2 * std::numbers::pi * 517 * x(k));
  }
  y(12345) = 7.0;
  y(67890) = -9.0;
  y(50000) = std::numeric_limits<double>::quiet_NaN();  // kept by both, never an extreme
  // Whole run (beyond both ends), 1001 samples (all kept), a decimated window, one around the
  // NaN and a spike, one narrower than a sample step.
  const std::vector<std::array<double, 2>> windows{
      {-1.0, 11.0}, {2.5, 2.6}, {1.0, 7.3}, {4.99, 6.8}, {1.23455, 1.23456}};
  std::string input = "{\"x\":\"" + base64_doubles(x) + "\",\"y\":\"" + base64_doubles(y) +
                      "\",\"columns\":" + std::to_string(columns) + ",\"windows\":[";
  for (std::size_t w = 0; w < windows.size(); ++w) {
    input += fmt::format("{}[{},{}]", w > 0 ? "," : "", windows[w][0], windows[w][1]);
  }
  input += "]}";
  const std::string page =
      "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head><body>\n"
      "<script type=\"application/json\" id=\"input\">" + input + "</script>\n" +
      interactive_scripts(InteractiveLibrary{"", ""}) + R"(<script>
var input = JSON.parse(document.getElementById("input").textContent);
var r = window.limberReport, x = r.decode(input.x), y = r.decode(input.y), lines = [];
input.windows.forEach(function (w) {
  var range = r.windowOf(x, w[0], w[1]);
  lines.push(r.m4(x, y, range[0], range[1], input.columns, []).join(" "));
});
lines.push(Array.prototype.map.call(y.subarray(49990, 50010), String).join(" "));
var pre = document.createElement("pre"); pre.id = "result"; pre.textContent = lines.join("\n");
document.body.appendChild(pre);
</script></body></html>
)";
  std::ofstream(root / "m4.html") << page;
  run_chromium(chromium, root / "profile", "--dump-dom", root / "m4.html", root / "dom.html", root / "dom.err");
  const std::string result = pre_text(testing::read_text(root / "dom.html"), "result");
  ASSERT_FALSE(result.empty()) << testing::read_text(root / "dom.err");

  for (std::size_t w = 0; w < windows.size(); ++w) {
    SCOPED_TRACE(fmt::format("window [{}, {}]", windows[w][0], windows[w][1]));
    const auto [first, last] = window_of(x, windows[w][0], windows[w][1]);
    const Eigen::Index count = last - first + 1;
    std::vector<double> expected;
    for (Eigen::Index k : m4_indices(x.segment(first, count), y.segment(first, count), columns)) {
      expected.push_back(static_cast<double>(first + k));
    }
    const std::vector<double> page_indices = numbers_on_line(result, static_cast<int>(w));
    EXPECT_EQ(page_indices, expected);
    if (w == 1) {
      EXPECT_EQ(page_indices.size(), static_cast<std::size_t>(count));  // ~1000 samples: all kept
    }
    if (w == 2) {
      EXPECT_LT(page_indices.size(), static_cast<std::size_t>(count));  // decimated
    }
  }
  // Decoded values: bit for bit (NaN read back as NaN).
  const std::vector<double> decoded = numbers_on_line(result, static_cast<int>(windows.size()));
  ASSERT_EQ(decoded.size(), 20u);
  for (Eigen::Index k = 0; k < 20; ++k) {
    const double expected = y(49990 + k);
    if (std::isnan(expected)) {
      EXPECT_TRUE(std::isnan(decoded[static_cast<std::size_t>(k)]));
    } else {
      EXPECT_EQ(decoded[static_cast<std::size_t>(k)], expected) << k;
    }
  }
}

// A report of a run with 10^5 samples per curve: the page carries every sample; zoomed to
// 1/100 of the run (1001 samples, fewer than the chart's 1000 columns hold at 4 per column),
// the chart shows every sample of the window with the values of results.h5. The page's own
// timing (load until the charts are built, and one zoom with its re-decimation and redraw) is
// printed, not asserted: speed is measured, not tested. A second zoom is left to the page's
// timer, as a reader's drag would be.
TEST(Browser, ZoomShowsEverySampleOfA100kSampleRun) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh)";
  const auto root = testing::fresh_directory("browser_zoom");
  testing::ReactionRun run;
  run.samples = 100001;  // t_k = k 1e-5 s
  testing::write_reaction_run(root / "run", run);
  ReportOptions options;
  options.directories = {root / "run"};
  options.output = root / "report";
  options.mode_shapes = false;
  const std::filesystem::path index = generate_report(options).index;
  const std::string html = testing::read_text(index);
  std::cout << "[ figures ] page of 10^5 samples per curve: " << html.size() / 1e6 << " MB\n";

  // The first chart is joint R3's force in ground axes (X, Y, Z, |F|).
  constexpr double kFrom = 0.5, kTo = 0.51, kFrom2 = 0.25, kTo2 = 0.2502;
  const std::string probe = testing::zoom_probe_script(kFrom, kTo, kFrom2, kTo2) + "</body>";
  std::string zoom_page = html;
  zoom_page.replace(zoom_page.rfind("</body>"), 7, probe);
  std::ofstream(root / "report/zoom.html") << zoom_page;
  const auto wall_start = std::chrono::steady_clock::now();
  run_chromium(chromium, root / "profile", "--dump-dom --virtual-time-budget=2000", root / "report/zoom.html",
               root / "dom.html", root / "dom.err");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const std::string result = pre_text(testing::read_text(root / "dom.html"), "result");
  ASSERT_FALSE(result.empty()) << testing::read_text(root / "dom.err");
  const std::vector<double> timing = numbers_on_line(result, 0);
  ASSERT_EQ(timing.size(), 3u);
  std::cout << "[ figures ] headless chromium: page loaded and charts built at " << timing[0]
            << " ms, zoom to 1001 samples (re-decimation and redraw) " << timing[1]
            << " ms; chart rows after the zoom " << timing[2] << "; chromium's wall time " << wall
            << " s\n";
  EXPECT_TRUE(console_lines(testing::read_text(root / "dom.err")).empty()) << testing::read_text(root / "dom.err");

  const RunData data = read_run_data(root / "run");
  const Eigen::VectorXd& t = data.results.time;
  for (const auto& [line, from, to] : {std::tuple{1, kFrom, kTo}, std::tuple{3, kFrom2, kTo2}}) {
    SCOPED_TRACE(fmt::format("window [{}, {}]", from, to));
    const std::vector<double> times = numbers_on_line(result, line);
    const std::vector<double> values = numbers_on_line(result, line + 1);
    std::vector<double> expected_times, expected_values;
    for (Eigen::Index k = 0; k < t.size(); ++k) {
      if (t(k) >= from && t(k) <= to) {
        expected_times.push_back(t(k));
        expected_values.push_back(data.joints[0].force_ground(k, 0));
      }
    }
    EXPECT_GT(expected_times.size(), 20u);
    EXPECT_EQ(times, expected_times);    // every sample of the window, no other
    EXPECT_EQ(values, expected_values);  // the stored doubles
  }

  // With the mouse, as a reader: drag to zoom, shift-drag to pan (the page re-decimates from
  // its timer each time), double-click to reset. Zoomed and panned, the chart holds every
  // sample of its window (20 pixels of ~1000: ~2 % of the run, ~2000 samples, under the 4000
  // that 1000 columns keep whole); reset, the whole run's M4 rows again.
  std::string mouse_page = html;
  mouse_page.replace(mouse_page.rfind("</body>"), 7, testing::interaction_probe_script() + "</body>");
  std::ofstream(root / "report/mouse.html") << mouse_page;
  run_chromium(chromium, root / "profile", "--window-size=1280,2000 --dump-dom --virtual-time-budget=5000",
               root / "report/mouse.html", root / "mouse.html", root / "mouse.err");
  const std::string states = pre_text(testing::read_text(root / "mouse.html"), "result");
  ASSERT_FALSE(states.empty()) << testing::read_text(root / "mouse.err");
  const std::vector<double> start = numbers_on_line(states, 0);
  ASSERT_EQ(start.size(), 4u);
  for (int line : {1, 2}) {
    const std::vector<double> state = numbers_on_line(states, line);
    ASSERT_EQ(state.size(), 4u) << line;
    const auto inside = ((t.array() >= state[0]) && (t.array() <= state[1])).count();
    EXPECT_LT(state[1] - state[0], 0.1) << "not zoomed, line " << line;
    EXPECT_GT(inside, 1000) << line;
    EXPECT_EQ(state[2], static_cast<double>(inside)) << "line " << line;
  }
  EXPECT_GT(numbers_on_line(states, 2)[0], numbers_on_line(states, 1)[0]);  // panned towards later times
  EXPECT_EQ(numbers_on_line(states, 3), start);                             // reset: as it opened
  EXPECT_TRUE(console_lines(testing::read_text(root / "mouse.err")).empty()) << testing::read_text(root / "mouse.err");
}

// Two runs sampled at different times (20001 and 30001 samples over 1 s) overlaid in one
// comparison chart: each curve carries its own times, and a zoom to 0.3-0.31 s shows each
// run's every sample in the window, at its own times, with its own values (the other run's
// column empty there unless both have a sample at that time).
TEST(Browser, ZoomOverlaysRunsSampledAtDifferentTimes) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh)";
  const auto root = testing::fresh_directory("browser_zoom_merge");
  testing::ReactionRun run;
  run.samples = 20001;
  testing::write_reaction_run(root / "a", run);
  run.samples = 30001;
  run.amplitude = 60.0;
  testing::write_reaction_run(root / "b", run);
  ReportOptions options;
  options.directories = {root / "a", root / "b"};
  options.output = root / "report";
  options.mode_shapes = false;
  const std::string html = testing::read_text(generate_report(options).index);
  // The comparison of ground X carries each run's times.
  const std::size_t json = html.find("id=\"json-compare_R3_ground_x\"");
  ASSERT_NE(json, std::string::npos);
  EXPECT_NE(html.find("\"x\":null,\"curves\":[{\"x\":\"", json), std::string::npos);

  constexpr double kFrom = 0.3, kTo = 0.31;
  const std::string probe = fmt::format(R"(<script>
(function () {{
  var g = window.limberReport.charts.filter(function (c) {{ return c.maindiv_.id === "plot-compare_R3_ground_x"; }})[0];
  g.updateOptions({{ dateWindow: [{0}, {1}] }});
  setTimeout(function () {{
    var lines = [];
    for (var column = 1; column <= 2; ++column) {{
      var t = [], v = [];
      for (var i = 0; i < g.numRows(); ++i) {{
        var x = g.getValue(i, 0), y = g.getValue(i, column);
        if (x >= {0} && x <= {1} && y !== null) {{ t.push(String(x)); v.push(String(y)); }}
      }}
      lines.push(t.join(" "), v.join(" "));
    }}
    var pre = document.createElement("pre"); pre.id = "result"; pre.textContent = lines.join("\n");
    document.body.appendChild(pre);
  }}, 100);
}})();
</script>
</body>)", kFrom, kTo);
  std::string page = html;
  page.replace(page.rfind("</body>"), 7, probe);
  std::ofstream(root / "report/zoom.html") << page;
  run_chromium(chromium, root / "profile", "--dump-dom --virtual-time-budget=2000", root / "report/zoom.html",
               root / "dom.html", root / "dom.err");
  const std::string result = pre_text(testing::read_text(root / "dom.html"), "result");
  ASSERT_FALSE(result.empty()) << testing::read_text(root / "dom.err");
  for (int r = 0; r < 2; ++r) {
    SCOPED_TRACE(r == 0 ? "run a" : "run b");
    const RunData data = read_run_data(root / (r == 0 ? "a" : "b"));
    std::vector<double> times, values;
    for (Eigen::Index k = 0; k < data.results.time.size(); ++k) {
      const double t = data.results.time(k);
      if (t < kFrom || t > kTo) continue;
      times.push_back(t);
      values.push_back(data.joints[0].force_ground(k, 0));
    }
    EXPECT_GT(times.size(), 200u);
    EXPECT_EQ(numbers_on_line(result, 2 * r), times);
    EXPECT_EQ(numbers_on_line(result, 2 * r + 1), values);
  }
  EXPECT_TRUE(console_lines(testing::read_text(root / "dom.err")).empty()) << testing::read_text(root / "dom.err");
}

}  // namespace
}  // namespace limber::report
