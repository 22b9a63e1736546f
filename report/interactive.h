// The interactive view of the report's plots: dygraphs (Debian package libjs-dygraphs, a
// JavaScript library for long time series) inlined into index.html at report time, so the page
// stays one offline file. Each plot's PNG stays on the page for print and PDF, and on screen
// whenever the library is not there or scripts are off.
//
// Long curves: a chart opens with the whole run's M4 rows (decimate.h) and, when that dropped
// samples, its JSON also holds every sample ("full", curve_export.h: base64 doubles). After a
// draw that moved the visible window (zoom, pan, range selector, time-window form) the page
// re-decimates that window by the same M4 rule, in JavaScript (window.limberReport.m4, the
// same operations as m4_indices, so the same indices), and draws the whole run's rows plus the
// window's: a window of at most 4 samples per column shows every sample, the range selector
// still shows the whole run. The samples are decoded at a chart's first zoom, so the page
// opens as fast as without them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace limber::report {

// Where Debian installs the library (dpkg -L libjs-dygraphs).
inline constexpr const char* kDygraphsScript = "/usr/share/javascript/dygraphs/dygraph.min.js";
inline constexpr const char* kDygraphsStyle = "/usr/share/javascript/dygraphs/dygraph.min.css";

struct InteractiveLibrary {
  std::string script;  // dygraph.min.js
  std::string style;   // dygraph.min.css ("" when absent: the page's own style suffices)
};

// Reads the library from `script` (and the style sheet beside it named `style`); nothing when
// the script is missing or unreadable: the report then shows the static figures with a note.
std::optional<InteractiveLibrary> load_interactive_library(
    const std::filesystem::path& script = kDygraphsScript,
    const std::filesystem::path& style = kDygraphsStyle);

// The page's style rules for interactive plots (screen: plot, legend, controls; print: the PNG).
std::string interactive_style();

// The time-window controls of a run's plots (one form per run section, applying to its plots).
std::string time_window_form(const std::string& anchor);

// The <script> elements closing the page: the library, then the re-decimation code
// (window.limberReport: decode, m4, windowOf, curves, rows, charts) and the code that turns
// each <div class="dygraph-plot" data-source="ID"> into a chart of the JSON in
// <script id="ID">, wires the time-window forms and marks <body> "interactive" (which hides
// the PNGs on screen). The re-decimation code runs without the library too (tests call it).
std::string interactive_scripts(const InteractiveLibrary& library);

}  // namespace limber::report
