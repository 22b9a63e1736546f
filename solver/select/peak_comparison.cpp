#include "select/peak_comparison.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace limber::select {

namespace {

const results::PeakWindow* find_window(const results::EventPeaks& peaks, const std::string& label) {
  const auto it = std::find_if(peaks.windows.begin(), peaks.windows.end(),
                               [&](const results::PeakWindow& w) { return w.start.label == label; });
  return it == peaks.windows.end() ? nullptr : &*it;
}

// |value − reference| / reference when the reference is at least the floor, else NaN.
double relative(double value, double reference, double floor) {
  return reference > 0.0 && reference >= floor ? std::abs(value - reference) / reference
                                               : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

PeakComparison compare_peaks(const results::EventPeaks& run, const results::EventPeaks& reference,
                             const ReleaseTimes& released) {
  PeakComparison out;
  for (const results::PeakWindow& window : run.windows) {
    if (!find_window(reference, window.start.label)) out.unmatched.push_back(window.start.label);
  }
  double worst = -1.0;
  for (const results::PeakWindow& ref : reference.windows) {
    const results::PeakWindow* mine = find_window(run, ref.start.label);
    if (!mine) {
      out.unmatched.push_back(ref.start.label);
      continue;
    }
    // The window's largest reference peaks set the floors.
    double largest_force = 0.0, largest_torque = 0.0;
    for (const results::JointPeak& p : ref.joints) {
      largest_force = std::max(largest_force, p.force);
      largest_torque = std::max(largest_torque, p.torque);
    }
    const double round_off = kRoundOffFloor * std::max(largest_force, largest_torque);
    const double force_floor = std::max(kPeakFloor * largest_force, round_off);
    const double torque_floor = std::max(kPeakFloor * largest_torque, round_off);
    for (std::size_t j = 0; j < reference.joints.size(); ++j) {
      const auto at = std::find(run.joints.begin(), run.joints.end(), reference.joints[j]);
      if (at == run.joints.end()) continue;
      const results::JointPeak& r = ref.joints[j];
      const results::JointPeak& p = mine->joints[static_cast<std::size_t>(at - run.joints.begin())];
      PeakDifference row{ref.start.label, reference.joints[j], mine->start.t, ref.start.t, p.force, r.force,
                         p.torque, r.torque, p.force_time, r.force_time};
      const auto release = released.find(row.joint);
      if (release == released.end() || release->second > ref.start.t) {
        row.force_error = relative(p.force, r.force, force_floor);
        row.torque_error = relative(p.torque, r.torque, torque_floor);
      }
      for (const auto& [error, kind] : {std::pair{row.force_error, "force"}, std::pair{row.torque_error, "torque"}}) {
        if (!std::isnan(error) && error > worst) {
          worst = error;
          out.worst = fmt::format("{} {}, {}", row.joint, kind, row.window);
        }
      }
      out.rows.push_back(row);
    }
  }
  if (worst >= 0.0) out.error = worst;
  if (!out.unmatched.empty()) {
    out.error = std::numeric_limits<double>::infinity();
    out.worst = fmt::format("window(s) in one run only: {}", fmt::join(out.unmatched, ", "));
  }
  return out;
}

}  // namespace limber::select
