// RunLibrariesOnOneThread: CHOLMOD's OpenMP regions and OpenBLAS end up on one thread; the
// OpenBLAS kernels drape asks for.
#include "src/numerics/library_threads.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>

namespace drape {
namespace {

int CallIntFunction(const char* name) {
  const auto function = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, name));
  return function == nullptr ? -1 : function();
}

TEST(LibraryThreads, OpenMpAndOpenBlasRunOnOneThreadUnlessTheUserChose) {
  const LibraryThreads result = RunLibrariesOnOneThread();
  if (std::getenv("OMP_MAX_ACTIVE_LEVELS") == nullptr &&
      std::getenv("OMP_THREAD_LIMIT") == nullptr) {
    ASSERT_TRUE(result.openmp_single);  // libgomp is loaded with CHOLMOD
    EXPECT_EQ(CallIntFunction("omp_get_max_active_levels"), 0);
  }
  if (std::getenv("OPENBLAS_NUM_THREADS") == nullptr && result.openblas_single) {
    EXPECT_EQ(CallIntFunction("openblas_get_num_threads"), 1);
  }
  // A second call changes nothing and says the same.
  const LibraryThreads again = RunLibrariesOnOneThread();
  EXPECT_EQ(again.openmp_single, result.openmp_single);
  EXPECT_EQ(again.openblas_single, result.openblas_single);
}

// Faster kernels are asked for only where OpenBLAS fell back to its generic ones, and only those
// the processor runs.
TEST(LibraryThreads, FasterBlasKernelsOnlyInPlaceOfTheGenericFallback) {
  EXPECT_EQ(FasterBlasCore("Prescott", true, true), "SkylakeX");
  EXPECT_EQ(FasterBlasCore("Prescott", false, true), "Haswell");
  EXPECT_EQ(FasterBlasCore("Prescott", false, false), "");
  EXPECT_EQ(FasterBlasCore("SkylakeX", true, true), "");
  EXPECT_EQ(FasterBlasCore("Zen", false, true), "");
  EXPECT_EQ(FasterBlasCore("", true, true), "");
}

// OpenBLAS is loaded with CHOLMOD and names its kernels (the benchmark and `drape compare` print
// them).
TEST(LibraryThreads, NamesTheLoadedBlasKernels) { EXPECT_FALSE(LoadedBlasKernels().core.empty()); }

}  // namespace
}  // namespace drape
