// A plot's curves as text: CSV beside the report (every sample, numbers that read back to the
// same doubles) and JSON inside the page for the interactive view (dygraphs' native array
// format, docs/report.md "Interactive plots").
#pragma once

#include "decimate.h"
#include "plot.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace limber::report {

// RFC 4180 CSV: a header row "<x_label>,<label> [unit]..." (the unit is the bracketed part of
// `y_label`, e.g. "force [N]" -> "[N]"), then one row per abscissa; numbers in the shortest
// form that parses back to the same double, an empty cell where a curve has no sample (NaN).
// Fields holding a comma, quote or line break are quoted, quotes doubled. Line ends "\n".
// A non-empty `comment` comes first, as the line "# <comment>" (pandas: comment="#").
std::string curve_csv(const CurveTable& table, const std::string& x_label,
                      const std::string& y_label, const std::string& comment = "");

// A JSON string literal of `text`, safe inside an HTML <script> element: quotes, backslashes
// and control characters escaped, and < > & as \u003c \u003e \u0026 so no "</script>" appears.
std::string json_string(const std::string& text);

// The plot as JSON: {"title", "xlabel", "ylabel", "labels" (x label first), "log",
// "colors" ("#rrggbb" per curve, as the PNG), "dashes" (per curve a dash pattern in pixels
// [on, off, ...], null for solid: LineStyle, as the PNG), "widths" (per curve its line width
// in pixels, 1.5 + its extra width), "samples" (before decimation), "data":
// [[x, y1, y2, ...], ...] with null for a missing or non-finite value}; "log" only when the
// plot asks for it and every value is positive (as the PNG). A non-empty `full`
// (full_resolution_json) is added as "full".
std::string curve_json(const PlotSpec& plot, const CurveTable& table, const std::string& full = "");

// Base64 (RFC 4648, with padding) of the values as IEEE 754 binary64 in little-endian byte
// order: the bytes of a JavaScript Float64Array on every platform a browser runs on.
std::string base64_doubles(const Eigen::Ref<const Eigen::VectorXd>& values);

// Every sample of a plot's curves, for the page to re-decimate the visible window when the
// reader zooms or pans (interactive.h): {"columns": `columns`, "x": base64 doubles of the
// shared abscissa or null, "curves": [{"x": its own abscissa (only when not shared), "y": its
// ordinates}, ...]}. 8 bytes per value, 4/3 of that as text.
std::string full_resolution_json(const std::vector<Curve>& curves, int columns);

}  // namespace limber::report
