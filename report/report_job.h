// `limber report`: one or more run directories -> OUT/index.html, OUT/images/*.png (figures),
// OUT/data/*.csv (every plotted curve) and OUT/media (the runs' videos) (docs/report.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace limber::report {

struct ReportOptions {
  std::vector<std::filesystem::path> directories;  // run directories holding results.h5
  std::filesystem::path output;  // report folder; empty: <first directory>/report
  std::string title;             // page title; empty: the first run's case title
  int plot_width = 1200;         // plot size [pixels]: ~17 cm wide at 180 dpi when printed
  int plot_height = 600;
  int mode_image_width = 480;    // mode-shape pictures [pixels]
  int mode_image_height = 320;
  bool mode_shapes = true;       // draw the mode shapes of flexible bodies
  // The plotting library inlined for interactive plots (interactive.h); a missing file gives
  // static figures with a note on the page.
  std::filesystem::path dygraphs_script = "/usr/share/javascript/dygraphs/dygraph.min.js";
  // Frames of the reaction plots, in order: "ground" (axes named by the case), "joint" (marker
  // j's axes), or the name of a joint marker ("R1.j") or a body ("crank") of the runs.
  std::vector<std::string> frames{"ground"};
  // A report config (report_config.h) listing the reaction plots; empty: every joint in every
  // frame of `frames`.
  std::filesystem::path config;
  // Components below this fraction of the joint's largest are listed "≈ 0", not drawn.
  double zero_fraction = 1e-4;
  // Pixel columns the interactive view's curves are decimated to (decimate.h).
  int interactive_columns = 1000;
};

struct ReportSummary {
  std::filesystem::path index;    // OUT/index.html
  int plots = 0;                  // PNG plots written (each with its CSV)
  bool interactive = false;       // the plotting library was inlined
  int mode_images = 0;
  std::vector<std::string> runs_not_ok;  // "<dir>: <status>" of failed or unfinished runs
};

// Writes the report. Throws InputError (expected/got) when a frame is neither "ground", "joint"
// nor a marker or body of a run, when the config is bad (naming its file and line), or
// zero_fraction is not in [0, 1), (naming the file) when no directory is given or one has no readable results.h5 — before anything is written — or when the report
// folder cannot be created (e.g. it names an existing file); std::runtime_error when
// the offscreen context cannot be created or a file cannot be written.
ReportSummary generate_report(const ReportOptions& options);

}  // namespace limber::report
