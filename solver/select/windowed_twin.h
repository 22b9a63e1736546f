// The reference's convergence check in the step, run over its event windows only
// (docs/select.md, "Reference check"): instead of the whole run again at half the step, each
// event window is re-run at half the step from the reference's own state just before the
// window's event (run/window_restart.h) — the start window from t = 0, as the reference started.
// The slow motion between windows, which both would run at the case's step, is not re-run; what
// the check compares, the event peaks, all lie in the windows. So the check measures the window
// response's convergence from the same state, at the cost of the windows alone.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "results/event_peaks.h"
#include "run/window_restart.h"

namespace limber::select {

// One stretch of the reference re-run at half its step.
struct TwinStretch {
  std::optional<run::RestartPoint> restart;  // empty: from t = 0 (statics included)
  double t_end = 0.0;                        // [s]
  std::vector<std::string> windows;          // labels of the reference's windows it re-runs

  double t_start() const { return restart ? restart->t : 0.0; }
};

// The share of the window length a stretch runs on past its last window's end: the re-run
// meets its event a little later or earlier than the reference did (microseconds on the
// satellite), and its own window must still end inside the stretch.
inline constexpr double kStretchMargin = 0.05;

// The stretches that re-run every window of `reference` (its event peaks): the window opened at
// t = 0 from the start, each later one from the restart point before its event (`restarts`,
// matched by label, as run::RunHooks::on_window gave them), a window without one from the start.
// Each stretch ends kStretchMargin × the window length after its last window, at most at
// `t_end`; stretches that overlap are merged (twin latches engaging together share one).
// Ordered by start time.
std::vector<TwinStretch> twin_stretches(const results::EventPeaks& reference,
                                        const std::vector<run::WindowRestart>& restarts, double t_end);

// The reference's windows as the stretches re-ran them: per window of `reference`, the window
// of the same label in the peaks of the stretch that re-ran it (`stretch_peaks[k]` for
// `stretches[k]`). A window the re-run did not open (its event did not happen in the stretch)
// is left out, so compare_peaks finds it unmatched: an infinite change.
results::EventPeaks merge_stretch_peaks(const results::EventPeaks& reference,
                                        const std::vector<TwinStretch>& stretches,
                                        const std::vector<results::EventPeaks>& stretch_peaks);

}  // namespace limber::select
