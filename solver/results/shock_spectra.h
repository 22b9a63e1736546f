// The shock response spectra of a run's acceleration probes (docs/shock-response-spectrum.md):
// per probe and per ground axis, the maximax SRS (shock_spectrum.h) of the whole run and of
// each event window.
//
// Windows: "whole run" [t_0, t_last]; then one from t = 0 ("start") and one from each latch
// event ("latch <name>" at its time), each lasting `window_length` or up to the next of those
// starts or the last sample, whichever comes first. Latches that lock within one sample
// interval of the previous start share its window ("latch L3, L4": a symmetric deployment's
// wings). A window holds the samples with start ≤ t ≤ end (1e-9 dt of slack); one with fewer
// than 2 samples is left out.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "results/shock_spectrum.h"

namespace limber::results {

inline constexpr double kDefaultShockWindowSeconds = 0.3;  // a latch shock rings down well within it
inline constexpr double kStandardGravity = 9.80665;        // [m/s²], 1 g for the spectra in g

// What to compute: the 1/6-octave grid from min_frequency_hz to max_frequency_hz (≤ the band
// limit of the sample interval, shock_spectrum.h), Q, and the event windows' length.
struct ShockSpectrumSettings {
  double min_frequency_hz = kDefaultSrsMinFrequencyHz;
  double max_frequency_hz = 0.0;  // [Hz]; 0: the band limit fs/10
  double q = kDefaultSrsQ;        // ζ = 1/(2Q), Q > 0
  double window_seconds = kDefaultShockWindowSeconds;  // > 0
};

struct ShockWindow {
  std::string name;  // "whole run", "start", "latch <name>"
  double start = 0.0, end = 0.0;  // [s]
};

// A latch's locking time (a run's events with engaged latches).
struct LatchTime {
  std::string name;
  double time = 0.0;  // [s]
};

// The windows of a run whose samples span [t_first, t_last] (see the top of this file);
// latches less than `merge_seconds` (the sample interval) after the previous start join it.
std::vector<ShockWindow> shock_windows(double t_first, double t_last, const std::vector<LatchTime>& latches,
                                       double window_seconds, double merge_seconds);

// One probe's accelerations, ground axes [m/s²], one row per sample.
struct ProbeHistory {
  std::string name;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> acceleration;
};

struct ProbeSpectra {
  std::string probe;
  // Per window (ShockSpectra::windows), per ground axis x, y, z [m/s²].
  std::vector<std::array<ShockSpectrum, 3>> windows;
};

struct ShockSpectra {
  ShockSpectrumSettings settings;  // max_frequency_hz resolved
  std::vector<double> frequency_hz;
  std::vector<ShockWindow> windows;
  std::vector<ProbeSpectra> probes;
};

// The frequency grid of `settings` for samples dt [s] apart. Throws InputError when it asks for
// frequencies above the band limit fs/10 (message naming the limit and the sample interval
// that would support them), or when min > max.
std::vector<double> shock_frequency_grid(const ShockSpectrumSettings& settings, double dt);

// The spectra of `probes` sampled at `time` (ns samples, uniform dt [s] apart; every history
// has ns rows) over the windows of shock_windows. Throws InputError as shock_frequency_grid.
ShockSpectra shock_spectra(const Eigen::VectorXd& time, double dt, const std::vector<ProbeHistory>& probes,
                           const std::vector<LatchTime>& latches, const ShockSpectrumSettings& settings);

}  // namespace limber::results
