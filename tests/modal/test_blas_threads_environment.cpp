// The modal tests are a program that runs eigensolutions: like limber's main, it sets one BLAS
// thread for the process (modal/blas_threads.h) before its tests. Without it the eigensolver's
// OpenBLAS and CHOLMOD threads spin on a loaded machine: the modal tests took 57 s without it,
// 6-20 s with it (2 cores shared with other builds, load average 12-16).
#include <gtest/gtest.h>

#include "modal/blas_threads.h"

namespace limber::modal {
namespace {

class OneBlasThread final : public ::testing::Environment {
 public:
  void SetUp() override { use_single_threaded_blas(); }
};

// Registered before main runs the tests (gtest_main); gtest owns and deletes it.
[[maybe_unused]] ::testing::Environment* const kOneBlasThread =
    ::testing::AddGlobalTestEnvironment(new OneBlasThread);

}  // namespace
}  // namespace limber::modal
