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

// The page's re-decimation (window.limberReport): base64 doubles decoded, decimate.h's M4 rule
// over the samples in the visible window, and the rows a chart draws (the whole run's M4
// rows, so the range selector keeps showing the whole run, plus the window's).
constexpr const char* kDecimateScript = R"JS(
(function () {
  "use strict";
  // Base64 of little-endian doubles (curve_export.h) -> Float64Array.
  function decode(text) {
    var bytes = atob(text), n = bytes.length, buffer = new Uint8Array(n);
    for (var i = 0; i < n; ++i) buffer[i] = bytes.charCodeAt(i);
    return new Float64Array(buffer.buffer);
  }
  // Samples first..last of (x, y) kept for `buckets` columns, pushed to `out` ascending: the
  // rule of decimate.h's m4_indices, operation for operation (the same doubles give the same
  // columns).
  function m4(x, y, first, last, buckets, out) {
    var n = last - first + 1, k;
    if (n <= 4 * buckets || n < 2) {
      for (k = first; k <= last; ++k) out.push(k);
      return out;
    }
    var x0 = x[first], span = x[last] - x[first], kept = [];
    function column(k) {
      if (!(span > 0)) return 0;
      var b = Math.floor((x[k] - x0) / span * buckets);
      return b < 0 ? 0 : b > buckets - 1 ? buckets - 1 : b;
    }
    var start = first;
    while (start <= last) {
      var b = column(start), end = start;
      while (end + 1 <= last && column(end + 1) === b) ++end;
      var lo = -1, hi = -1;
      for (k = start; k <= end; ++k) {
        if (!isFinite(y[k])) { kept.push(k); continue; }  // a gap or a blow-up stays visible
        if (lo < 0 || y[k] < y[lo]) lo = k;
        if (hi < 0 || y[k] > y[hi]) hi = k;
      }
      kept.push(start, end);
      if (lo >= 0) kept.push(lo);
      if (hi >= 0) kept.push(hi);
      start = end + 1;
    }
    kept.sort(function (a, c) { return a - c; });
    for (k = 0; k < kept.length; ++k) if (k === 0 || kept[k] !== kept[k - 1]) out.push(kept[k]);
    return out;
  }
  // [first, last]: the samples of ascending x inside [lo, hi] and one beyond each edge, so
  // the lines run to the chart's border.
  function windowOf(x, lo, hi) {
    var a = 0, b = x.length - 1, first, last, m;
    while (a < b) { m = (a + b + 1) >> 1; if (x[m] <= lo) a = m; else b = m - 1; }
    first = a;
    a = 0; b = x.length - 1;
    while (a < b) { m = (a + b) >> 1; if (x[m] >= hi) b = m; else a = m + 1; }
    last = Math.max(a, first);
    return [first, last];
  }
  // One curve's abscissa and ordinates, decoded, with its whole-run M4 rows.
  function curves(full) {
    var shared = full.x ? decode(full.x) : null;
    return full.curves.map(function (c) {
      var x = shared || decode(c.x), y = decode(c.y);
      var n = Math.min(x.length, y.length);
      return { x: x, y: y, n: n, whole: n > 0 ? m4(x, y, 0, n - 1, full.columns, []) : [] };
    });
  }
  // The rows of a chart showing [lo, hi]: each curve's whole-run rows and its window's, merged
  // on equal abscissae; null where a curve has no sample or a non-finite one.
  function rows(list, columns, lo, hi) {
    var byX = new Map();
    list.forEach(function (c, i) {
      if (c.n === 0) return;
      var range = windowOf(c.x.subarray(0, c.n), lo, hi);
      var kept = c.whole.concat(m4(c.x, c.y, range[0], range[1], columns, []));
      for (var j = 0; j < kept.length; ++j) {
        var k = kept[j], x = c.x[k], row = byX.get(x);
        if (!row) {
          row = [x];
          for (var e = 0; e < list.length; ++e) row.push(null);
          byX.set(x, row);
        }
        row[i + 1] = isFinite(c.y[k]) ? c.y[k] : null;
      }
    });
    return Array.from(byX.values()).sort(function (a, b) { return a[0] - b[0]; });
  }
  window.limberReport = { decode: decode, m4: m4, windowOf: windowOf, curves: curves, rows: rows, charts: [] };
})();
)JS";

