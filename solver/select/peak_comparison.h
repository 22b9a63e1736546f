// Event peaks of a run against a reference run's (docs/select.md, "Event peaks"): per joint and
// window, the relative difference of the peak force and torque magnitudes (results/event_peaks.h,
// tracked at every integrator step). Unlike the sample-by-sample measure (series_error.h), a
// ringing that shifts in phase, or a latch-up a few milliseconds later, changes it only as much
// as it changes the loads a structure is sized for.
//
// Windows are matched by label ("start", "latch latch_R3"): a window that one run has and the
// other has not (an event that happened in one only) makes the comparison's error infinite and
// is named. A joint whose reference peak is below kPeakFloor of the window's largest peak of
// that kind (force or torque) is not compared: a relative difference of a load that is noise
// beside the window's main loads means nothing; nor one below kRoundOffFloor of the window's
// largest peak of either kind (forces in N and torques in N m compared as numbers, as `limber
// sweep` filters its quantities): the out-of-plane torques of a planar mechanism are round-off
// (1e-15 N m beside kN forces: an unreduced nonlinear rod makes them determinate and zero)
// or the minimum-norm split of redundant joints, whose relative differences are meaningless.
// Nor is a joint released at or before the
// window's start (a hold-down released at t = 0): after its release it carries nothing, and
// its value at the instant of release is its stowed preload, a static load that the
// minimum-norm rule splits among redundant supports (and so depends on the mode set), not the
// window's response.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "results/event_peaks.h"

namespace limber::select {

inline constexpr double kPeakFloor = 0.01;
inline constexpr double kRoundOffFloor = 1e-6;

// The window [s] over which `limber select` tracks event peaks unless the case or the command
// line sets one (RunSettings::peak_window): the first periods of a deployed panel's lowest
// modes (three at 10 Hz), where latch-up peaks occur.
inline constexpr double kSelectPeakWindow = 0.3;

// One joint in one window.
struct PeakDifference {
  std::string window;  // label
  std::string joint;
  double start = 0.0, reference_start = 0.0;  // window start in the run and in the reference [s]
  double force = 0.0, reference_force = 0.0;     // max |F| [N]
  double torque = 0.0, reference_torque = 0.0;   // max |T| [N m]
  double force_time = 0.0, reference_force_time = 0.0;  // when [s]
  // |peak − reference| / reference; NaN when not compared (reference below kPeakFloor).
  double force_error = std::numeric_limits<double>::quiet_NaN();
  double torque_error = std::numeric_limits<double>::quiet_NaN();
};

struct PeakComparison {
  std::vector<PeakDifference> rows;   // windows of the reference in order, joints in model order
  std::vector<std::string> unmatched; // window labels found in one run only
  // Largest force or torque error over the rows (infinite when a window is unmatched; NaN
  // when nothing was compared), and where: "R1 force, latch latch_R1".
  double error = std::numeric_limits<double>::quiet_NaN();
  std::string worst;
};

// Release time [s] of the joints that have one (Joint::release_time), by name.
using ReleaseTimes = std::map<std::string, double>;

// `run` against `reference`. Joints are matched by name (both runs of one case have the same).
PeakComparison compare_peaks(const results::EventPeaks& run, const results::EventPeaks& reference,
                             const ReleaseTimes& released = {});

}  // namespace limber::select
