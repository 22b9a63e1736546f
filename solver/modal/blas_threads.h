// One BLAS thread for the scope of a guard, the previous count restored after.
// OpenBLAS (Debian's default BLAS) otherwise starts one thread per core for every dense
// kernel large enough; in CHOLMOD's supernodal factorisation and ARPACK's Lanczos
// orthogonalisation those threads mostly spin-wait on a loaded machine, and the sweeps run
// several modal analyses side by side anyway. With another BLAS (no OpenBLAS symbols at run
// time) the guard does nothing.
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
};

}  // namespace limber::modal
