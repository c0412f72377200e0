// RunLibrariesOnOneThread: CHOLMOD's OpenMP regions and OpenBLAS end up on one thread, the regions
// inline; the OpenBLAS kernels drape asks for.
#include "src/numerics/library_threads.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "src/numerics/sparse_hessian.h"
#include "tests/assembled_hessian.h"
#include "tests/hand_built_models.h"

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

// CHOLMOD's OpenMP regions reach drape's GOMP_parallel, which runs them inline where OpenMP runs on
// one thread (and hands them to libgomp where the user chose its threads); the factorisation they
// compute solves its system.
TEST(LibraryThreads, CholmodRegionsRunInlineWhereOpenMpRunsOnOneThread) {
  const LibraryThreads threads = RunLibrariesOnOneThread();
  testing::SheetSpec spec;
  spec.nu = 30;
  spec.nv = 30;
  spec.fixed = {0, 29};
  const testing::AssembledHessian assembled(testing::Sheet(spec), /*project=*/true);
  const FreeHessian& hessian = assembled.hessian;
  SparseCholesky cholesky(hessian);
  const long before = InlineOpenMpRegions();
  const std::vector<double> shift(hessian.size(), 1.0);
  ASSERT_TRUE(cholesky.Factorize(hessian.projected_values(), &shift));
  if (threads.openmp_single) {
    EXPECT_GT(InlineOpenMpRegions(), before);
  } else {
    EXPECT_EQ(InlineOpenMpRegions(), before);
  }
  std::vector<double> b(hessian.size()), x, product(hessian.size());
  for (int k = 0; k < hessian.size(); ++k) b[k] = std::sin(k);
  cholesky.Solve(b, &x);
  hessian.Multiply(hessian.projected_values(), x.data(), product.data());
  for (int k = 0; k < hessian.size(); ++k) EXPECT_NEAR(product[k] + x[k], b[k], 1e-9);
}

void CallSetIntFunction(const char* name, int value) {
  const auto function = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, name));
  if (function != nullptr) function(value);
}

// A host process (the Python module) that runs OpenBLAS on 2 threads and OpenMP 3 levels deep has
// them back when the last of two nested holds ends; inside, both run on one thread and CHOLMOD's
// regions inline. What the user chose through the environment drape leaves alone.
TEST(LibraryThreads, AHoldGivesTheHostItsSettingsBack) {
  const LibraryThreads ours = RunLibrariesOnOneThread();
  CallSetIntFunction("openblas_set_num_threads", 2);
  CallSetIntFunction("omp_set_max_active_levels", 3);
  const int host_threads = CallIntFunction("openblas_get_num_threads");
  const int host_levels = CallIntFunction("omp_get_max_active_levels");
  {
    const LibrariesHeldOnOneThread outer;
    { const LibrariesHeldOnOneThread inner; }
    if (ours.openblas_single) {
      EXPECT_EQ(CallIntFunction("openblas_get_num_threads"), 1);
    }
    if (ours.openmp_single) {
      EXPECT_EQ(CallIntFunction("omp_get_max_active_levels"), 0);
      testing::SheetSpec spec;
      spec.nu = 20;
      spec.nv = 20;
      spec.fixed = {0, 19};
      const testing::AssembledHessian assembled(testing::Sheet(spec), /*project=*/true);
      SparseCholesky cholesky(assembled.hessian);
      const long before = InlineOpenMpRegions();
      const std::vector<double> shift(assembled.hessian.size(), 1.0);
      ASSERT_TRUE(cholesky.Factorize(assembled.hessian.projected_values(), &shift));
      EXPECT_GT(InlineOpenMpRegions(), before);
    }
  }
  EXPECT_EQ(CallIntFunction("openblas_get_num_threads"), host_threads);
  EXPECT_EQ(CallIntFunction("omp_get_max_active_levels"), host_levels);
  CallSetIntFunction("openblas_set_num_threads", 1);  // as RunLibrariesOnOneThread left them
  CallSetIntFunction("omp_set_max_active_levels", 0);
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
