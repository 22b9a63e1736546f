// The wall-clock budget of an integration (IntegratorOptions::max_wall_seconds): started by
// init(), asked after every step, so that no run can go on unseen for ever.
#pragma once

#include <chrono>
#include <cmath>

namespace limber::integrate {

class WallClockBudget {
 public:
  // `seconds` may be +inf (no budget).
  void start(double seconds) {
    seconds_ = seconds;
    start_ = std::chrono::steady_clock::now();
  }
  bool spent() const {
    if (std::isinf(seconds_)) return false;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > seconds_;
  }

 private:
  double seconds_ = INFINITY;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace limber::integrate
