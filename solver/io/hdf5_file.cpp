#include "io/hdf5_file.h"

#include <numeric>

#include "core/error.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"

namespace limber::io {

using results::H5Handle;

// A file or group identifier shared by the H5Group values that refer to it (results/h5_handle.h
// closes it by its kind, as for every identifier here).
struct H5Group::Handle {
  explicit Handle(hid_t id) : handle(id) {}
  H5Handle handle;
};

namespace {

// HDF5 prints its error stack by default; limber reports errors itself.
void silence_hdf5() {
  static const bool silenced = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)silenced;
}

[[noreturn]] void fail(const std::string& what, const std::string& where) {
  throw InputError("HDF5: " + what + " '" + where + "'");
}

hsize_t element_count(const H5Dims& dims) {
  return std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
}

// Variable-length UTF-8 string type.
H5Handle string_type() {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  return H5Handle(type);
}

// Writes one dataset of `file_type` from memory of `memory_type` (results/h5_write.h, the
// writing calls results.h5's writer uses too).
void write_dataset(hid_t location, const std::string& name, const std::string& path,
                   hid_t file_type, hid_t memory_type, const H5Dims& dims, const void* data) {
  if (!results::try_write_dataset(location, name.c_str(), file_type, memory_type, dims, data)) {
    fail("cannot write dataset", path + "/" + name);
  }
}

// Reads a whole numeric dataset converted to `memory_type`.
template <typename T>
std::vector<T> read_dataset(hid_t location, const std::string& name, const std::string& path,
                            hid_t memory_type, H5Dims* dims) {
  H5Handle dataset(H5Dopen2(location, name.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) fail("missing dataset", path + "/" + name);
  H5Handle space(H5Dget_space(dataset.get()));
  H5Dims shape(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  std::vector<T> values(element_count(shape));
  if (!values.empty() &&
      H5Dread(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    fail("cannot read dataset", path + "/" + name);
  }
  if (dims) *dims = shape;
  return values;
}

}  // namespace

H5Group::H5Group(std::shared_ptr<Handle> file, std::shared_ptr<Handle> self, std::string path)
    : file_(std::move(file)), self_(std::move(self)), path_(std::move(path)) {}

H5Group H5Group::create_file(const std::string& path) {
  silence_hdf5();
  // 1.8-compatible format: readable by every 1.8+ tool, no SWMR status flag.
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18);
  hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (id < 0) fail("cannot create file", path);
  auto file = std::make_shared<Handle>(id);
  return H5Group(file, file, path + ":");
}

H5Group H5Group::open_file(const std::string& path) {
  silence_hdf5();
  hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) fail("cannot open file", path);
  auto file = std::make_shared<Handle>(id);
  return H5Group(file, file, path + ":");
}

H5Group H5Group::create_group(const std::string& name) const {
  hid_t id = H5Gcreate2(self_->handle.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail("cannot create group", path_ + "/" + name);
  return H5Group(file_, std::make_shared<Handle>(id), path_ + "/" + name);
}

H5Group H5Group::open_group(const std::string& name) const {
  hid_t id = H5Gopen2(self_->handle.get(), name.c_str(), H5P_DEFAULT);
  if (id < 0) fail("missing group", path_ + "/" + name);
  return H5Group(file_, std::make_shared<Handle>(id), path_ + "/" + name);
}

bool H5Group::has(const std::string& name) const {
  return H5Lexists(self_->handle.get(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> H5Group::links() const {
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  };
  if (H5Literate(self_->handle.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names) < 0) {
    fail("cannot list", path_);
  }
  return names;
}

void H5Group::write_doubles(const std::string& name, const H5Dims& dims, const double* data) const {
  write_dataset(self_->handle.get(), name, path_, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data);
}

void H5Group::write_ints(const std::string& name, const H5Dims& dims, const int* data) const {
  write_dataset(self_->handle.get(), name, path_, H5T_STD_I32LE, H5T_NATIVE_INT, dims, data);
}

void H5Group::write_strings(const std::string& name, const std::vector<std::string>& values) const {
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  H5Handle type = string_type();
  write_dataset(self_->handle.get(), name, path_, type.get(), type.get(), {values.size()}, pointers.data());
}

void H5Group::write_attribute(const std::string& name, const std::string& value) const {
  H5Handle type = string_type();
  const char* text = value.c_str();
  if (!results::try_write_scalar_attribute(self_->handle.get(), name.c_str(), type.get(),
                                           type.get(), &text)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

void H5Group::write_attribute(const std::string& name, int value) const {
  if (!results::try_write_scalar_attribute(self_->handle.get(), name.c_str(), H5T_STD_I32LE,
                                           H5T_NATIVE_INT, &value)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

std::vector<double> H5Group::read_doubles(const std::string& name, H5Dims* dims) const {
  return read_dataset<double>(self_->handle.get(), name, path_, H5T_NATIVE_DOUBLE, dims);
}

std::vector<int> H5Group::read_ints(const std::string& name, H5Dims* dims) const {
  return read_dataset<int>(self_->handle.get(), name, path_, H5T_NATIVE_INT, dims);
}

std::vector<std::string> H5Group::read_strings(const std::string& name) const {
  H5Handle dataset(H5Dopen2(self_->handle.get(), name.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) fail("missing dataset", path_ + "/" + name);
  H5Handle space(H5Dget_space(dataset.get()));
  const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  // Fixed-length strings (results.h5's string datasets): read as stored, each up to its first NUL.
  H5Handle file_type(H5Dget_type(dataset.get()));
  if (H5Tget_class(file_type.get()) == H5T_STRING && H5Tis_variable_str(file_type.get()) == 0) {
    const std::size_t size = H5Tget_size(file_type.get());
    std::string buffer(count * size, '\0');
    if (count > 0 && H5Dread(dataset.get(), file_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
      fail("cannot read strings", path_ + "/" + name);
    }
    std::vector<std::string> values;
    for (std::size_t k = 0; k < count; ++k) {
      const std::string text = buffer.substr(k * size, size);
      values.push_back(text.substr(0, text.find('\0')));
    }
    return values;
  }
  std::vector<char*> pointers(count, nullptr);
  H5Handle type = string_type();
  if (count > 0 &&
      H5Dread(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
    fail("cannot read strings", path_ + "/" + name);
  }
  // Copy out, then let HDF5 free what it allocated.
  std::vector<std::string> values;
  for (char* pointer : pointers) values.emplace_back(pointer ? pointer : "");
  if (count > 0) H5Dvlen_reclaim(type.get(), space.get(), H5P_DEFAULT, pointers.data());
  return values;
}

std::string H5Group::read_string_attribute(const std::string& name) const {
  H5Handle attribute(H5Aopen(self_->handle.get(), name.c_str(), H5P_DEFAULT));
  if (!attribute.valid()) fail("missing attribute", path_ + "@" + name);
  // Fixed-length strings (results.h5's attributes): read as stored, up to the first NUL.
  H5Handle file_type(H5Aget_type(attribute.get()));
  if (H5Tget_class(file_type.get()) == H5T_STRING && H5Tis_variable_str(file_type.get()) == 0) {
    std::string fixed(H5Tget_size(file_type.get()), '\0');
    if (H5Aread(attribute.get(), file_type.get(), fixed.data()) < 0) fail("cannot read attribute", path_ + "@" + name);
    return fixed.substr(0, fixed.find('\0'));
  }
  H5Handle type = string_type();
  char* text = nullptr;
  if (H5Aread(attribute.get(), type.get(), &text) < 0) {
    fail("cannot read attribute", path_ + "@" + name);
  }
  std::string value = text ? text : "";
  H5free_memory(text);
  return value;
}

int H5Group::read_int_attribute(const std::string& name) const {
  H5Handle attribute(H5Aopen(self_->handle.get(), name.c_str(), H5P_DEFAULT));
  int value = 0;
  if (!attribute.valid() || H5Aread(attribute.get(), H5T_NATIVE_INT, &value) < 0) {
    fail("missing attribute", path_ + "@" + name);
  }
  return value;
}

}  // namespace limber::io
