// One BLAS thread and no OpenMP parallel regions for the whole process. OpenBLAS (Debian's
// default BLAS) otherwise starts one thread per core for every dense kernel large enough, and
// CHOLMOD's supernodal kernels open OpenMP regions of a fixed 4 threads; in the eigensolver's
// factorisation and Lanczos iteration those threads mostly spin-wait on a loaded machine (a
// 61k-DOF plate among other jobs on 2 cores: 31-37 s wall with OpenBLAS threads, 7-9 s
// without; docs/benchmarks.md), and sweeps run several analyses side by side anyway.
// It changes a setting of the whole process, every other user of BLAS in it included, so a
// program's entry point decides it, never a library: limber's main (solver/app/main.cpp) and
// the Python module's init (solver/python/module.cpp) call it once. Without OpenBLAS or OpenMP
// at run time (their symbols are weak) it leaves that library alone.
#pragma once

namespace limber::modal {

void use_single_threaded_blas();

}  // namespace limber::modal
