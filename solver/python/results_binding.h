// limber.Results and limber.read_results: a results.h5 (docs/results-format.md) read through
// the results library's reader (results/h5_reader.h) at the layout's paths
// (results/results_layout.h) into numpy arrays, the same object whether the file comes from
// limber.run or from `limber run`.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>

namespace limber::python {

// Adds Results, BodyResults, JointResults and read_results to `module`.
void bind_results(pybind11::module_& module);

// The results object of `file`; `keep_path` false leaves its `path` None (a temporary file).
// Throws InputError when `file` is not a readable results file.
pybind11::object read_results(const std::filesystem::path& file, bool keep_path = true);

}  // namespace limber::python
