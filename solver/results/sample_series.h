// The per-sample datasets of results.h5 (results_writer.h): each an unlimited, chunked dataset
// grown by a block of rows at a time, the rows appended since the last block buffered in memory;
// and the writer's error policy, an HDF5 failure thrown as std::runtime_error.
#pragma once

#include <hdf5.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "results/h5_handle.h"

namespace limber::results {

// Throws when an HDF5 call failed (negative return): the file is unusable from then on.
herr_t check(herr_t status, const char* what);
// `id`, owned, or a throw when it is an HDF5 failure.
H5Handle checked(hid_t id, const char* what);

// A per-sample dataset: [ns] (width 0) or [ns, width], grown by a block of rows at a time; the
// rows appended since the last block wait in `pending` (row-major, memory type).
struct Series {
  H5Handle dataset;
  hid_t memory_type = H5T_NATIVE_DOUBLE;
  int rank = 1;       // 1: [ns]; 2: [ns, width], width >= 0
  hsize_t width = 0;
  std::size_t row_bytes = 0;
  std::vector<unsigned char> pending;
};

// An empty, chunked, unlimited per-sample dataset: [ns] for width 0, else [ns, width].
Series create_series(hid_t parent, const char* name, hid_t file_type, hid_t memory_type, hsize_t width);
// [ns, width] for any width, 0 included (a flexible body without modes).
Series create_columns(hid_t parent, const char* name, hid_t file_type, hid_t memory_type, hsize_t width);
Series create_series_of_rank(hid_t parent, const char* name, hid_t file_type, hid_t memory_type, int rank,
                             hsize_t width);

// Buffers one row of a series (written by write_pending).
void append_row(Series& series, const void* row);
void append_vector3(Series& series, const Eigen::Vector3d& v);

// Extends a series to `first` + `rows` rows and writes `rows` rows from `data` at row `first`.
void write_rows(Series& series, std::int64_t first, std::int64_t rows, const void* data);
// Writes the `rows` buffered rows at row `first` and empties the buffer.
void write_pending(Series& series, std::int64_t first, std::int64_t rows);

}  // namespace limber::results
