#include "results/h5_group.h"

#include "core/error.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"

namespace limber::results {

// A file or group identifier shared by the H5Group values that refer to it (h5_handle.h
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
  if (!try_write_dataset(location, name.c_str(), file_type, memory_type, dims, data)) {
    fail("cannot write dataset", path + "/" + name);
  }
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

H5Group H5Group::create_group(const std::string& name) const {
  hid_t id = H5Gcreate2(self_->handle.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail("cannot create group", path_ + "/" + name);
  return H5Group(file_, std::make_shared<Handle>(id), path_ + "/" + name);
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
  if (!try_write_scalar_attribute(self_->handle.get(), name.c_str(), type.get(),
                                           type.get(), &text)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

void H5Group::write_attribute(const std::string& name, int value) const {
  if (!try_write_scalar_attribute(self_->handle.get(), name.c_str(), H5T_STD_I32LE,
                                           H5T_NATIVE_INT, &value)) {
    fail("cannot write attribute", path_ + "@" + name);
  }
}

}  // namespace limber::results
