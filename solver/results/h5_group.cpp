#include "results/h5_group.h"

#include "core/error.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"

#include <mutex>

namespace limber::results {

// A file or group identifier shared by the Hdf5Group values that refer to it (h5_handle.h
// closes it by its kind, as for every identifier here).
struct Hdf5Group::Handle {
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

// Variable-length UTF-8 string type.
H5Handle string_type() {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  return H5Handle(type);
}

// Writes one dataset of `file_type` from memory of `memory_type` (h5_write.h, the writing
// calls results.h5's writer uses too).
void write_dataset(hid_t location, const std::string& name, const std::string& path,
                   hid_t file_type, hid_t memory_type, const H5Dims& dims, const void* data) {
  const std::vector<hsize_t> extents(dims.begin(), dims.end());
  if (!try_write_dataset(location, name.c_str(), file_type, memory_type, extents, data)) {
    fail("cannot write dataset", path + "/" + name);
  }
}

// File access with the format bounds of `format`.
H5Handle file_access(Hdf5Format format) {
  if (format == Hdf5Format::kLibraryDefault) return H5Handle();
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  const H5F_libver_t low = format == Hdf5Format::kOnly18 ? H5F_LIBVER_V18 : H5F_LIBVER_EARLIEST;
  H5Pset_libver_bounds(access.get(), low, H5F_LIBVER_V18);
  return access;
}

}  // namespace

Hdf5Group::Hdf5Group(std::shared_ptr<Handle> file, std::shared_ptr<Handle> self, std::string path)
    : file_(std::move(file)), self_(std::move(self)), path_(std::move(path)) {}

Hdf5Group Hdf5Group::create_file(const std::string& path, Hdf5Format format) {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  silence_hdf5();
  const H5Handle access = file_access(format);
  hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.valid() ? access.get() : H5P_DEFAULT);
  if (id < 0) fail("cannot create file", path);
  auto file = std::make_shared<Handle>(id);
  return Hdf5Group(file, file, path + ":");
}

Hdf5Group Hdf5Group::create_group(const std::string& name) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  hid_t id = H5Gcreate2(self_->handle.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail("cannot create group", path_ + "/" + name);
  return Hdf5Group(file_, std::make_shared<Handle>(id), path_ + "/" + name);
}

void Hdf5Group::write_doubles(const std::string& name, const H5Dims& dims, const double* data) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  write_dataset(self_->handle.get(), name, path_, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data);
}

void Hdf5Group::write_ints(const std::string& name, const H5Dims& dims, const int* data) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  write_dataset(self_->handle.get(), name, path_, H5T_STD_I32LE, H5T_NATIVE_INT, dims, data);
}

void Hdf5Group::write_strings(const std::string& name, const std::vector<std::string>& values) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  H5Handle type = string_type();
  write_dataset(self_->handle.get(), name, path_, type.get(), type.get(), {values.size()}, pointers.data());
}

void Hdf5Group::write_fixed_strings(const std::string& name, const std::vector<std::string>& values) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  if (!try_write_string_dataset(self_->handle.get(), name.c_str(), values)) {
    fail("cannot write dataset", path_ + "/" + name);
  }
}

void Hdf5Group::write_attribute(const std::string& name, const std::string& value) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  H5Handle type = string_type();
  const char* text = value.c_str();
  if (!try_write_scalar_attribute(self_->handle.get(), name.c_str(), type.get(), type.get(), &text)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

void Hdf5Group::write_fixed_attribute(const std::string& name, const std::string& value) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  if (!try_write_string_attribute(self_->handle.get(), name.c_str(), value)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

void Hdf5Group::write_attribute(const std::string& name, int value) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  if (!try_write_scalar_attribute(self_->handle.get(), name.c_str(), H5T_STD_I32LE, H5T_NATIVE_INT, &value)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

void Hdf5Group::write_attribute(const std::string& name, double value) const {
  const std::lock_guard<std::recursive_mutex> lock(hdf5_lock());
  if (!try_write_scalar_attribute(self_->handle.get(), name.c_str(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

}  // namespace limber::results
