#include "modal/blas_threads.h"

// OpenBLAS's thread control, weak: null when the BLAS linked at run time is another one.
extern "C" {
void openblas_set_num_threads(int threads) __attribute__((weak));
// OpenMP (loaded with CHOLMOD, whose supernodal kernels open parallel regions of a fixed
// 4 threads): with max-active-levels 0 every parallel region runs on the calling thread.
void omp_set_max_active_levels(int levels) __attribute__((weak));
}

namespace limber::modal {

void use_single_threaded_blas() {
  if (omp_set_max_active_levels != nullptr) omp_set_max_active_levels(0);
  if (openblas_set_num_threads != nullptr) openblas_set_num_threads(1);
}

}  // namespace limber::modal
