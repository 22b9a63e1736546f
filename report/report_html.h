// The text of index.html: one self-contained page (inline CSS, the inlined plotting library and
// its data, no remote fonts, styles or scripts) linking only files inside the report folder:
// the PNG figures, the curves' CSV files and the run's media.
// Every string read from files is escaped (html.h).
#pragma once

#include "interactive.h"
#include "mode_shape_images.h"
#include "plot_set.h"
#include "run_data.h"

#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// A plot as written: its figure (PNG in images/), the CSV of every sample (in data/, "" when
// not written) and the decimated curves of the interactive view (JSON, curve_export.h; "" for
// none) with the rows they hold.
struct WrittenPlot {
  NamedPlot plot;
  std::string csv_file;
  std::string interactive_json;
  std::size_t interactive_rows = 0;
};

// What the page shows for one run; file names are relative to the images/ folder.
struct RunSection {
  const RunData* run = nullptr;
  std::string label;                // "run 1: <directory name>"
  std::string anchor;               // HTML id prefix, e.g. "run1"
  std::vector<WrittenPlot> plots;
  std::vector<ModeImage> mode_images;
  std::vector<std::string> stills;
  std::string video_url;            // URL of the video inside the report folder, "" when absent
};

struct ReportContent {
  std::string title;
  // The inlined plotting library; none: static figures only, with `interactive_note` shown.
  std::optional<InteractiveLibrary> interactive;
  std::string interactive_note;
  std::vector<RunSection> runs;
  std::vector<WrittenPlot> comparisons;
};

// Folders of the images and of the curves' CSV files, relative to index.html.
inline constexpr const char* kImageFolder = "images";
inline constexpr const char* kDataFolder = "data";
inline constexpr const char* kMediaFolder = "media";

std::string report_html(const ReportContent& content);

}  // namespace limber::report
