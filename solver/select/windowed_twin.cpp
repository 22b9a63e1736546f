#include "select/windowed_twin.h"

#include <algorithm>

#include "core/error.h"

namespace limber::select {

std::vector<TwinStretch> twin_stretches(const results::EventPeaks& reference,
                                        const std::vector<run::WindowRestart>& restarts, double t_end) {
  // One stretch per window, from its restart point (or the start).
  std::vector<TwinStretch> single;
  for (const results::PeakWindow& window : reference.windows) {
    TwinStretch stretch;
    if (window.start.t > 0.0) {
      const auto found = std::find_if(restarts.begin(), restarts.end(), [&](const run::WindowRestart& r) {
        return r.window.label == window.start.label && r.before.t < window.start.t;
      });
      if (found != restarts.end()) stretch.restart = found->before;
    }
    stretch.t_end = std::min(t_end, window.end + kStretchMargin * reference.window);
    stretch.windows.push_back(window.start.label);
    single.push_back(std::move(stretch));
  }
  std::stable_sort(single.begin(), single.end(),
                   [](const TwinStretch& a, const TwinStretch& b) { return a.t_start() < b.t_start(); });
  // Overlapping stretches merged into the earlier one.
  std::vector<TwinStretch> merged;
  for (TwinStretch& stretch : single) {
    if (!merged.empty() && stretch.t_start() <= merged.back().t_end) {
      merged.back().t_end = std::max(merged.back().t_end, stretch.t_end);
      merged.back().windows.push_back(stretch.windows.front());
      continue;
    }
    merged.push_back(std::move(stretch));
  }
  return merged;
}

results::EventPeaks merge_stretch_peaks(const results::EventPeaks& reference,
                                        const std::vector<TwinStretch>& stretches,
                                        const std::vector<results::EventPeaks>& stretch_peaks) {
  LIMBER_DEMAND(stretches.size() == stretch_peaks.size());
  results::EventPeaks merged;
  merged.window = reference.window;
  merged.joints = reference.joints;
  for (const results::PeakWindow& window : reference.windows) {
    for (std::size_t k = 0; k < stretches.size(); ++k) {
      const std::vector<std::string>& labels = stretches[k].windows;
      if (std::find(labels.begin(), labels.end(), window.start.label) == labels.end()) continue;
      const std::vector<results::PeakWindow>& rerun = stretch_peaks[k].windows;
      const auto same = std::find_if(rerun.begin(), rerun.end(), [&](const results::PeakWindow& w) {
        return w.start.label == window.start.label;
      });
      if (same != rerun.end()) merged.windows.push_back(*same);
    }
  }
  return merged;
}

}  // namespace limber::select
