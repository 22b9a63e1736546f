// Child processes for `limber sweep`: every grid point is its own `limber run`, so each run
// stays single-threaded, a crash takes down one point only, and the kernel measures its peak
// memory (wait4's ru_maxrss). At most `parallel` children run at a time.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace limber::sweep {

struct ChildJob {
  std::vector<std::string> argv;     // argv[0] is the executable's path
  std::filesystem::path stdout_file; // created or truncated
  std::filesystem::path stderr_file;
};

struct ChildOutcome {
  int exit_code = -1;          // when it exited; -1 when killed by a signal or never started
  int signal = 0;              // the signal that ended it, 0 when it exited
  double wall_seconds = 0.0;   // from start to exit [s]
  long peak_rss_kib = 0;       // largest resident set [KiB] (Linux ru_maxrss)
  std::string spawn_error;     // why it could not start ("" when it did)
};

struct PoolHooks {
  std::function<void(std::size_t job)> on_start;
  std::function<void(std::size_t job, const ChildOutcome&)> on_finish;
  // Polled about every 0.2 s; on true no further job starts and running children get SIGTERM
  // (limber run then closes its file as "interrupted").
  std::function<bool()> should_stop;
  // Called about every 0.2 s while children run (a progress line).
  std::function<void()> on_tick;
};

// Runs `jobs` (in order, `parallel` >= 1 at a time) and returns when every started child has
// ended. Children inherit the environment; their stdout and stderr go to the job's files.
void run_processes(const std::vector<ChildJob>& jobs, int parallel, const PoolHooks& hooks);

}  // namespace limber::sweep
