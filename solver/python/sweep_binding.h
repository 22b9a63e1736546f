// limber.sweep: `limber sweep`'s study (sweep/sweep_study.h) in this process, its --json
// document returned as a dict. Every grid point stays a `limber run` child process, as in the
// command (single-threaded, its peak memory measured by the kernel, a crash costing one point:
// sweep/process_pool.h), of the `limber` executable, found in this order: $LIMBER_EXECUTABLE; <prefix>/bin/limber beside an
// installed module (<prefix>/lib/python3/dist-packages); the build tree's, when the module is
// the build tree's; `limber` on PATH.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>

namespace limber::python {

// The `limber` executable, found as above. Throws std::runtime_error naming the places looked
// at when there is none.
std::filesystem::path limber_executable();

// Adds sweep to `module`.
void bind_sweep(pybind11::module_& module);

}  // namespace limber::python
