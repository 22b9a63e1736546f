#include "results/h5_reader.h"

#include "core/error.h"

#include <atomic>
#include <cstdint>
#include <cstdio>

#include <unistd.h>

namespace limber::results {

namespace {

// Checks that `path` is an HDF5 file (a truncated file is not) and opens it read-only, without
// HDF5's file lock: the writer of a run still going holds an exclusive lock on results.h5 until
// it closes the file, which made every reader fail to open it ("unable to lock file"). Unlocked,
// a reader sees the file as of the writer's last flush (results_writer.h writes and flushes in
// blocks) and cannot disturb the writer: it opens read-only and takes no lock the writer waits
// for (docs/results-format.md, "Reading a file still being written").
hid_t open_checked(const std::filesystem::path& path, const std::string& kind,
                   const std::string& missing_hint) {
  const std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError("expected a " + kind + " '" + name + "', got no such file" + missing_hint);
  }
  if (H5Fis_hdf5(name.c_str()) <= 0) {
    throw InputError("expected an HDF5 " + kind + " '" + name +
                     "', got a file HDF5 cannot open (truncated or not HDF5)");
  }
  const H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_file_locking(access.get(), /*use_file_locking=*/false, /*ignore_when_disabled=*/true);
  const hid_t file = H5Fopen(name.c_str(), H5F_ACC_RDONLY, access.get());
  if (file < 0) {
    throw InputError("expected a readable " + kind + " '" + name + "', got an HDF5 open failure");
  }
  return file;
}

// Opens `image` read-only through HDF5's core driver (no backing store): nothing on disk. HDF5
// tells open files apart by name, so each image is opened under one of its own.
hid_t open_image(const std::vector<unsigned char>& image, const std::string& name, const std::string& kind) {
  static std::atomic<std::int64_t> images_opened{0};
  const std::string label = "(limber image in memory " + std::to_string(getpid()) + "." +
                            std::to_string(++images_opened) + ")";
  const H5Handle access(H5Pcreate(H5P_FILE_ACCESS));
  const bool ready = H5Pset_fapl_core(access.get(), image.size() + 1, /*backing_store=*/false) >= 0 &&
                     H5Pset_file_image(access.get(), const_cast<unsigned char*>(image.data()), image.size()) >= 0;
  const hid_t file = ready && !image.empty() ? H5Fopen(label.c_str(), H5F_ACC_RDONLY, access.get()) : -1;
  if (file < 0) throw InputError("expected an HDF5 " + kind + " '" + name + "' in memory, got bytes HDF5 cannot open");
  return file;
}

// An attribute's value as text: strings as they are, numbers "%.6g", arrays ", "-separated.
std::string attribute_text(hid_t attribute) {
  H5Handle type(H5Aget_type(attribute));
  H5Handle space(H5Aget_space(attribute));
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get()));
  switch (H5Tget_class(type.get())) {
    case H5T_STRING: {
      if (H5Tis_variable_str(type.get()) > 0) {
        H5Handle memory(H5Tcopy(H5T_C_S1));
        H5Tset_size(memory.get(), H5T_VARIABLE);
        H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
        char* text = nullptr;
        if (n != 1 || H5Aread(attribute, memory.get(), &text) < 0) return "(unreadable)";
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
      }
      std::string value(H5Tget_size(type.get()) * n, '\0');
      if (H5Aread(attribute, type.get(), value.data()) < 0) return "(unreadable)";
      return value.substr(0, value.find('\0'));
    }
    case H5T_INTEGER:
    case H5T_FLOAT: {
      std::vector<double> values(n);
      if (H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) < 0) return "(unreadable)";
      std::string text;
      for (std::size_t k = 0; k < n; ++k) {
        char number[32];
        std::snprintf(number, sizeof number, "%.6g", values[k]);
        text += (k > 0 ? ", " : "") + std::string(number);
      }
      return text;
    }
    default:
      return "(not shown)";
  }
}

}  // namespace

