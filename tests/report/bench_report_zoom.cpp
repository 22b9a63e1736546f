// limber_bench_report_zoom: what carrying every sample in the report page costs and what a zoom
// costs, in headless chromium (docs/report.md "Long runs", docs/benchmarks.md). Writes a
// reaction run of --samples samples per curve (tests/report/reaction_runs.h), its report, and
// the same page without the full-resolution data (each chart's "full" field cut out: the page
// before the zoom re-decimation), then opens each --runs times with a script at the end of the
// page that zooms the first chart to 1/100 of the run (interactive.cpp's re-decimation and
// redraw, timed inside the page) and prints, per page: its size, the time from navigation to
// the end of the page's scripts (parsing, the library, building every chart), the zoom, and
// the chart's rows after it; median and range over the runs.
//   limber_bench_report_zoom [--samples 100001] [--runs 5] [--keep DIR]
#include "chromium.h"
#include "reaction_runs.h"
#include "report_job.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace limber::report;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The page with every chart's "full" field (the last of its JSON object) cut out.
std::string without_full_data(const std::string& page) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t full = page.find(",\"full\":{"); full != std::string::npos; full = page.find(",\"full\":{", at)) {
    const std::size_t end = page.find("</script>", full);  // the object's closing "}}" precedes it
    out += page.substr(at, full - at) + "}";
    at = end;
  }
  return out + page.substr(at);
}

struct Timing {
  double load_ms = 0, zoom_ms = 0, rows = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int samples = 100001, runs = 5;
  std::filesystem::path keep;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--samples" && i + 1 < argc) {
      samples = std::atoi(argv[++i]);
    } else if (arg == "--runs" && i + 1 < argc) {
      runs = std::atoi(argv[++i]);
    } else if (arg == "--keep" && i + 1 < argc) {
      keep = argv[++i];
    } else {
      std::fprintf(stderr, "usage: limber_bench_report_zoom [--samples 100001] [--runs 5] [--keep DIR]\n");
      return 2;
    }
  }
  const std::string chromium = testing::find_chromium();
  if (chromium.empty() || samples < 1000 || runs < 1) {
    std::fprintf(stderr, "needs chromium on PATH, --samples >= 1000 and --runs >= 1\n");
    return 2;
  }
  const std::filesystem::path root =
      keep.empty() ? std::filesystem::temp_directory_path() / "limber_bench_report_zoom" : keep;
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);

  // The run and its report.
  testing::ReactionRun run;
  run.samples = samples;
  testing::write_reaction_run(root / "run", run);
  ReportOptions options;
  options.directories = {root / "run"};
  options.output = root / "report";
  options.mode_shapes = false;
  const auto report_start = std::chrono::steady_clock::now();
  const ReportSummary summary = generate_report(options);
  const double report_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - report_start).count();
  const std::string page = read_text(summary.index);
  std::size_t charts = 0, full = 0;
  for (std::size_t at = page.find("data-source=\""); at != std::string::npos; at = page.find("data-source=\"", at + 1)) ++charts;
  for (std::size_t at = page.find(",\"full\":{"); at != std::string::npos; at = page.find(",\"full\":{", at + 1)) ++full;
  std::printf("run: %d samples per curve, %zu charts, %zu carrying every sample; report written in %.2f s\n",
              samples, charts, full, report_s);

  // Zoom to 1/100 of the run (duration 1 s) around its middle; the probe's second zoom is
  // not timed here.
  const double from = 0.5, to = 0.51;
  const std::string probe = testing::zoom_probe_script(from, to, 0.25, 0.2502) + "</body>";
  for (const bool with_full : {true, false}) {
    std::string text = with_full ? page : without_full_data(page);
    text.replace(text.rfind("</body>"), 7, probe);
    const std::filesystem::path file = root / "report" / (with_full ? "zoom_full.html" : "zoom_decimated_only.html");
    std::ofstream(file, std::ios::binary) << text;
    std::vector<double> load, zoom;
    double rows = 0;
    for (int k = 0; k < runs; ++k) {
      testing::run_chromium(chromium, root / "profile", "--dump-dom --virtual-time-budget=2000", file,
                            root / "dom.html", root / "dom.err");
      const std::string result = testing::pre_text(read_text(root / "dom.html"), "result");
      const std::vector<double> numbers = testing::numbers_on_line(result, 0);
      if (numbers.size() != 3) {
        std::fprintf(stderr, "the page left no timing (see %s)\n", (root / "dom.err").c_str());
        return 1;
      }
      load.push_back(numbers[0]);
      zoom.push_back(numbers[1]);
      rows = numbers[2];
    }
    std::printf("%-34s %7.2f MB  load %7.1f ms (%.1f to %.1f)  zoom %6.1f ms (%.1f to %.1f)  rows after zoom %.0f\n",
                with_full ? "page with every sample:" : "page with the M4 rows only (before):",
                static_cast<double>(text.size()) / 1e6, median(load), *std::min_element(load.begin(), load.end()),
                *std::max_element(load.begin(), load.end()), median(zoom), *std::min_element(zoom.begin(), zoom.end()),
                *std::max_element(zoom.begin(), zoom.end()), rows);
  }
  if (keep.empty()) std::filesystem::remove_all(root);
  return 0;
}
