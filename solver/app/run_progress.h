// The progress line of `limber run` on stderr: simulated time against the end time and the
// steps taken. Drawn only when stderr is a terminal (isatty), so piped output and logs stay
// clean; redrawn at most when the percentage changes.
#pragma once

namespace limber::app {

class RunProgress {
 public:
  // `t_end` [s] is 100 %; `enabled` false draws nothing.
  RunProgress(double t_end, bool enabled);
  // Ends the line if anything was drawn.
  ~RunProgress();
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  void update(double t, long steps);
  // Erases the line so a message can be printed; the next update redraws it.
  void clear();

 private:
  double t_end_;
  bool active_;
  int last_percent_ = -1;
};

}  // namespace limber::app
