// The writing calls that results.h5's writer and Hdf5Group (h5_group.h: modes.h5, linear.h5, scene.h5) share:
// whole datasets and scalar attributes through the HDF5 C API. Each returns false on an HDF5
// failure; the caller says which file and object failed, in its own kind of error.
#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

namespace limber::results {

// Creates dataset `name` in `parent` of shape `dims` (empty: a scalar) and writes `data`
// (row-major, `memory_type`) into it; a dataset with a zero dimension gets no data.
bool try_write_dataset(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                       const std::vector<hsize_t>& dims, const void* data);

// Writes the scalar attribute `name` of `object` from `value` (`memory_type`), replacing an
// attribute of the same name.
bool try_write_scalar_attribute(hid_t object, const char* name, hid_t file_type,
                                hid_t memory_type, const void* value);

// Writes the scalar string attribute `name` of `object`: fixed length, null-padded (replacing
// one of the same name).
bool try_write_string_attribute(hid_t object, const char* name, const std::string& value);

// Creates the one-dimensional dataset `name` in `parent` of fixed-length, null-padded strings.
bool try_write_string_dataset(hid_t parent, const char* name, const std::vector<std::string>& values);

}  // namespace limber::results
