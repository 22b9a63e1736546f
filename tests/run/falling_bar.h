// The second method of the hold-down tests (hold_down_run_test.cpp, event_release_run_test.cpp):
// a uniform bar hinged at one end (I = m L² / 3) falling from rest at θ = 0 under gravity g,
// θ̈ = 3 g cos θ / (2 L), integrated by RK4 at 1e-5 s (error ~1e-14 over the tests' spans).
#pragma once

#include <algorithm>
#include <cmath>

namespace limber::test {

// θ after `duration` [s] of the fall of a bar of length `length` [m] under `gravity` [m/s²].
inline double falling_bar_angle(double duration, double length, double gravity) {
  const auto accel = [&](double theta) { return 1.5 * gravity * std::cos(theta) / length; };
  const int n = std::max(1, static_cast<int>(std::lround(duration / 1e-5)));
  const double h = duration / n;
  double th = 0.0, w = 0.0;
  for (int i = 0; i < n; ++i) {
    const double k1t = w, k1w = accel(th);
    const double k2t = w + 0.5 * h * k1w, k2w = accel(th + 0.5 * h * k1t);
    const double k3t = w + 0.5 * h * k2w, k3w = accel(th + 0.5 * h * k2t);
    const double k4t = w + h * k3w, k4w = accel(th + h * k3t);
    th += h / 6.0 * (k1t + 2 * k2t + 2 * k3t + k4t);
    w += h / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return th;
}

}  // namespace limber::test
