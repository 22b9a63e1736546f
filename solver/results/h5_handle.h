// RAII ownership of an HDF5 C-API identifier (file, group, dataset, dataspace, type, property
// list, attribute): the matching H5?close runs when the handle dies. Shared by the results
// writer and the readers in render/ and report/.
#pragma once

#include <hdf5.h>

#include "results/hdf5_lock.h"

#include <mutex>
#include <utility>

namespace limber::results {

class H5Handle {
 public:
  H5Handle() = default;
  // Takes ownership of id; a negative id (an HDF5 failure) is kept as "invalid".
  explicit H5Handle(hid_t id) : id_(id) {}
  H5Handle(H5Handle&& other) noexcept : id_(std::exchange(other.id_, -1)) {}
  H5Handle& operator=(H5Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, -1);
    }
    return *this;
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes the identifier now (with the H5?close matching its type).
  void reset();

 private:
  hid_t id_ = -1;
};

// Silences HDF5's automatic error-stack printing while alive; callers report failures
// themselves (exceptions or messages that name the file).
class SilentHdf5Errors {
 public:
  SilentHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~SilentHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  SilentHdf5Errors(const SilentHdf5Errors&) = delete;
  SilentHdf5Errors& operator=(const SilentHdf5Errors&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

}  // namespace limber::results
