#include "app/event_peaks_text.h"

#include <fmt/format.h>

namespace limber::app {

void print_event_peaks(std::FILE* out, const results::EventPeaks& peaks) {
  if (peaks.windows.empty()) return;
  fmt::print(out, "event peaks (largest reaction on body j at every step, {:g} s after each event):\n",
             peaks.window);
  for (const results::PeakWindow& window : peaks.windows) {
    fmt::print(out, "  {} at {:.6g} s ({} steps in the window)\n", window.start.label, window.start.t, window.states);
    for (std::size_t j = 0; j < peaks.joints.size() && window.states > 0; ++j) {
      const results::JointPeak& p = window.joints[j];
      fmt::print(out, "    {:<12} |F| {:>10.4g} N at {:<9.6g} |T| {:>10.4g} N m at {:.6g}\n", peaks.joints[j], p.force,
                 p.force_time, p.torque, p.torque_time);
    }
  }
}

}  // namespace limber::app
