#include "select/job_queue.h"

#include <thread>
#include <vector>

namespace limber::select {

void JobQueue::push_back(Job job) {
  {
    const std::lock_guard lock(mutex_);
    jobs_.push_back(std::move(job));
  }
  changed_.notify_one();
}

void JobQueue::push_front(Job job) {
  {
    const std::lock_guard lock(mutex_);
    jobs_.push_front(std::move(job));
  }
  changed_.notify_one();
}

void JobQueue::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    // Wait for a job, or for the end: nothing queued and nothing running that could add one.
    changed_.wait(lock, [&] { return failure_ || !jobs_.empty() || running_ == 0; });
    if (failure_ || jobs_.empty()) return;
    Job job = std::move(jobs_.front());
    jobs_.pop_front();
    ++running_;
    lock.unlock();
    std::exception_ptr thrown;
    try {
      job(*this);
    } catch (...) {
      thrown = std::current_exception();
    }
    lock.lock();
    --running_;
    if (thrown && !failure_) failure_ = thrown;
    changed_.notify_all();
  }
}

void JobQueue::run(int workers) {
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back([this] { work(); });
  work();
  for (std::thread& thread : threads) thread.join();
  if (failure_) std::rethrow_exception(failure_);
}

}  // namespace limber::select
