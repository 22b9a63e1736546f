// A thin, checked layer over the HDF5 C API (1.10) for writing modes.h5 (modes_writer.h):
// files and groups as RAII handles, whole datasets of doubles, ints and strings, scalar
// attributes (reading: h5_reader.h and modes_reader.h). Datasets are row-major (C order), as
// HDF5 stores them.
// Files are written in the 1.8-compatible format (no "open for writing" flag that
// would lock readers out after a crash; see docs/results-format.md).
//
// Every failure (missing file, missing dataset, wrong shape) throws InputError naming
// the file and the object; HDF5's own error printing is switched off.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace limber::results {

using H5Dims = std::vector<hsize_t>;

// A file or a group in it.
class H5Group {
 public:
  // Creates (truncates) an HDF5 file.
  static H5Group create_file(const std::string& path);

  H5Group create_group(const std::string& name) const;

  // Datasets: `data` holds product(dims) values, row-major. An empty `dims` writes a scalar.
  void write_doubles(const std::string& name, const H5Dims& dims, const double* data) const;
  void write_ints(const std::string& name, const H5Dims& dims, const int* data) const;
  void write_strings(const std::string& name, const std::vector<std::string>& values) const;
  void write_attribute(const std::string& name, const std::string& value) const;
  void write_attribute(const std::string& name, int value) const;

  const std::string& path() const { return path_; }  // "file.h5:/bodies/rod"

 private:
  struct Handle;
  H5Group(std::shared_ptr<Handle> file, std::shared_ptr<Handle> self, std::string path);
  std::shared_ptr<Handle> file_;  // keeps the file open while any group lives
  std::shared_ptr<Handle> self_;
  std::string path_;
};

}  // namespace limber::results
