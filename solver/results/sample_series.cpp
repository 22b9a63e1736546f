#include "results/sample_series.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "results/results_writer.h"

namespace limber::results {

herr_t check(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("results.h5: HDF5 failed to ") + what);
  return status;
}

H5Handle checked(hid_t id, const char* what) {
  check(static_cast<herr_t>(id < 0 ? -1 : 0), what);
  return H5Handle(id);
}

Series create_series(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                     hsize_t width) {
  return create_series_of_rank(parent, name, file_type, memory_type, width == 0 ? 1 : 2, width);
}
Series create_columns(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                      hsize_t width) {
  return create_series_of_rank(parent, name, file_type, memory_type, 2, width);
}
Series create_series_of_rank(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                             int rank, hsize_t width) {
  const hsize_t dims[2] = {0, width};
  // A chunk may not exceed a fixed dimension: zero columns stay extendible instead.
  const hsize_t max_dims[2] = {H5S_UNLIMITED, width == 0 ? H5S_UNLIMITED : width};
  // Chunks of about 8k values: few chunks to touch per flush, little waste.
  const hsize_t chunk_rows = std::clamp<hsize_t>(8192 / std::max<hsize_t>(width, 1), 1, 256);
  const hsize_t chunk[2] = {chunk_rows, std::max<hsize_t>(width, 1)};
  H5Handle space = checked(H5Screate_simple(rank, dims, max_dims), "create a dataspace");
  H5Handle properties = checked(H5Pcreate(H5P_DATASET_CREATE), "create properties");
  check(H5Pset_chunk(properties.get(), rank, chunk), "set chunking");
  Series series;
  series.dataset = checked(H5Dcreate2(parent, name, file_type, space.get(), H5P_DEFAULT,
                                      properties.get(), H5P_DEFAULT),
                           "create a per-sample dataset");
  series.memory_type = memory_type;
  series.rank = rank;
  series.width = width;
  series.row_bytes = H5Tget_size(memory_type) * (rank == 1 ? 1 : width);
  series.pending.reserve(kBlockRows * series.row_bytes);
  return series;
}

void append_row(Series& series, const void* row) {
  const auto* bytes = static_cast<const unsigned char*>(row);
  series.pending.insert(series.pending.end(), bytes, bytes + series.row_bytes);
}
void append_vector3(Series& series, const Eigen::Vector3d& v) { append_row(series, v.data()); }

void write_rows(Series& series, std::int64_t first, std::int64_t rows, const void* data) {
  if (rows == 0) return;
  const hsize_t new_dims[2] = {static_cast<hsize_t>(first + rows), series.width};
  check(H5Dset_extent(series.dataset.get(), new_dims), "extend a dataset");
  if (series.rank == 2 && series.width == 0) return;  // rows of nothing: the extent says it all
  H5Handle file_space = checked(H5Dget_space(series.dataset.get()), "get a dataspace");
  const int rank = series.rank;
  const hsize_t start[2] = {static_cast<hsize_t>(first), 0};
  const hsize_t count[2] = {static_cast<hsize_t>(rows), series.width};
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
        "select rows");
  H5Handle memory_space = checked(H5Screate_simple(rank, count, nullptr), "create a dataspace");
  check(H5Dwrite(series.dataset.get(), series.memory_type, memory_space.get(), file_space.get(),
                 H5P_DEFAULT, data),
        "write rows");
}
void write_pending(Series& series, std::int64_t first, std::int64_t rows) {
  LIMBER_DEMAND(series.pending.size() == static_cast<std::size_t>(rows) * series.row_bytes);
  write_rows(series, first, rows, series.pending.data());
  series.pending.clear();
}

}  // namespace limber::results
