#ifndef DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_
#define DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_

#include <string>

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
// machine the threads wait on each other (381,000 context switches in a 7.8 s run), and one
// factorisation of the 50×50 sheet's Hessian takes 0.045 s with them against 0.022 s on one thread
// (docs/benchmarks.md). Both libraries are looked up at run time (they are dependencies of CHOLMOD
// and LAPACK, not of drape); a missing one is left alone. Idempotent; the first call does the work
// (for the rest of the process: LibrariesHeldOnOneThread for a call's duration).
LibraryThreads RunLibrariesOnOneThread();

// Holds OpenMP and OpenBLAS on one thread, as RunLibrariesOnOneThread does, while one of these
// lives at least, and gives them back the settings they had before the first when the last ends:
// for a process drape is a guest in (the Python module), whose own NumPy and OpenMP code must not
// be left on one thread once drape's call has returned. CHOLMOD's regions run inline
// (InlineOpenMpRegions) only while OpenMP is held. The settings the user chose through the
// environment are left alone, as RunLibrariesOnOneThread leaves them.
class LibrariesHeldOnOneThread {
 public:
  LibrariesHeldOnOneThread();
  ~LibrariesHeldOnOneThread();
  LibrariesHeldOnOneThread(const LibrariesHeldOnOneThread&) = delete;
  LibrariesHeldOnOneThread& operator=(const LibrariesHeldOnOneThread&) = delete;
};

// How many OpenMP parallel regions (CHOLMOD's) drape has run inline, on the calling thread, in
// place of libgomp's team of one. drape defines libgomp's entry point GOMP_parallel, which comes
// first in the dynamic linker's search for CHOLMOD's calls: where RunLibrariesOnOneThread made
// OpenMP's regions inactive (openmp_single), a region's body is called directly, which is what a
// team of one runs, without the team's set-up and closing barrier, whose futex wake is a system
// call; otherwise (the user chose OpenMP's threads) the region goes to libgomp's GOMP_parallel.
// CHOLMOD opens several regions per supernode: a 5.4 s solve of the 2,821-node drape tester made
// 791,093 futex calls in 224 factorisations, and one factorisation took 0.0121 s with libgomp's
// teams of one, 0.0059 s inline, on this project's virtual machine (docs/benchmarks.md, session
// 15).
long InlineOpenMpRegions();

// Which OpenBLAS kernels run, and whether drape chose them. Debian 12's OpenBLAS (0.3.21) picks
// its kernels when it loads, from the processor's model number; for a model newer than it knows
// (e.g. Intel's 5th-generation Xeon, model 207) it falls back to its generic Prescott (SSE3)
// kernels. On such a processor one factorisation of the 100×100 sheet's Hessian takes 0.186 s with
// them against 0.102 s with OpenBLAS's AVX-512 (SkylakeX) kernels (docs/benchmarks.md, session
// 12). The kernels can only be chosen before the library loads, through OPENBLAS_CORETYPE.
struct BlasKernels {
  std::string core;              // openblas_get_corename(); empty if OpenBLAS is not loaded
  bool chosen_by_drape = false;  // OPENBLAS_CORETYPE was set by RestartWithFasterBlasKernels
};
BlasKernels LoadedBlasKernels();
// The same as a line of a record: "SkylakeX (chosen by drape)", "Prescott", or "unknown".
std::string BlasKernelsText();

// The OpenBLAS kernels to ask for where OpenBLAS runs `core`: "SkylakeX" on a processor with
// AVX-512 (F, CD, BW, DQ, VL), "Haswell" on one with AVX2 and FMA, when `core` is the generic
// fallback "Prescott"; otherwise empty (OpenBLAS knows the processor, or it has nothing faster).
std::string FasterBlasCore(const std::string& core, bool avx512, bool avx2_fma);

// Called first in main(). Where OpenBLAS runs its generic fallback on a processor that has faster
// kernels (FasterBlasCore) and the user did not choose (OPENBLAS_CORETYPE unset), sets
// OPENBLAS_CORETYPE and runs the same program again with the same arguments (/proc/self/exe), so
// that OpenBLAS loads those kernels; MPI and the rest start only in the new image. Returns where
// nothing is to be done, or if the program cannot be run again (it goes on as it is).
void RestartWithFasterBlasKernels(char** argv);

}  // namespace drape

#endif  // DRAPE_SRC_NUMERICS_LIBRARY_THREADS_H_
