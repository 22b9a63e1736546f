// One BLAS thread and no OpenMP parallel regions for the scope of a guard, the previous
// settings restored after. OpenBLAS (Debian's default BLAS) otherwise starts one thread per
// core for every dense kernel large enough, and CHOLMOD's supernodal kernels open OpenMP
// regions of a fixed 4 threads; in the factorisation and the Lanczos iteration those
// threads mostly spin-wait on a loaded machine (a 61k-DOF plate among other jobs on 2
// cores: 31-37 s wall with OpenBLAS threads, 7-9 s without; docs/benchmarks.md), and sweeps
// run several analyses side by side anyway. Without OpenBLAS or OpenMP at run time (their
// symbols are weak) the guard leaves that library alone.
#pragma once

namespace limber::modal {

class SingleThreadedBlas {
 public:
  SingleThreadedBlas();
  ~SingleThreadedBlas();
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  int previous_threads_ = 0;  // 0: nothing to restore
  int previous_levels_ = -1;  // OpenMP max-active-levels before; -1: nothing to restore
};

}  // namespace limber::modal
