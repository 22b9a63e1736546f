#include "app/event_peaks_text.h"

#include <fmt/format.h>

#include "core/json_text.h"

namespace limber::app {

namespace {

std::string json_vector(const Eigen::Vector3d& v) {
  return fmt::format("[{}, {}, {}]", json_number(v(0)), json_number(v(1)), json_number(v(2)));
}

}  // namespace

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

std::string json_event_peaks(const results::EventPeaks& peaks) {
  std::string windows;
  for (std::size_t w = 0; w < peaks.windows.size(); ++w) {
    const results::PeakWindow& window = peaks.windows[w];
    std::string joints;
    for (std::size_t j = 0; j < peaks.joints.size(); ++j) {
      const results::JointPeak& p = window.joints[j];
      joints += fmt::format(
          "{}{{\"joint\": {}, \"force\": {}, \"force_time\": {}, \"torque\": {}, \"torque_time\": {}, "
          "\"force_component\": {}, \"force_component_time\": {}, \"torque_component\": {}, "
          "\"torque_component_time\": {}}}",
          j ? ", " : "", json_string(peaks.joints[j]), json_number(p.force), json_number(p.force_time),
          json_number(p.torque), json_number(p.torque_time), json_vector(p.force_component),
          json_vector(p.force_component_time), json_vector(p.torque_component), json_vector(p.torque_component_time));
    }
    windows += fmt::format("{}{{\"label\": {}, \"start\": {}, \"end\": {}, \"states\": {}, \"joints\": [{}]}}",
                           w ? ", " : "", json_string(window.start.label), json_number(window.start.t),
                           json_number(window.end), window.states, joints);
  }
  return fmt::format("{{\"window\": {}, \"windows\": [{}]}}", json_number(peaks.window), windows);
}

}  // namespace limber::app
