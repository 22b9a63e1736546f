#include "integrate/sample_times.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::integrate {

void check_sample_times(double t0, double t_end, double dt) {
  if (!(dt > 0.0)) throw InputError(fmt::format("sample interval: expected > 0, got {}", dt));
  if (!(t_end >= t0) || !std::isfinite(t_end)) {
    throw InputError(fmt::format("end time: expected a finite time ≥ {} (the start), got {}", t0, t_end));
  }
  // Bound the count before it is cast (an end time of 1e308 s overflowed it and crashed).
  const double count = std::floor((t_end - t0) / dt);
  if (!(count <= kMaxSamples)) {
    throw InputError(fmt::format("number of samples (end time {} s / sample interval {} s): expected "
                                 "at most {:g}, got {:g}; choose a larger sample interval",
                                 t_end - t0, dt, kMaxSamples, count));
  }
}

SampleTimes::SampleTimes(std::vector<double> times) : list_(std::move(times)), size_(list_.size()) {
  if (list_.empty()) throw InputError("sample times: expected at least one, got none");
  for (std::size_t i = 1; i < list_.size(); ++i) {
    if (!(list_[i] > list_[i - 1])) {
      throw InputError(fmt::format("sample time {}: expected > {} (strictly increasing), got {}", i,
                                   list_[i - 1], list_[i]));
    }
  }
}

SampleTimes SampleTimes::uniform(double t0, double t_end, double dt) {
  check_sample_times(t0, t_end, dt);
  // Grid points i dt up to round-off; t_end is appended unless the last point is within 1e-9 dt.
  const auto n = static_cast<std::size_t>(std::floor((t_end - t0) / dt * (1.0 + 1e-12)));
  const double last_grid_point = std::min(t0 + static_cast<double>(n) * dt, t_end);
  const std::size_t size = t_end - last_grid_point > 1e-9 * dt ? n + 2 : n + 1;
  return SampleTimes(t0, t_end, dt, size);
}

double SampleTimes::operator[](std::size_t i) const {
  if (!list_.empty()) return list_[i];
  if (i + 1 == size_) return t_end_;
  return std::min(t0_ + static_cast<double>(i) * dt_, t_end_);
}

std::vector<double> uniform_sample_times(double t0, double t_end, double dt) {
  const SampleTimes grid = SampleTimes::uniform(t0, t_end, dt);
  std::vector<double> times(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) times[i] = grid[i];
  return times;
}

}  // namespace limber::integrate
