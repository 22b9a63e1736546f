// The difference of one quantity's series to a reference series, as `limber select` and
// `limber sweep` measure it (docs/select.md, docs/sweep.md): relative to the reference's own
// size, on the reference's samples.
//   peak: max_k |x(t_k) − x_ref(t_k)| / max_k |x_ref(t_k)|
//   rms:  sqrt(Σ_k (x(t_k) − x_ref(t_k))²) / sqrt(Σ_k x_ref(t_k)²)
// over the reference sample times t_k inside the run's [t_0, t_last]; x(t_k) is interpolated
// linearly between the run's samples (exact where the two share their sample times, as runs of
// one case with one sample interval do).
#pragma once

#include <limits>

#include <Eigen/Core>

namespace limber::select {

struct SeriesError {
  double peak = std::numeric_limits<double>::quiet_NaN();  // relative, NaN when not measured
  double rms = std::numeric_limits<double>::quiet_NaN();
  int samples = 0;  // reference samples compared
};

// Precondition: t and x have equal sizes, so do t_ref and x_ref; both time series ascend.
// NaN errors when no reference sample lies in the run's time span or the reference is zero
// there.
SeriesError series_error(const Eigen::VectorXd& t, const Eigen::VectorXd& x, const Eigen::VectorXd& t_ref,
                         const Eigen::VectorXd& x_ref);

}  // namespace limber::select
