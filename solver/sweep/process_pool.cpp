#include "sweep/process_pool.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

#include "core/error.h"

extern char** environ;

namespace limber::sweep {

namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  std::size_t job = 0;
  Clock::time_point start;
};

// Starts one child with stdout and stderr redirected; returns its pid or -1 with `error` set.
pid_t spawn(const ChildJob& job, std::string& error) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const int flags = O_WRONLY | O_CREAT | O_TRUNC;  // no O_CLOEXEC: these become the child's fd 1 and 2
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.stdout_file.c_str(), flags, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, job.stderr_file.c_str(), flags, 0644);
  std::vector<char*> argv;
  for (const std::string& argument : job.argv) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int status = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status != 0) {
    error = std::string("cannot start ") + argv[0] + ": " + std::strerror(status);
    return -1;
  }
  return pid;
}

}  // namespace

void run_processes(const std::vector<ChildJob>& jobs, int parallel, const PoolHooks& hooks) {
  LIMBER_DEMAND(parallel >= 1);
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  bool stopping = false;
  constexpr auto kTick = std::chrono::milliseconds(200);
  while (next < jobs.size() || !running.empty()) {
    // A stop request: no new child, SIGTERM to the running ones (once).
    if (!stopping && hooks.should_stop && hooks.should_stop()) {
      stopping = true;
      for (const auto& [pid, child] : running) kill(pid, SIGTERM);
    }
    // Start children up to the limit.
    while (!stopping && next < jobs.size() && static_cast<int>(running.size()) < parallel) {
      const std::size_t job = next++;
      std::filesystem::create_directories(jobs[job].stdout_file.parent_path());
      if (hooks.on_start) hooks.on_start(job);
      std::string error;
      const pid_t pid = spawn(jobs[job], error);
      if (pid < 0) {
        ChildOutcome outcome;
        outcome.spawn_error = error;
        if (hooks.on_finish) hooks.on_finish(job, outcome);
        continue;
      }
      running[pid] = {job, Clock::now()};
    }
    if (running.empty()) {
      if (stopping) break;
      continue;
    }
    // Reap every child that ended; otherwise wait a tick.
    bool reaped = false;
    while (true) {
      int status = 0;
      rusage usage{};
      const pid_t pid = wait4(-1, &status, WNOHANG, &usage);
      if (pid <= 0) break;
      const auto found = running.find(pid);
      if (found == running.end()) continue;  // not one of ours
      ChildOutcome outcome;
      outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - found->second.start).count();
      outcome.peak_rss_kib = usage.ru_maxrss;
      if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
      if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
      const std::size_t job = found->second.job;
      running.erase(found);
      reaped = true;
      if (hooks.on_finish) hooks.on_finish(job, outcome);
    }
    if (!reaped) {
      if (hooks.on_tick) hooks.on_tick();
      std::this_thread::sleep_for(kTick);
    }
  }
}

}  // namespace limber::sweep
