// Headless chromium for the report's tests and benchmark: found on PATH, run on a page with
// networking features off, and what a page script left in a <pre> read back from the DOM.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace limber::report::testing {

// chromium's path, or "" when it is not installed.
inline std::string find_chromium() {
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
inline int run_chromium(const std::string& chromium, const std::filesystem::path& profile,
                 const std::string& extra, const std::filesystem::path& page,
                 const std::filesystem::path& out, const std::filesystem::path& err) {
  const std::string command =
      "'" + chromium + "' --headless --no-sandbox --disable-gpu --disable-extensions "
      "--no-first-run --disable-background-networking --disable-sync --disable-default-apps "
      "--user-data-dir='" + profile.string() + "' --enable-logging=stderr --v=0 " + extra +
      " 'file://" + page.string() + "' > '" + out.string() + "' 2> '" + err.string() + "'";
  return std::system(command.c_str());
}

// The text of <pre id="ID"> in a DOM chromium dumped ("" when absent).
inline std::string pre_text(const std::string& dom, const std::string& id) {
  const std::string open = "<pre id=\"" + id + "\">";
  const std::size_t start = dom.find(open);
  if (start == std::string::npos) return "";
  const std::size_t end = dom.find("</pre>", start);
  return dom.substr(start + open.size(), end - start - open.size());
}

// Line `k` of `text` split at blanks, as numbers (strtod reads JavaScript's shortest form of
// a double back to the same double, and "NaN").
inline std::vector<double> numbers_on_line(const std::string& text, int k) {
  std::istringstream lines(text);
  std::string line;
  // Past the last line: nothing (a failed getline leaves `line` as it was).
  for (int i = 0; i <= k; ++i) {
    if (!std::getline(lines, line)) return {};
  }
  std::vector<double> out;
  std::istringstream words(line);
  for (std::string word; words >> word;) out.push_back(std::strtod(word.c_str(), nullptr));
  return out;
}

// A script for the end of a report's <body>: on the first chart (window.limberReport.charts[0]),
// a zoom to [from, to] with its re-decimation run at once and timed, then a zoom to
// [from2, to2] left to the page's own timer. It leaves <pre id="result">: line 0 "LOAD ZOOM
// ROWS" (ms from navigation to the end of the page's scripts, ms of the first zoom, the
// chart's rows after it), lines 1 and 2 the times and first curve's values the chart holds in
// [from, to], lines 3 and 4 those in [from2, to2].
inline std::string zoom_probe_script(double from, double to, double from2, double to2) {
  return fmt::format(R"(<script>
(function () {{
  var loaded = performance.now(), r = window.limberReport, g = r.charts[0], lines = [];
  // Rows of the chart inside [a, b]: their times and X values.
  function shown(a, b) {{
    var t = [], v = [];
    for (var i = 0; i < g.numRows(); ++i) {{
      var x = g.getValue(i, 0);
      if (x >= a && x <= b) {{ t.push(String(x)); v.push(String(g.getValue(i, 1))); }}
    }}
    return [t.join(" "), v.join(" ")];
  }}
  var start = performance.now();
  g.updateOptions({{ dateWindow: [{0}, {1}] }});
  if (g.limberRefine) g.limberRefine();  // absent when the chart holds every sample
  var zoom = performance.now() - start;
  lines.push(loaded.toFixed(1) + " " + zoom.toFixed(1) + " " + g.numRows());
  lines = lines.concat(shown({0}, {1}));
  // The reader's way: the window moves, the page re-decimates from its timer.
  g.updateOptions({{ dateWindow: [{2}, {3}] }});
  setTimeout(function () {{
    lines = lines.concat(shown({2}, {3}));
    var pre = document.createElement("pre"); pre.id = "result"; pre.textContent = lines.join("\n");
    document.body.appendChild(pre);
  }}, 100);
}})();
</script>
)", from, to, from2, to2);
}

// A script for the end of a report's <body> that works the first chart as a reader does, with
// mouse events: a 20-pixel drag (zoom), a shift-drag of 400 pixels in ten steps (pan), a
// double-click (reset), each followed by a pause for the page's timer. It leaves <pre
// id="result"> with one line per state (start, zoomed, panned, reset): "FROM TO SHOWN ROWS",
// the chart's x range, its rows inside that range and all its rows.
inline std::string interaction_probe_script() {
  return R"(<script>
(function () {
  var g = window.limberReport.charts[0], lines = [];
  var area = g.getArea(), rect = g.mouseEventElement_.getBoundingClientRect(), x0 = area.x + area.w / 2;
  function send(type, x, shift, target) {
    (target || g.mouseEventElement_).dispatchEvent(new MouseEvent(type, {
      bubbles: true, cancelable: true, button: 0, shiftKey: shift,
      clientX: rect.left + x, clientY: rect.top + area.y + area.h / 2 }));
  }
  function state() {
    var range = g.xAxisRange(), shown = 0;
    for (var i = 0; i < g.numRows(); ++i) {
      var x = g.getValue(i, 0);
      if (x >= range[0] && x <= range[1]) ++shown;
    }
    lines.push(String(range[0]) + " " + String(range[1]) + " " + shown + " " + g.numRows());
  }
  state();
  send("mousedown", x0, false);
  send("mousemove", x0 + 10, false, document);
  send("mousemove", x0 + 20, false, document);
  send("mouseup", x0 + 20, false, document);
  setTimeout(function () {
    state();
    send("mousedown", x0, true);
    var step = 0;
    (function move() {
      send("mousemove", x0 - 40 * ++step, true, document);
      if (step < 10) { setTimeout(move, 20); return; }
      send("mouseup", x0 - 40 * step, true, document);
      setTimeout(function () {
        state();
        send("dblclick", x0, false);
        setTimeout(function () {
          state();
          var pre = document.createElement("pre"); pre.id = "result"; pre.textContent = lines.join("\n");
          document.body.appendChild(pre);
        }, 100);
      }, 100);
    })();
  }, 100);
})();
</script>
)";
}

}  // namespace limber::report::testing
