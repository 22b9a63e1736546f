// Long calls of the module (limber.select, limber.sweep) run on a thread of their own while
// Python's main thread, with the GIL released, looks at its signals every 0.1 s: Ctrl-C is seen
// however many threads the call itself uses (Python runs signal handlers only in its main
// thread). The work stops when `stop` turns true, at its next safe point.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <functional>

namespace limber::python {

// True in Python's main thread.
bool in_main_thread();

// Runs `work(stop)` to its end. From the main thread, a signal handler's exception (Ctrl-C:
// KeyboardInterrupt) sets `stop` and is raised once `work` returns; an exception `work` throws
// is rethrown. Call with the GIL held.
void run_interruptible(const std::function<void(const std::atomic<bool>& stop)>& work);

}  // namespace limber::python
