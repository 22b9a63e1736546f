#include "app/run_progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace limber::app {

RunProgress::RunProgress(double t_end, bool enabled)
    : t_end_(t_end), active_(enabled && isatty(STDERR_FILENO) == 1) {}

RunProgress::~RunProgress() {
  if (active_ && last_percent_ >= 0) std::fputc('\n', stderr);
}

void RunProgress::update(double t, long steps) {
  if (!active_) return;
  const int percent = t_end_ > 0.0 ? std::clamp(static_cast<int>(100.0 * t / t_end_), 0, 100) : 100;
  if (percent == last_percent_) return;
  last_percent_ = percent;
  // 30-character bar redrawn in place.
  constexpr int kWidth = 30;
  const int filled = kWidth * percent / 100;
  std::fprintf(stderr, "\rrun [%.*s%*s] %3d%%  t = %.4g s  %ld steps", filled,
               "##############################", kWidth - filled, "", percent, t, steps);
  std::fflush(stderr);
}

void RunProgress::clear() {
  if (!active_ || last_percent_ < 0) return;
  std::fputs("\r\033[K", stderr);
  last_percent_ = -1;
}

}  // namespace limber::app
