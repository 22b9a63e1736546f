// How far the momentum of a free-floating system drifted over a run (docs/report.md "Summary"):
// with no joint to ground and no gravity nothing outside acts on the bodies, so the linear
// and angular momentum results.h5 stores (/momentum) stay at their first values up to the
// integration's error. Computed from run data only.
#pragma once

#include "run_data.h"

#include <optional>

namespace limber::report {

// The change from the first to the last sample, |P_last − P_first| [kg m/s] and
// |L_last − L_first| [kg m²/s], each also relative to its scale: the larger of the first value
// and of the momentum of the whole mass moving with the peak kinetic energy, sqrt(2 m T_peak)
// (times the system's size, the largest distance between two body origins at the first
// sample, for L). A system at rest at the start has P_first = 0: the scale is what moves.
struct MomentumDrift {
  double linear = 0.0, angular = 0.0;                // absolute drift
  double linear_scale = 0.0, angular_scale = 0.0;    // 0 when masses or energy are missing
  double linear_relative() const { return linear_scale > 0.0 ? linear / linear_scale : 0.0; }
  double angular_relative() const { return angular_scale > 0.0 ? angular / angular_scale : 0.0; }
};

// The drift of `run`, or none when it does not apply: no /momentum (older files), fewer than
// two samples, a joint to ground (its reaction is an outside force), or a gravity energy that
// changes (gravity is one too).
std::optional<MomentumDrift> momentum_drift(const RunData& run);

}  // namespace limber::report
