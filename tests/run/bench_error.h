// The benchmarks' accuracy measure: the rms of a deflection history's difference from a
// reference, over the reference's rms (common samples only).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace limber::run::bench {

inline double rms(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, x.size())));
}

inline double relative_rms_error(const std::vector<double>& value, const std::vector<double>& reference) {
  std::vector<double> difference;
  for (std::size_t k = 0; k < std::min(value.size(), reference.size()); ++k) {
    difference.push_back(value[k] - reference[k]);
  }
  return rms(difference) / rms(reference);
}

}  // namespace limber::run::bench
