#include "sizing_loads.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "core/markup_escape.h"

namespace limber::report {

namespace {

// A joint's peak in one window of one run; `found` false when the run has no such row.
struct Cell {
  bool found = false;
  results::JointPeak peak;
};

// "12.3 (4.191 s)" for a peak and its time, "–" when the run has none.
std::string peak_text(double value, double time) {
  if (!std::isfinite(time)) return "–";
  return fmt::format("{:.4g} <span class=\"note\">({:.3f} s)</span>", value, time);
}

std::string components_text(const Eigen::Vector3d& v) {
  return fmt::format("{:.3g}, {:.3g}, {:.3g}", v.x(), v.y(), v.z());
}

// (max − min) / max over the runs that have the row, or NaN with fewer than two.
double spread(const std::vector<Cell>& cells, double results::JointPeak::*value) {
  double low = INFINITY, high = 0.0;
  int count = 0;
  for (const Cell& c : cells) {
    if (!c.found) continue;
    low = std::min(low, c.peak.*value);
    high = std::max(high, c.peak.*value);
    ++count;
  }
  return count >= 2 && high > 0.0 ? (high - low) / high : NAN;
}

}  // namespace

std::string sizing_loads_section(const std::vector<RunSection>& runs) {
  // Rows in the order of the first run that has them: (window label, joint).
  std::vector<std::pair<std::string, std::string>> rows;
  std::map<std::pair<std::string, std::string>, std::vector<Cell>> table;
  std::map<std::string, double> window_start;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const RunData& run = *runs[r].run;
    const results::EventPeaks& peaks = run.event_peaks;
    std::map<std::string, std::string> types;
    for (const render::JointTrack& joint : run.results.joints) types[joint.name] = joint.type;
    for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
      const results::PeakWindow& window = peaks.windows[w];
      for (std::size_t j = 0; j < peaks.joints.size(); ++j) {
        const results::JointPeak& peak = window.joints[j];
        const bool hinge = types[peaks.joints[j]] == "revolute";
        if (!(hinge || w == 0) || (peak.force == 0.0 && peak.torque == 0.0)) continue;
        const auto key = std::make_pair(window.start.label, peaks.joints[j]);
        auto [it, added] = table.try_emplace(key, std::vector<Cell>(runs.size()));
        if (added) rows.push_back(key);
        it->second[r] = {true, peak};
        window_start.try_emplace(window.start.label, window.start.t);
      }
    }
  }
  if (rows.empty()) return "";

  std::string out =
      "<section id=\"sizing\">\n<h2>Loads for sizing</h2>\n"
      "<p>Per hinge and per event, the largest reaction on body j about its joint point, in the "
      "joint frame, tracked at every integrator step in the window after the event (not at the "
      "output samples; docs/results-format.md, \"Event peaks\"). Hold-downs and other joints are "
      "listed in the first window, where they carry the stowed preload.";
  if (runs.size() > 1) {
    out += " With several runs, <em>spread</em> is (largest − smallest) / largest over the runs: "
           "how far a richer mode set or a finer step moved the peak.";
  }
  out += "</p>\n<table><tr><th>window (from)</th><th>joint</th>";
  for (const RunSection& s : runs) {
    out += fmt::format("<th>{0}: |F| [N]</th><th>{0}: max |F_x|, |F_y|, |F_z| [N]</th><th>{0}: |T| [N m]</th>",
                       markup_escape(s.label));
  }
  if (runs.size() > 1) out += "<th>spread |F|</th><th>spread |T|</th>";
  out += "</tr>\n";
  for (const auto& key : rows) {
    const std::vector<Cell>& cells = table[key];
    out += fmt::format("<tr><td>{} ({:.4g} s)</td><td>{}</td>", markup_escape(key.first), window_start[key.first],
                       markup_escape(key.second));
    for (const Cell& c : cells) {
      if (!c.found) {
        out += "<td>–</td><td>–</td><td>–</td>";
        continue;
      }
      out += fmt::format("<td class=\"number\">{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>",
                         peak_text(c.peak.force, c.peak.force_time), components_text(c.peak.force_component),
                         peak_text(c.peak.torque, c.peak.torque_time));
    }
    if (runs.size() > 1) {
      const double f = spread(cells, &results::JointPeak::force), t = spread(cells, &results::JointPeak::torque);
      out += fmt::format("<td class=\"number\">{}</td><td class=\"number\">{}</td>",
                         std::isfinite(f) ? fmt::format("{:.1f} %", 100.0 * f) : "–",
                         std::isfinite(t) ? fmt::format("{:.1f} %", 100.0 * t) : "–");
    }
    out += "</tr>\n";
  }
  return out + "</table>\n</section>\n";
}

}  // namespace limber::report