H5Reader::H5Reader(std::filesystem::path path, std::string kind, const std::string& missing_hint)
    : path_(std::move(path)),
      kind_(std::move(kind)),
      file_(open_checked(path_, kind_, missing_hint)) {}

H5Reader::H5Reader(const std::vector<unsigned char>& image, std::filesystem::path name, std::string kind)
    : path_(std::move(name)), kind_(std::move(kind)), file_(open_image(image, path_.string(), kind_)) {}

void H5Reader::fail(const std::string& expected, const std::string& got) const {
  throw InputError(kind_ + " '" + path_.string() + "': expected " + expected + ", got " + got);
}

bool H5Reader::exists(const std::string& object) const {
  return H5Lexists(file_.get(), object.c_str(), H5P_DEFAULT) > 0;
}

std::string H5Reader::string_attribute(const std::string& object, const char* name,
                                       bool required, const std::string& fallback) const {
  if (H5Aexists_by_name(file_.get(), object.c_str(), name, H5P_DEFAULT) <= 0) {
    if (required) fail(std::string("attribute '") + name + "' on " + object, "none");
    return fallback;
  }
  H5Handle attribute(H5Aopen_by_name(file_.get(), object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT));
  H5Handle type(H5Aget_type(attribute.get()));
  if (H5Tget_class(type.get()) != H5T_STRING) fail(std::string("a string ") + name, "another type");
  if (H5Tis_variable_str(type.get()) > 0) {
    // The memory type takes the file's character set (HDF5 does not convert ASCII <-> UTF-8).
    H5Handle memory_type(H5Tcopy(H5T_C_S1));
    H5Tset_size(memory_type.get(), H5T_VARIABLE);
    H5Tset_cset(memory_type.get(), H5Tget_cset(type.get()));
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory_type.get(), &text) < 0) fail(name, "an unreadable value");
    std::string value = text != nullptr ? text : "";
    H5free_memory(text);
    return value;
  }
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(attribute.get(), type.get(), value.data()) < 0) fail(name, "an unreadable value");
  return value.substr(0, value.find('\0'));
}

bool H5Reader::has_attribute(const std::string& object, const char* name) const {
  return exists(object) && H5Aexists_by_name(file_.get(), object.c_str(), name, H5P_DEFAULT) > 0;
}

std::vector<double> H5Reader::doubles_attribute(const std::string& object, const char* name,
                                                std::size_t n) const {
  if (H5Aexists_by_name(file_.get(), object.c_str(), name, H5P_DEFAULT) <= 0) {
    fail(std::string("attribute '") + name + "' on " + object, "none");
  }
  H5Handle attribute(H5Aopen_by_name(file_.get(), object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT));
  H5Handle space(H5Aget_space(attribute.get()));
  if (static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())) != n) {
    fail(std::to_string(n) + " values in " + object + "@" + name, "another count");
  }
  std::vector<double> values(n);
  H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data());
  return values;
}

std::vector<hsize_t> H5Reader::dims(const std::string& dataset) const {
  if (!exists(dataset)) fail("dataset " + dataset, "none");
  H5Handle id(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT));
  H5Handle space(H5Dget_space(id.get()));
  std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), d.data(), nullptr);
  return d;
}

hsize_t H5Reader::rows(const std::string& dataset, hsize_t width) const {
  const std::vector<hsize_t> d = dims(dataset);
  const bool ok = width == 0 ? d.size() == 1 : (d.size() == 2 && d[1] == width);
  if (!ok) fail(dataset + " with " + std::to_string(width) + " columns", "another shape");
  return d[0];
}