// Builds every chart, then wires the forms. Zoom: drag; pan: shift-drag; reset: double-click;
// the range selector under each chart moves its time window; the legend reads the curves at the
// cursor. A decimated chart (decimate.h) is re-decimated over the visible window after each
// draw that moved it, from every sample the page holds ("full").
constexpr const char* kInitScript = R"JS(
(function () {
  "use strict";
  if (typeof Dygraph === "undefined") return;
  var report = window.limberReport;
  // Redraws chart g with the rows of its visible window, unless that window is drawn already.
  function refine(g) {
    var range = g.xAxisRange();
    if (g.limberWindow && g.limberWindow[0] === range[0] && g.limberWindow[1] === range[1]) return;
    g.limberWindow = range;
    // Decoded at the first zoom, so that a page of many long curves opens fast.
    if (!g.limberCurves) g.limberCurves = report.curves(g.limberFull);
    g.updateOptions({ file: report.rows(g.limberCurves, g.limberFull.columns, range[0], range[1]) });
  }
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
    var options = {
      labels: spec.labels, title: spec.title, xlabel: spec.xlabel, ylabel: spec.ylabel,
      logscale: spec.log, colors: spec.colors, strokeWidth: 1.5,
      legend: "always", labelsDiv: document.getElementById(div.getAttribute("data-legend")),
      showRangeSelector: true, rangeSelectorHeight: 30, connectSeparatedPoints: true,
      // The range selector would make a drag pan; keep drag to zoom, shift-drag to pan and
      // double-click to reset, as the page says.
      interactionModel: Dygraph.defaultInteractionModel,
      axes: {
        // Tick labels to 9 significant digits, trailing zeros dropped: dygraphs' default of 2
        // decimals repeats labels on a short run or a zoomed window ("0.50, 0.50, 0.50").
        x: { valueFormatter: function (x) { return xname + " = " + x.toPrecision(6); },
             axisLabelFormatter: function (x) { return String(+x.toPrecision(9)); } },
        y: { valueFormatter: function (y) { return y.toPrecision(5); }, axisLabelWidth: 80 }
      }
    };
    if (spec.full) {
      // After a draw that moved the window (zoom, pan, range selector, form), from a timer:
      // a chart cannot be given new data while it draws.
      options.drawCallback = function (g, initial) {
        if (initial || g.limberPending) return;
        g.limberPending = true;
        setTimeout(function () { g.limberPending = false; refine(g); }, 0);
      };
    }
    // Curves lying on earlier ones are dashed, as in the PNG (curve_styles.h).
    // Earlier runs of a comparison are drawn wider, so later ones leave them visible.
    if (spec.dashes || spec.widths) {
      options.series = {};
      for (var c = 0; c + 1 < spec.labels.length; ++c) {
        var series = {};
        if (spec.dashes && spec.dashes[c]) series.strokePattern = spec.dashes[c];
        if (spec.widths && spec.widths[c] !== 1.5) series.strokeWidth = spec.widths[c];
        options.series[spec.labels[c + 1]] = series;
      }
    }
    var chart = new Dygraph(div, spec.data, options);
    if (spec.full) {
      chart.limberFull = spec.full;
      chart.limberWindow = chart.xAxisRange();  // the page's rows are the whole run's M4
      chart.limberRefine = function () { refine(this); };
    }
    chart.limberDiv = div;
    report.charts.push(chart);
    var run = div.getAttribute("data-run");
    (charts[run] = charts[run] || []).push(chart);
  }
  // A chart built inside a closed <details> has no width: drawn again when it opens.
  var folds = document.querySelectorAll("details");
  for (var f = 0; f < folds.length; ++f) {
    folds[f].addEventListener("toggle", function (event) {
      if (!event.target.open) return;
      report.charts.forEach(function (c) {
        if (event.target.contains(c.limberDiv)) c.resize();
      });
    });
  }
  // A link to a figure inside a fold (the summary's "seed Fig. 10") opens the folds around it.
  function reveal() {
    var target = location.hash && document.getElementById(decodeURIComponent(location.hash.slice(1)));
    for (var e = target; e; e = e.parentElement) if (e.tagName === "DETAILS") e.open = true;
    if (target) target.scrollIntoView();
  }
  window.addEventListener("hashchange", reveal);
  reveal();
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
  return "<script>\n" + library.script + "\n</script>\n<script>" + kDecimateScript + kInitScript + "</script>\n";
}

}  // namespace limber::report
