// The results writers' attributes, fixed-size datasets and named groups (results_writer.cpp,
// stress_series.cpp): thin wrappers of h5_write.h that throw on an HDF5 failure (sample_series.h's
// check).
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "results/h5_handle.h"
#include "results/results_writer.h"

namespace limber::results {

// The longest text of a string attribute, in bytes: an attribute holds at most 64 KiB in the
// 1.8 file format. The case's names and title are shorter (core/names.h, io/case_reader.cpp);
// longer text (a run's message, which may quote many names) is cut, ending "… (N bytes)".
inline constexpr std::size_t kMaxAttributeText = 16384;

// A fixed-length, null-padded string attribute (replacing one of the same name: status is
// rewritten at finish).
void write_string_attribute(hid_t object, const char* name, const std::string& value);
void write_int_attribute(hid_t object, const char* name, int value);
void write_doubles_attribute(hid_t object, const char* name, const double* values, hsize_t count);

// Mass, centre of mass and inertia about it (row-major) as the body group's attributes.
void write_mass_properties(hid_t body, const MassProperties& m);
// The body's shapes, one group each under /bodies/<body>/shapes (none: no group).
void write_shapes(hid_t body_group, const std::vector<ShapeSpec>& shapes);

H5Handle create_group(hid_t parent, const std::string& name);
// Writes a whole fixed-size dataset (results/h5_write.h); rank 0 means a scalar.
void write_dataset(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                   const std::vector<hsize_t>& dims, const void* data);
// A one-dimensional dataset of fixed-length, null-padded strings.
void write_string_dataset(hid_t parent, const char* name, const std::vector<std::string>& values);

// The link of a declared name (results/link_name.h), new within its kind: names are unique on
// input and the mapping is injective, so a repeat is a caller bug.
std::string new_link(std::set<std::string>& links, const std::string& name);
// A group named by a free-text name: its link, and the name itself in the attribute `name`.
H5Handle create_named_group(hid_t parent, std::set<std::string>& links, const std::string& name);

}  // namespace limber::results