void H5Reader::read_rows(const std::string& dataset, hid_t memory_type, hsize_t rows,
                         void* values) const {
  const std::vector<hsize_t> d = dims(dataset);
  H5Handle id(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT));
  H5Handle file_space(H5Dget_space(id.get()));
  // Select the leading rows only (a killed run may have longer datasets).
  std::vector<hsize_t> start(d.size(), 0), count = d;
  if (!count.empty()) count[0] = rows;
  H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                      nullptr);
  H5Handle memory_space(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr));
  if (H5Dread(id.get(), memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT,
              values) < 0) {
    fail("readable data in " + dataset, "a read failure (damaged file?)");
  }
}

std::vector<std::string> H5Reader::strings(const std::string& dataset) const {
  const hsize_t n = rows(dataset, 0);
  H5Handle id(H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT));
  H5Handle file_type(H5Dget_type(id.get()));
  if (H5Tget_class(file_type.get()) != H5T_STRING) fail("strings in " + dataset, "another type");
  if (H5Tis_variable_str(file_type.get()) <= 0) {
    // Fixed length, null-padded (results.h5's redundant equations, clearance pairs).
    const std::size_t size = H5Tget_size(file_type.get());
    std::vector<char> buffer(static_cast<std::size_t>(n) * size);
    if (n > 0 && H5Dread(id.get(), file_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                         buffer.data()) < 0) {
      fail("readable strings in " + dataset, "a read failure (damaged file?)");
    }
    std::vector<std::string> values;
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
      const std::string text(buffer.data() + k * size, size);
      values.push_back(text.substr(0, text.find('\0')));
    }
    return values;
  }
  // Read as C strings in the file's character set, copy, then let HDF5 free its buffers.
  H5Handle memory_type(H5Tcopy(H5T_C_S1));
  H5Tset_size(memory_type.get(), H5T_VARIABLE);
  H5Tset_cset(memory_type.get(), H5Tget_cset(file_type.get()));
  std::vector<char*> pointers(static_cast<std::size_t>(n), nullptr);
  if (n > 0 && H5Dread(id.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                       pointers.data()) < 0) {
    fail("readable strings in " + dataset, "a read failure (damaged file?)");
  }
  std::vector<std::string> values;
  for (char* text : pointers) {
    values.emplace_back(text != nullptr ? text : "");
    H5free_memory(text);
  }
  return values;
}

std::vector<std::string> H5Reader::members(const std::string& group) const {
  std::vector<std::string> names;
  if (!exists(group)) return names;
  H5Handle id(H5Gopen2(file_.get(), group.c_str(), H5P_DEFAULT));
  H5G_info_t info;
  H5Gget_info(id.get(), &info);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t n = H5Lget_name_by_idx(id.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0,
                                         H5P_DEFAULT);
    std::string name(static_cast<std::size_t>(n), '\0');
    H5Lget_name_by_idx(id.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(),
                       static_cast<std::size_t>(n) + 1, H5P_DEFAULT);
    names.push_back(name);
  }
  return names;
}

std::vector<std::pair<std::string, std::string>> H5Reader::attribute_texts(
    const std::string& object) const {
  std::vector<std::pair<std::string, std::string>> out;
  if (object != "/" && !exists(object)) return out;
  H5O_info_t info;
  if (H5Oget_info_by_name2(file_.get(), object.c_str(), &info, H5O_INFO_NUM_ATTRS,
                           H5P_DEFAULT) < 0) {
    return out;
  }
  for (hsize_t k = 0; k < info.num_attrs; ++k) {
    H5Handle attribute(H5Aopen_by_idx(file_.get(), object.c_str(), H5_INDEX_NAME, H5_ITER_INC, k,
                                      H5P_DEFAULT, H5P_DEFAULT));
    if (!attribute.valid()) continue;
    const ssize_t length = H5Aget_name(attribute.get(), 0, nullptr);
    std::string name(static_cast<std::size_t>(length), '\0');
    H5Aget_name(attribute.get(), static_cast<std::size_t>(length) + 1, name.data());
    out.emplace_back(name, attribute_text(attribute.get()));
  }
  return out;
}

}  // namespace limber::results
