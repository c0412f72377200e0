#ifndef DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_
#define DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_

namespace drape {

// What RunLibrariesOnOneThread did: for each library, whether it was found and set to one thread.
struct LibraryThreads {
  bool openmp_single = false;    // OpenMP regions (CHOLMOD's supernodal kernels) run on 1 thread
  bool openblas_single = false;  // OpenBLAS (LAPACK's dpotrf, BLAS kernels) runs on 1 thread
};

// Makes CHOLMOD's OpenMP regions and OpenBLAS run on one thread, unless the user chose otherwise
// through OMP_MAX_ACTIVE_LEVELS, OMP_THREAD_LIMIT or OPENBLAS_NUM_THREADS. Debian's CHOLMOD
// (SuiteSparse 5) opens OpenMP regions of a fixed 4 threads inside every large supernode,
// ignoring OMP_NUM_THREADS, and OpenBLAS keeps its own spinning threads: on this project's 2-core
// machine the threads wait on each other (38,000 context switches a second), and one factorisation
// of the 50×50 sheet's Hessian takes 0.045 s with them against 0.022 s on one thread
// (docs/benchmarks.md). Both libraries are looked up at run time (they are dependencies of CHOLMOD
// and LAPACK, not of drape); a missing one is left alone. Idempotent; the first call does the work.
LibraryThreads RunLibrariesOnOneThread();

}  // namespace drape

#endif  // DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_
