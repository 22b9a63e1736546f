#include "results/shock_spectra.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "core/error.h"

namespace limber::results {

std::vector<ShockWindow> shock_windows(double t_first, double t_last, const std::vector<LatchTime>& latches,
                                       double window_seconds, double merge_seconds) {
  LIMBER_DEMAND(window_seconds > 0.0 && t_last >= t_first);
  std::vector<ShockWindow> windows{{"whole run", t_first, t_last}};
  // Window starts in time order: t = 0, then the latches inside the run, those within
  // merge_seconds of the previous start joining its window.
  std::vector<LatchTime> inside;
  std::copy_if(latches.begin(), latches.end(), std::back_inserter(inside),
               [&](const LatchTime& latch) { return latch.time >= t_first && latch.time <= t_last; });
  std::stable_sort(inside.begin(), inside.end(), [](const LatchTime& a, const LatchTime& b) { return a.time < b.time; });
  std::vector<ShockWindow> starts{{"start", t_first, t_last}};
  for (const LatchTime& latch : inside) {
    ShockWindow& previous = starts.back();
    if (latch.time - previous.start < merge_seconds) {
      previous.name += (starts.size() == 1 ? ", latch " : ", ") + latch.name;
    } else {
      starts.push_back({"latch " + latch.name, latch.time, t_last});
    }
  }
  // Each lasts window_seconds, or up to the next start or the last sample.
  for (std::size_t k = 0; k < starts.size(); ++k) {
    ShockWindow window = starts[k];
    window.end = std::min(window.start + window_seconds, t_last);
    if (k + 1 < starts.size()) window.end = std::min(window.end, starts[k + 1].start);
    windows.push_back(window);
  }
  return windows;
}

std::vector<double> shock_frequency_grid(const ShockSpectrumSettings& settings, double dt) {
  const double limit = srs_frequency_limit(dt);
  const double f_max = settings.max_frequency_hz > 0.0 ? settings.max_frequency_hz : limit;
  const auto unsupported = [&](const char* which, double f) {
    return InputError(fmt::format(
        "expected an SRS {} frequency of at most {:g} Hz (fs/{:g} for samples {:g} s apart: the band the "
        "sampling supports), got {:g} Hz; a sample_interval of at most {:g} s supports it",
        which, limit, kSrsSamplesPerPeriod, dt, f, 1.0 / (kSrsSamplesPerPeriod * f)));
  };
  if (settings.min_frequency_hz > limit * (1.0 + 1e-9)) throw unsupported("minimum", settings.min_frequency_hz);
  if (f_max > limit * (1.0 + 1e-9)) throw unsupported("maximum", f_max);
  return srs_frequency_grid(settings.min_frequency_hz, f_max);
}

ShockSpectra shock_spectra(const Eigen::VectorXd& time, double dt, const std::vector<ProbeHistory>& probes,
                           const std::vector<LatchTime>& latches, const ShockSpectrumSettings& settings) {
  LIMBER_DEMAND(settings.q > 0.0 && dt > 0.0);
  ShockSpectra out;
  out.settings = settings;
  out.frequency_hz = shock_frequency_grid(settings, dt);
  out.settings.max_frequency_hz = out.frequency_hz.back();
  // The uniform part of the record: a last sample at t_end off the grid is left out.
  Eigen::Index ns = time.size();
  while (ns > 0 && std::abs(time(ns - 1) - (time(0) + static_cast<double>(ns - 1) * dt)) > 1e-6 * dt) --ns;
  if (ns < 2) return out;
  // Each window's samples [first, first + count).
  const double slack = 1e-9 * dt;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> ranges;
  for (const ShockWindow& window : shock_windows(time(0), time(ns - 1), latches, settings.window_seconds, dt)) {
    const auto first = static_cast<Eigen::Index>(std::ceil((window.start - time(0) - slack) / dt));
    const auto last = std::min(ns - 1, static_cast<Eigen::Index>(std::floor((window.end - time(0) + slack) / dt)));
    if (last - first + 1 < 2) continue;
    out.windows.push_back(window);
    ranges.emplace_back(first, last - first + 1);
  }
  const double zeta = 1.0 / (2.0 * settings.q);
  for (const ProbeHistory& probe : probes) {
    LIMBER_DEMAND(probe.acceleration.rows() == time.size());
    ProbeSpectra spectra{probe.name, {}};
    for (const auto& [first, count] : ranges) {
      std::array<ShockSpectrum, 3> axes;
      for (int axis = 0; axis < 3; ++axis) {
        const Eigen::VectorXd record = probe.acceleration.col(axis).segment(first, count);
        axes[static_cast<std::size_t>(axis)] = shock_response_spectrum(record, dt, out.frequency_hz, zeta);
      }
      spectra.windows.push_back(std::move(axes));
    }
    out.probes.push_back(std::move(spectra));
  }
  return out;
}

}  // namespace limber::results
