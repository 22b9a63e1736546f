#include "python/interruptible.h"

#include <chrono>
#include <exception>
#include <future>
#include <optional>

namespace py = pybind11;

namespace limber::python {

bool in_main_thread() {
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")());
}

void run_interruptible(const std::function<void(const std::atomic<bool>& stop)>& work) {
  std::atomic<bool> stop{false};
  const bool check_signals = in_main_thread();
  std::optional<py::error_already_set> raised;
  {
    py::gil_scoped_release released;
    std::future<void> done = std::async(std::launch::async, [&] { work(stop); });
    while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
      if (!check_signals || stop) continue;
      py::gil_scoped_acquire acquired;
      if (PyErr_CheckSignals() != 0) {
        raised.emplace();  // fetches the pending exception
        stop = true;
      }
    }
    try {
      done.get();  // rethrows what `work` threw
    } catch (...) {
      if (!raised) throw;  // else: the work's way of stopping; the signal's exception is raised
    }
  }
  if (raised) throw std::move(*raised);
}

}  // namespace limber::python
