#include "sizing_loads.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "core/markup_escape.h"

namespace limber::report {

namespace {

// Windows that open within this time are one (a symmetric deployment's twin latches) [s].
constexpr double kSameTime = 1e-6;

// (window, joint) of a table row.
using RowKey = std::pair<std::string, std::string>;

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

// The three joint-frame components, rounding shown as 0.
std::string components_text(const Eigen::Vector3d& v, double floor) {
  const auto c = [floor](double x) { return x <= floor ? 0.0 : x; };
  return fmt::format("{:.3g}, {:.3g}, {:.3g}", c(v.x()), c(v.y()), c(v.z()));
}

// (max − min) / max over the runs that have the row, or NaN with fewer than two or when the
// largest is rounding (at most `floor`).
double spread(const std::vector<Cell>& cells, double results::JointPeak::*value, double floor) {
  double low = INFINITY, high = 0.0;
  int count = 0;
  for (const Cell& c : cells) {
    if (!c.found) continue;
    low = std::min(low, c.peak.*value);
    high = std::max(high, c.peak.*value);
    ++count;
  }
  return count >= 2 && high > floor ? (high - low) / high : NAN;
}


// One table of `rows`; `floor_force`, `floor_torque`: values at or below are rounding ("≈ 0").
std::string loads_table(const std::vector<RunSection>& runs, const std::vector<RowKey>& rows,
                        const std::map<RowKey, std::vector<Cell>>& table,
                        const std::map<std::string, double>& window_start, double floor_force,
                        double floor_torque) {
  std::string out = "<table><tr><th>window (from)</th><th>joint</th>";
  for (const RunSection& s : runs) {
    out += fmt::format("<th>{0}: |F| [N]</th><th>{0}: max |F_x|, |F_y|, |F_z| [N]</th><th>{0}: |T| [N m]</th>",
                       markup_escape(s.label));
  }
  if (runs.size() > 1) out += "<th>spread |F|</th><th>spread |T|</th>";
  out += "</tr>\n";
  const auto value = [](double v, double t, double floor) {
    return v <= floor ? std::string("≈ 0") : peak_text(v, t);
  };
  for (const RowKey& key : rows) {
    const std::vector<Cell>& cells = table.at(key);
    out += fmt::format("<tr><td>{} ({:.4g} s)</td><td>{}</td>", markup_escape(key.first),
                       window_start.at(key.first), markup_escape(key.second));
    for (const Cell& c : cells) {
      if (!c.found) {
        out += "<td>–</td><td>–</td><td>–</td>";
        continue;
      }
      out += fmt::format("<td class=\"number\">{}</td><td class=\"number\">{}</td><td class=\"number\">{}</td>",
                         value(c.peak.force, c.peak.force_time, floor_force),
                         components_text(c.peak.force_component, floor_force),
                         value(c.peak.torque, c.peak.torque_time, floor_torque));
    }
    if (runs.size() > 1) {
      const double f = spread(cells, &results::JointPeak::force, floor_force);
      const double t = spread(cells, &results::JointPeak::torque, floor_torque);
      out += fmt::format("<td class=\"number\">{}</td><td class=\"number\">{}</td>",
                         std::isfinite(f) ? fmt::format("{:.1f} %", 100.0 * f) : "–",
                         std::isfinite(t) ? fmt::format("{:.1f} %", 100.0 * t) : "–");
    }
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

}  // namespace

std::string sizing_loads_section(const std::vector<RunSection>& runs) {
  // Rows in the order of the first run that has them; windows that open together (within
  // kSameTime) are one window, named after all of them.
  std::vector<RowKey> hinge_rows, other_rows;
  std::map<RowKey, std::vector<Cell>> table;
  std::map<std::string, double> window_start;  // as the first run that has it saw it
  double largest_force = 0.0, largest_torque = 0.0;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const RunData& run = *runs[r].run;
    const results::EventPeaks& peaks = run.event_peaks;
    std::map<std::string, std::string> types;
    for (const render::JointTrack& joint : run.results.joints) types[joint.name] = joint.type;
    std::vector<std::vector<std::string>> names(peaks.windows.size());
    std::vector<bool> repeat(peaks.windows.size(), false);
    for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
      names[w] = {peaks.windows[w].start.label};
      for (std::size_t v = 0; v < w && !repeat[w]; ++v) {
        if (std::abs(peaks.windows[v].start.t - peaks.windows[w].start.t) > kSameTime || repeat[v]) continue;
        repeat[w] = true;
        names[v].push_back(peaks.windows[w].start.label);
      }
    }
    for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
      if (repeat[w]) continue;
      // Keyed by the events, not their times: the runs' same latch-up side by side.
      std::sort(names[w].begin(), names[w].end());
      const std::string window = fmt::format("{}", fmt::join(names[w], ", "));
      window_start.try_emplace(window, peaks.windows[w].start.t);
      for (std::size_t j = 0; j < peaks.joints.size(); ++j) {
        const results::JointPeak& peak = peaks.windows[w].joints[j];
        const bool hinge = types[peaks.joints[j]] == "revolute";
        if (!(hinge || w == 0) || (peak.force == 0.0 && peak.torque == 0.0)) continue;
        const RowKey key(window, peaks.joints[j]);
        auto [it, added] = table.try_emplace(key, std::vector<Cell>(runs.size()));
        if (added) (hinge ? hinge_rows : other_rows).push_back(key);
        it->second[r] = {true, peak};
        largest_force = std::max(largest_force, peak.force);
        largest_torque = std::max(largest_torque, peak.torque);
      }
    }
  }
  if (hinge_rows.empty() && other_rows.empty()) return "";
  // Rounding: a millionth of the largest (a revolute's torque about its own free axis).
  const double floor_force = 1e-6 * largest_force, floor_torque = 1e-6 * std::max(largest_torque, largest_force);

  std::string out =
      "<section id=\"sizing\">\n<h2>Loads for sizing</h2>\n"
      "<p>Per hinge and per event, the largest reaction on body j about its joint point, in the "
      "joint frame, tracked at every integrator step in the window after the event (not at the "
      "output samples; docs/results-format.md, \"Event peaks\"). \"≈ 0\": below a millionth of the "
      "largest load, rounding.";
  if (runs.size() > 1) {
    out += " <em>Spread</em> is (largest − smallest) / largest over the runs: how far a richer "
           "mode set or a finer step moved the peak.";
  }
  out += "</p>\n" + loads_table(runs, hinge_rows, table, window_start, floor_force, floor_torque);
  if (!other_rows.empty()) {
    out += fmt::format("<details><summary>Hold-downs, brackets and other joints in the first window "
                       "({} rows): the stowed preload they carry until the release</summary>\n{}</details>\n",
                       other_rows.size(), loads_table(runs, other_rows, table, window_start, floor_force, floor_torque));
  }
  return out + "</section>\n";
}

}  // namespace limber::report
