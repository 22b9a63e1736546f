// limber's typed HDF5 writer (HDF5 1.10): files and groups as values, whole datasets of doubles,
// ints and strings, scalar attributes. The one writing API outside results.h5's own writer:
// modes.h5 (modes_writer.h), linear.h5 (run/linear_file) and render's scene.h5 write through
// it, so no HDF5 type appears outside limber_results (reading: results_reader.h,
// modes_reader.h). Datasets are row-major (C order), as HDF5 stores them.
//
// Every failure (cannot create the file, a group, a dataset or an attribute) throws InputError
// naming the file and the object; HDF5's own error printing is switched off. Every call holds
// hdf5_lock() (h5_handle.h): HDF5 as Debian builds it is not thread-safe.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace limber::results {

// Dimensions of a dataset (HDF5's hsize_t is unsigned long long); empty: a scalar.
using H5Dims = std::vector<unsigned long long>;

// The HDF5 file format versions a file may use (H5Pset_libver_bounds).
enum class Hdf5Format {
  kEarliestUpTo18,  // earliest to 1.8: readable by every 1.8+ tool, no SWMR status flag (modes.h5)
  kOnly18,          // 1.8 alone: compact groups, a sixth smaller for many small groups (scene.h5)
  kLibraryDefault,  // the library's default bounds (linear.h5)
};

// A file or a group in it.
class Hdf5Group {
 public:
  // Creates (truncates) an HDF5 file.
  static Hdf5Group create_file(const std::string& path, Hdf5Format format = Hdf5Format::kEarliestUpTo18);

  Hdf5Group create_group(const std::string& name) const;

  // Datasets: `data` holds product(dims) values, row-major (float64 and int32 in the file).
  void write_doubles(const std::string& name, const H5Dims& dims, const double* data) const;
  void write_ints(const std::string& name, const H5Dims& dims, const int* data) const;
  // One-dimensional string datasets: variable length UTF-8, or fixed length (the longest value,
  // at least 1) and null-padded.
  void write_strings(const std::string& name, const std::vector<std::string>& values) const;
  void write_fixed_strings(const std::string& name, const std::vector<std::string>& values) const;
  // Scalar attributes: a variable length UTF-8 string, a fixed-length null-padded string, int32,
  // float64. An attribute of the same name is replaced.
  void write_attribute(const std::string& name, const std::string& value) const;
  void write_fixed_attribute(const std::string& name, const std::string& value) const;
  void write_attribute(const std::string& name, int value) const;
  void write_attribute(const std::string& name, double value) const;

  const std::string& path() const { return path_; }  // "file.h5:/bodies/rod"

 private:
  struct Handle;
  Hdf5Group(std::shared_ptr<Handle> file, std::shared_ptr<Handle> self, std::string path);
  std::shared_ptr<Handle> file_;  // keeps the file open while any group lives
  std::shared_ptr<Handle> self_;
  std::string path_;
};

}  // namespace limber::results
