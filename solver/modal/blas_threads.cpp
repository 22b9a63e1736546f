#include "modal/blas_threads.h"

// OpenBLAS's thread control, weak: null when the BLAS linked at run time is another one.
extern "C" {
void openblas_set_num_threads(int threads) __attribute__((weak));
int openblas_get_num_threads() __attribute__((weak));
// OpenMP (loaded with CHOLMOD, whose supernodal kernels open parallel regions of a fixed
// 4 threads): with max-active-levels 0 every parallel region runs on the calling thread.
int omp_get_max_active_levels() __attribute__((weak));
void omp_set_max_active_levels(int levels) __attribute__((weak));
}

namespace limber::modal {

SingleThreadedBlas::SingleThreadedBlas() {
  if (omp_get_max_active_levels != nullptr && omp_set_max_active_levels != nullptr) {
    previous_levels_ = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
  }
  if (openblas_set_num_threads == nullptr || openblas_get_num_threads == nullptr) return;
  previous_threads_ = openblas_get_num_threads();
  if (previous_threads_ > 1) openblas_set_num_threads(1);
}

SingleThreadedBlas::~SingleThreadedBlas() {
  if (previous_threads_ > 1) openblas_set_num_threads(previous_threads_);
  if (previous_levels_ >= 0) omp_set_max_active_levels(previous_levels_);
}

}  // namespace limber::modal
