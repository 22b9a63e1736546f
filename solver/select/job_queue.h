// The runs of a selection on a few threads, the longest first: a queue of jobs that `workers`
// threads take from its front, to which a running job may add more (the reference's event
// windows, known once the reference has run, go to the front so that they start next, while the
// other thread goes on with the remaining sets).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>

namespace limber::select {

class JobQueue {
 public:
  using Job = std::function<void(JobQueue&)>;

  // Adds a job at the end or at the front (from any thread, also from a running job).
  void push_back(Job job);
  void push_front(Job job);

  // Runs every job, on `workers` threads (1: in order on this one), until the queue is empty
  // and no job is running. After the first exception a job throws, no further job starts; it
  // is rethrown once the running ones end.
  void run(int workers);

 private:
  // One thread's loop: the front job, until there is none left and none running.
  void work();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> jobs_;
  int running_ = 0;
  std::exception_ptr failure_;
};

}  // namespace limber::select
