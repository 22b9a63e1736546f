#include "modal/blas_threads.h"

// OpenBLAS's thread control, weak: null when the BLAS linked at run time is another one.
extern "C" {
void openblas_set_num_threads(int threads) __attribute__((weak));
int openblas_get_num_threads() __attribute__((weak));
}

namespace limber::modal {

SingleThreadedBlas::SingleThreadedBlas() {
  if (openblas_set_num_threads == nullptr || openblas_get_num_threads == nullptr) return;
  previous_threads_ = openblas_get_num_threads();
  if (previous_threads_ > 1) openblas_set_num_threads(1);
}

SingleThreadedBlas::~SingleThreadedBlas() {
  if (previous_threads_ > 1) openblas_set_num_threads(previous_threads_);
}

}  // namespace limber::modal
