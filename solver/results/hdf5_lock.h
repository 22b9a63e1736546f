// The process's one lock around HDF5 calls, apart from h5_handle.h so that a caller outside
// limber_results (the Python module) can take it without seeing an HDF5 type.
#pragma once

#include <mutex>

namespace limber::results {

// The lock around limber's writing HDF5 calls: HDF5 as Debian builds it is not thread-safe
// (libhdf5.settings: "Threadsafety: no"), and `limber select` runs two sets at once, each
// writing its own results.h5. Every ResultsWriter call and every H5Handle close holds it
// (recursive: a close inside a writer call takes it again).
std::recursive_mutex& hdf5_lock();

}  // namespace limber::results
