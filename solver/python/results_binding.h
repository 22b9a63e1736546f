// limber.Results and limber.read_results: a results.h5 (docs/results-format.md) read by the
// results library's typed reader of the file as written (results/results_arrays.h) and handed
// over as numpy arrays, the same object whether the file comes from limber.run (on disk or in
// memory) or from `limber run`.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <vector>

namespace limber::python {

// Adds Results, BodyResults, JointResults and read_results to `module`.
void bind_results(pybind11::module_& module);

// The results object of the results file `file` (Results.path is its path), or of a results
// file kept in memory (ResultsWriter::file_image(); Results.path None): one reader for both.
// Throws InputError when the file is not a readable results file. Both take HDF5's lock
// (results/hdf5_lock.h) with the GIL released; callers must not hold that lock.
pybind11::object read_results(const std::filesystem::path& file);
pybind11::object read_results(const std::vector<unsigned char>& image);

}  // namespace limber::python
