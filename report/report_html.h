// The text of index.html: one self-contained page (inline CSS, no scripts, no remote fonts or
// styles) linking only the PNG files written beside it and, when present, the run's video.
// Every string read from files is escaped (html.h).
#pragma once

#include "mode_shape_images.h"
#include "plot_set.h"
#include "run_data.h"

#include <string>
#include <vector>

namespace limber::report {

// What the page shows for one run; file names are relative to the images/ folder.
struct RunSection {
  const RunData* run = nullptr;
  std::string label;                // "run 1: <directory name>"
  std::string anchor;               // HTML id prefix, e.g. "run1"
  std::vector<NamedPlot> plots;
  std::vector<ModeImage> mode_images;
  std::vector<std::string> stills;
  std::string video_url;            // relative URL of animation.mp4, "" when absent
};

struct ReportContent {
  std::string title;
  std::vector<RunSection> runs;
  std::vector<NamedPlot> comparisons;
};

// Folder of the images, relative to index.html.
inline constexpr const char* kImageFolder = "images";

std::string report_html(const ReportContent& content);

}  // namespace limber::report
