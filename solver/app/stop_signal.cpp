#include "app/stop_signal.h"

#include <csignal>

namespace limber::app {
namespace {

volatile std::sig_atomic_t g_received = 0;

extern "C" void record_stop(int signal) {
  g_received = signal;
  // A second signal ends the process: the user insists.
  std::signal(signal, SIG_DFL);
}

}  // namespace

StopSignals::StopSignals() {
  g_received = 0;
  std::signal(SIGINT, record_stop);
  std::signal(SIGTERM, record_stop);
}

StopSignals::~StopSignals() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

int StopSignals::received() { return g_received; }

}  // namespace limber::app
