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

std::vector<double> shock_frequency_grid(const ShockSpectrumSettings& settings, double longest_step) {
  const double limit = srs_frequency_limit(longest_step);
  const double f_max = settings.max_frequency_hz > 0.0 ? settings.max_frequency_hz : limit;
  const auto unsupported = [&](const char* which, double f) {
    return InputError(fmt::format(
        "expected an SRS {} frequency of at most {:g} Hz (1/{:g} of the record's longest step, {:g} s: the band the "
        "steps support), got {:g} Hz; steps of at most {:g} s support it",
        which, limit, kSrsSamplesPerPeriod, longest_step, f, 1.0 / (kSrsSamplesPerPeriod * f)));
  };
  if (settings.min_frequency_hz > limit * (1.0 + 1e-9)) throw unsupported("minimum", settings.min_frequency_hz);
  if (f_max > limit * (1.0 + 1e-9)) throw unsupported("maximum", f_max);
  return srs_frequency_grid(settings.min_frequency_hz, f_max);
}

namespace {

// The record's value at t by its linear interpolation over [time(k), time(k + 1)].
Eigen::RowVector3d interpolated(const Eigen::VectorXd& time, const ProbeHistory& probe, Eigen::Index k, double t) {
  const double h = time(k + 1) - time(k);
  const double r = h > 0.0 ? std::clamp((t - time(k)) / h, 0.0, 1.0) : 1.0;
  return (1.0 - r) * probe.acceleration.row(k) + r * probe.acceleration.row(k + 1);
}

// One window's record [start, end]: the points strictly inside it, and at its ends the
// interpolated values (after a jump at the start, before one at the end).
struct WindowRecord {
  Eigen::VectorXd time;
  Eigen::MatrixXd acceleration;  // [n, 3 probes]: probe p's axes in columns 3p .. 3p+2
};
WindowRecord window_record(const Eigen::VectorXd& time, const std::vector<ProbeHistory>& probes,
                           const ShockWindow& window) {
  const double* begin = time.data();
  const double* end = begin + time.size();
  // k0: the last point at or before the start; k1: the first at or after the end.
  const auto k0 = static_cast<Eigen::Index>(std::upper_bound(begin, end, window.start) - begin) - 1;
  const auto k1 = static_cast<Eigen::Index>(std::lower_bound(begin, end, window.end) - begin);
  LIMBER_DEMAND(k0 >= 0 && k1 < time.size() && k0 < k1);
  const Eigen::Index n = k1 - k0 + 1;
  WindowRecord record{Eigen::VectorXd(n), Eigen::MatrixXd(n, 3 * static_cast<Eigen::Index>(probes.size()))};
  record.time = time.segment(k0, n);
  record.time(0) = window.start;
  record.time(n - 1) = window.end;
  for (std::size_t p = 0; p < probes.size(); ++p) {
    auto columns = record.acceleration.middleCols(3 * static_cast<Eigen::Index>(p), 3);
    columns = probes[p].acceleration.middleRows(k0, n);
    columns.row(0) = interpolated(time, probes[p], std::min(k0, time.size() - 2), window.start);
    columns.row(n - 1) = interpolated(time, probes[p], k1 - 1, window.end);
  }
  return record;
}

}  // namespace

ShockSpectra shock_spectra(const Eigen::VectorXd& time, double band_step, const std::vector<ProbeHistory>& probes,
                           const std::vector<LatchTime>& latches, const ShockSpectrumSettings& settings) {
  LIMBER_DEMAND(settings.q > 0.0 && time.size() >= 2);
  ShockSpectra out;
  out.settings = settings;
  out.longest_step = longest_step(time);
  out.frequency_hz = shock_frequency_grid(settings, band_step);
  out.settings.max_frequency_hz = out.frequency_hz.back();
  const Eigen::Index n = time.size();
  for (const ProbeHistory& probe : probes) {
    LIMBER_DEMAND(probe.acceleration.rows() == n);
    out.probes.push_back({probe.name, {}});
  }
  const double zeta = 1.0 / (2.0 * settings.q);
  const double t_first = time(0), t_last = time(n - 1);
  for (const ShockWindow& window : shock_windows(t_first, t_last, latches, settings.window_seconds, out.longest_step)) {
    if (!(window.end > window.start)) continue;
    out.windows.push_back(window);
    // All probes and axes at once: the steps' coefficients are shared.
    const WindowRecord record = window_record(time, probes, window);
    const std::vector<ShockSpectrum> columns =
        shock_response_spectra(record.time, record.acceleration, out.frequency_hz, zeta);
    for (std::size_t p = 0; p < probes.size(); ++p) {
      out.probes[p].windows.push_back({columns[3 * p], columns[3 * p + 1], columns[3 * p + 2]});
    }
  }
  return out;
}

}  // namespace limber::results
