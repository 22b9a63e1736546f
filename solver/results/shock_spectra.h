// The shock response spectra of a run's acceleration probes (docs/shock-response-spectrum.md):
// per probe and per ground axis, the maximax SRS (shock_spectrum.h) of the whole run and of
// each event window, from the probes' record at the integrator's steps (not only the output
// samples), whose longest step sets the band.
//
// Windows: "whole run" [t_0, t_last]; then one from t = 0 ("start") and one from each latch
// event ("latch <name>" at its time), each lasting `window_length` or up to the next of those
// starts or the last point, whichever comes first. Latches that lock within one longest step
// of the previous start share its window ("latch L3, L4": a symmetric deployment's wings). A
// window's record is the points inside it with the record's linear interpolation at its ends
// (at a jump, the value after it at the start and before it at the end); one that spans no
// time is left out.
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
// limit of the record's longest step, shock_spectrum.h), Q, and the event windows' length.
struct ShockSpectrumSettings {
  double min_frequency_hz = kDefaultSrsMinFrequencyHz;
  double max_frequency_hz = 0.0;  // [Hz]; 0: the band limit 1/(10 h_max)
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

// The windows of a run whose record spans [t_first, t_last] (see the top of this file);
// latches less than `merge_seconds` (the record's longest step) after the previous start join it.
std::vector<ShockWindow> shock_windows(double t_first, double t_last, const std::vector<LatchTime>& latches,
                                       double window_seconds, double merge_seconds);

// One probe's accelerations, ground axes [m/s²], one row per point of the record.
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
  double longest_step = 0.0;       // the record's longest step as taken [s]
  std::vector<double> frequency_hz;
  std::vector<ShockWindow> windows;
  std::vector<ProbeSpectra> probes;
};

// The frequency grid of `settings` for a record whose steps are at most `longest_step` [s].
// Throws InputError when it asks for frequencies above the band limit 1/(10 longest_step)
// (message naming the limit and the longest step that would support them), or when min > max.
std::vector<double> shock_frequency_grid(const ShockSpectrumSettings& settings, double longest_step);

// The spectra of `probes` recorded at `time` (n points, not decreasing, spanning a positive
// time; every history has n rows) over the windows of shock_windows, on the grid of `settings`
// checked against `band_step` [s], the longest step the record was promised (a run's
// io::probe_record_step; generalized-α may exceed it by the 1 % of a step too short to report).
// Throws InputError as shock_frequency_grid.
ShockSpectra shock_spectra(const Eigen::VectorXd& time, double band_step, const std::vector<ProbeHistory>& probes,
                           const std::vector<LatchTime>& latches, const ShockSpectrumSettings& settings);

}  // namespace limber::results
