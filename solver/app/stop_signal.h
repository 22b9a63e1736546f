// SIGINT (Ctrl-C) and SIGTERM (a batch system's stop) ask a long command to stop at its next
// safe point, so that it can close its files as "interrupted" instead of being killed
// mid-write. While a StopSignals lives, the first such signal is recorded; a second one
// falls back to the default action (the process ends at once).
#pragma once

namespace limber::app {

class StopSignals {
 public:
  StopSignals();   // installs the handlers
  ~StopSignals();  // restores the default actions
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received since construction, or 0.
  static int received();
};

}  // namespace limber::app
