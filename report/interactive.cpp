#include "interactive.h"

#include <fstream>
#include <sstream>

namespace limber::report {
namespace {

std::optional<std::string> read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) return std::nullopt;
  return text.str();
}

// Builds every chart, then wires the forms. Zoom: drag; pan: shift-drag; reset: double-click;
// the range selector under each chart moves its time window; the legend reads the curves at the
// cursor. Decimated data: see decimate.h.
constexpr const char* kInitScript = R"JS(
(function () {
  "use strict";
  if (typeof Dygraph === "undefined") return;
  // Shown before drawing: a chart measures its box when it is built.
  document.body.classList.add("interactive");
  var charts = {};
  var divs = document.querySelectorAll("div.dygraph-plot");
  for (var i = 0; i < divs.length; ++i) {
    var div = divs[i];
    var source = document.getElementById(div.getAttribute("data-source"));
    if (!source) continue;
    var spec = JSON.parse(source.textContent);
    var xname = spec.xlabel;
    var chart = new Dygraph(div, spec.data, {
      labels: spec.labels, title: spec.title, xlabel: spec.xlabel, ylabel: spec.ylabel,
      logscale: spec.log, colors: spec.colors, strokeWidth: 1.5,
      legend: "always", labelsDiv: document.getElementById(div.getAttribute("data-legend")),
      showRangeSelector: true, rangeSelectorHeight: 30, connectSeparatedPoints: true,
      axes: {
        x: { valueFormatter: function (x) { return xname + " = " + x.toPrecision(6); } },
        y: { valueFormatter: function (y) { return y.toPrecision(5); }, axisLabelWidth: 80 }
      }
    });
    var run = div.getAttribute("data-run");
    (charts[run] = charts[run] || []).push(chart);
  }
  var forms = document.querySelectorAll("form.time-window");
  for (var j = 0; j < forms.length; ++j) {
    (function (form) {
      var list = charts[form.getAttribute("data-run")] || [];
      form.addEventListener("submit", function (event) {
        event.preventDefault();
        var from = parseFloat(form.elements["from"].value);
        var to = parseFloat(form.elements["to"].value);
        if (!(from < to)) return;
        list.forEach(function (c) { c.updateOptions({ dateWindow: [from, to] }); });
      });
      form.elements["reset"].addEventListener("click", function () {
        list.forEach(function (c) { c.resetZoom(); });
      });
    })(forms[j]);
  }
})();
)JS";

}  // namespace

std::optional<InteractiveLibrary> load_interactive_library(const std::filesystem::path& script,
                                                           const std::filesystem::path& style) {
  std::optional<std::string> js = read_file(script);
  if (!js || js->empty()) return std::nullopt;
  // A "</script" inside would end the inline element early: refuse such a file.
  if (js->find("</script") != std::string::npos) return std::nullopt;
  std::optional<std::string> css = read_file(style);
  if (css && css->find("</style") != std::string::npos) css.reset();
  return InteractiveLibrary{std::move(*js), css.value_or("")};
}

std::string interactive_style() {
  return R"(
.dygraph-plot { width: 100%; height: 420px; display: none; }
.plot-legend { min-height: 1.4em; font-size: .9em; display: none; }
form.time-window { display: none; margin: .5em 0; font-size: .95em; }
form.time-window input[type=number] { width: 8em; }
body.interactive .dygraph-plot, body.interactive .plot-legend { display: block; }
body.interactive form.time-window { display: block; }
body.interactive figure.plot img.static { display: none; }
.dygraph-title { font-size: 1.1em; font-weight: bold; }
.dygraph-label { font-size: .95em; }
@media print {
  body.interactive .dygraph-plot, body.interactive .plot-legend,
  body.interactive form.time-window { display: none; }
  body.interactive figure.plot img.static { display: block; }
}
)";
}

std::string time_window_form(const std::string& anchor) {
  return "<form class=\"time-window\" data-run=\"" + anchor +
         "\">Time window of every plot below: from <input type=\"number\" name=\"from\" "
         "step=\"any\"> to <input type=\"number\" name=\"to\" step=\"any\"> s "
         "<button type=\"submit\">apply</button> <button type=\"button\" name=\"reset\">whole "
         "run</button> <span class=\"note\">In a plot: drag to zoom, shift-drag to pan, "
         "double-click to reset; the slider under it moves the window; the legend reads the "
         "curves at the cursor.</span></form>\n";
}

std::string interactive_scripts(const InteractiveLibrary& library) {
  return "<script>\n" + library.script + "\n</script>\n<script>" + kInitScript + "</script>\n";
}

}  // namespace limber::report
