#include "stress_summary.h"

#include <fmt/format.h>

namespace limber::report {

std::vector<StressPeak> stress_peaks(const RunData& run) {
  std::vector<StressPeak> peaks;
  for (std::size_t b = 0; b < run.stresses.size() && b < run.results.bodies.size(); ++b) {
    const std::optional<render::StressTrack>& track = run.stresses[b];
    if (!track || track->peak.size() == 0) continue;
    const render::BodyTrack& body = run.results.bodies[b];
    StressPeak peak;
    peak.body = body.name;
    Eigen::Index k = 0;
    peak.value = track->peak.maxCoeff(&k);
    peak.time = run.results.time(k);
    peak.element = track->peak_element(k);
    // The element's name in the case's numbering and its centre.
    const auto lines = static_cast<int>(body.mesh.lines.rows());
    const auto& nodes = body.mesh.nodes;
    if (peak.element < lines) {
      peak.element_name = fmt::format("beam {}", peak.element + 1);
      for (int n : {0, 1}) peak.centre_B += nodes.row(body.mesh.lines(peak.element, n)).transpose() / 2.0;
    } else if (peak.element - lines < body.mesh.quads.rows()) {
      const int q = peak.element - lines;
      peak.element_name = lines == 0 ? fmt::format("quad {}", q + 1)
                                     : fmt::format("quad {} (element {})", q + 1, peak.element + 1);
      for (int n = 0; n < 4; ++n) peak.centre_B += nodes.row(body.mesh.quads(q, n)).transpose() / 4.0;
    }
    // The last hinge event before the peak.
    for (const HingeEventRow& e : run.events) {
      if (e.time > peak.time) break;
      const HingeLimitTrack& limit = run.hinge_limits[static_cast<std::size_t>(e.limit)];
      const char* what = limit.kind == "latch" ? "locked" : (e.engaged ? "made contact" : "lost contact");
      peak.after = fmt::format("{:.3f} s after {} {}", peak.time - e.time, limit.name, what);
    }
    peaks.push_back(std::move(peak));
  }
  return peaks;
}

}  // namespace limber::report
