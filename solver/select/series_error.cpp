#include "select/series_error.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace limber::select {

SeriesError series_error(const Eigen::VectorXd& t, const Eigen::VectorXd& x, const Eigen::VectorXd& t_ref,
                         const Eigen::VectorXd& x_ref) {
  LIMBER_DEMAND(t.size() == x.size() && t_ref.size() == x_ref.size());
  SeriesError error;
  if (t.size() == 0) return error;
  double largest_difference = 0.0, largest_reference = 0.0, sum_difference = 0.0, sum_reference = 0.0;
  Eigen::Index j = 0;  // run sample at or before the reference time
  for (Eigen::Index k = 0; k < t_ref.size(); ++k) {
    const double time = t_ref(k);
    if (time < t(0) || time > t(t.size() - 1)) continue;
    while (j + 1 < t.size() && t(j + 1) <= time) ++j;
    // Linear interpolation; weight 0 at a shared sample time, so the value is then exact.
    double value = x(j);
    if (t(j) < time && j + 1 < t.size()) {
      const double w = (time - t(j)) / (t(j + 1) - t(j));
      value = (1.0 - w) * x(j) + w * x(j + 1);
    }
    const double difference = value - x_ref(k);
    largest_difference = std::max(largest_difference, std::abs(difference));
    largest_reference = std::max(largest_reference, std::abs(x_ref(k)));
    sum_difference += difference * difference;
    sum_reference += x_ref(k) * x_ref(k);
    ++error.samples;
  }
  if (error.samples == 0 || !(largest_reference > 0.0)) return error;
  error.peak = largest_difference / largest_reference;
  error.rms = std::sqrt(sum_difference / sum_reference);
  return error;
}

}  // namespace limber::select
