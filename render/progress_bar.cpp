#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace limber::render {

ProgressBar::ProgressBar(std::string label, int total, bool enabled)
    : label_(std::move(label)), total_(std::max(total, 1)),
      active_(enabled && isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
  if (active_ && last_percent_ >= 0) std::fputc('\n', stderr);
}

void ProgressBar::update(int done) {
  if (!active_) return;
  const int percent = std::clamp(100 * done / total_, 0, 100);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  // 30-character bar, carriage return to redraw in place.
  constexpr int kWidth = 30;
  const int filled = kWidth * percent / 100;
  std::fprintf(stderr, "\r%s [%.*s%*s] %3d%% (%d/%d)", label_.c_str(), filled,
               "##############################", kWidth - filled, "", percent, done, total_);
  std::fflush(stderr);
}

}  // namespace limber::render
