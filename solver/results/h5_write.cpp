#include "results/h5_write.h"

#include "results/h5_handle.h"

#include <algorithm>

namespace limber::results {

bool try_write_dataset(hid_t parent, const char* name, hid_t file_type, hid_t memory_type,
                       const std::vector<hsize_t>& dims, const void* data) {
  const H5Handle space(dims.empty() ? H5Screate(H5S_SCALAR)
                                    : H5Screate_simple(static_cast<int>(dims.size()), dims.data(),
                                                       nullptr));
  if (!space.valid()) return false;
  const H5Handle dataset(H5Dcreate2(parent, name, file_type, space.get(), H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT));
  if (!dataset.valid()) return false;
  // Empty datasets (e.g. a mesh without quads) hold no data to write.
  if (std::any_of(dims.begin(), dims.end(), [](hsize_t d) { return d == 0; })) return true;
  return H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
}

bool try_write_scalar_attribute(hid_t object, const char* name, hid_t file_type,
                                hid_t memory_type, const void* value) {
  // results.h5's status and message are rewritten at the end of a run.
  if (H5Aexists(object, name) > 0 && H5Adelete(object, name) < 0) return false;
  const H5Handle space(H5Screate(H5S_SCALAR));
  if (!space.valid()) return false;
  const H5Handle attribute(
      H5Acreate2(object, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  return attribute.valid() && H5Awrite(attribute.get(), memory_type, value) >= 0;
}

bool try_write_string_attribute(hid_t object, const char* name, const std::string& value) {
  const H5Handle type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0) {
    return false;
  }
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  return try_write_scalar_attribute(object, name, type.get(), type.get(), padded.data());
}

bool try_write_string_dataset(hid_t parent, const char* name, const std::vector<std::string>& values) {
  // One width for all: the longest value (at least 1).
  std::size_t width = 1;
  for (const std::string& value : values) width = std::max(width, value.size());
  std::string packed(width * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k) packed.replace(k * width, values[k].size(), values[k]);
  const H5Handle type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), width) < 0 || H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0) {
    return false;
  }
  return try_write_dataset(parent, name, type.get(), type.get(), {values.size()}, packed.data());
}

}  // namespace limber::results
