// A one-line progress bar on stderr, drawn only when stderr is a terminal (isatty): logs and
// CI output stay clean.
#pragma once

#include <string>

namespace limber::render {

class ProgressBar {
 public:
  // `total` steps labelled `label`; `enabled` false draws nothing.
  ProgressBar(std::string label, int total, bool enabled);
  // Ends the line if anything was drawn.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Shows `done` of total steps (redrawn when the percentage changes).
  void update(int done);
  bool active() const { return active_; }

 private:
  std::string label_;
  int total_;
  bool active_;
  int last_percent_ = -1;
};

}  // namespace limber::render
