// Read-only access to limber's HDF5 files (results.h5, modes.h5) through the HDF5 C API: the
// reading layer under limber_results' typed readers (results_reader.h, run_records.h,
// modes_reader.h, ...; paths in results/results_layout.h and results/modes_layout.h), used
// directly only inside limber_results and by tests. Every failure is an InputError naming the file:
// "<kind> '<path>': expected ..., got ...". Exposes HDF5 types.
#pragma once

#include <hdf5.h>

#include "results/h5_handle.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace limber::results {

class H5Reader {
 public:
  // Opens `path` read-only; `kind` names the file in messages ("results file"), `missing_hint`
  // ends the message for a missing file. Throws InputError when the file is missing, is not
  // HDF5 (e.g. truncated) or cannot be opened.
  H5Reader(std::filesystem::path path, std::string kind, const std::string& missing_hint);
  // Opens a file image in memory (ResultsWriter::file_image(); copied, so `image` may go);
  // `name` stands for it in messages. Throws InputError when the bytes are not an HDF5 file.
  H5Reader(const std::vector<unsigned char>& image, std::filesystem::path name, std::string kind);

  const std::filesystem::path& path() const { return path_; }
  [[noreturn]] void fail(const std::string& expected, const std::string& got) const;
  bool exists(const std::string& object) const;

  // A string attribute (fixed or variable length); `fallback` when absent and optional.
  std::string string_attribute(const std::string& object, const char* name, bool required = true,
                               const std::string& fallback = "") const;
  bool has_attribute(const std::string& object, const char* name) const;
  // A real attribute of exactly n values.
  std::vector<double> doubles_attribute(const std::string& object, const char* name,
                                        std::size_t n) const;
  // Dimensions of a dataset; fails when absent.
  std::vector<hsize_t> dims(const std::string& dataset) const;
  // Rows of a dataset with `width` columns (width 0: one-dimensional), checked.
  hsize_t rows(const std::string& dataset, hsize_t width) const;
  // The first `rows` rows of a dataset, row-major, converted to T (`memory_type`).
  template <typename T>
  std::vector<T> read(const std::string& dataset, hid_t memory_type, hsize_t rows) const;
  // A one-dimensional dataset of strings (variable length, or fixed length and null-padded).
  std::vector<std::string> strings(const std::string& dataset) const;
  // Every attribute of `object` ("/" for the root) as text, in name order: strings as they are,
  // numbers "%.6g", arrays ", "-separated, other types "(not shown)"; empty when absent.
  std::vector<std::pair<std::string, std::string>> attribute_texts(const std::string& object) const;
  // Names of the members of a group, alphabetical (empty when the group is absent).
  std::vector<std::string> members(const std::string& group) const;

 private:
  // Reads `count` rows selected in the dataset into `values`.
  void read_rows(const std::string& dataset, hid_t memory_type, hsize_t rows, void* values) const;

  std::filesystem::path path_;
  std::string kind_;
  SilentHdf5Errors silent_;
  H5Handle file_;
};

template <typename T>
std::vector<T> H5Reader::read(const std::string& dataset, hid_t memory_type, hsize_t rows) const {
  const std::vector<hsize_t> d = dims(dataset);
  std::size_t per_row = 1;
  for (std::size_t k = 1; k < d.size(); ++k) per_row *= d[k];
  std::vector<T> values(static_cast<std::size_t>(rows) * per_row);
  if (!values.empty()) read_rows(dataset, memory_type, rows, values.data());
  return values;
}

}  // namespace limber::results
