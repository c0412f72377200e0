#include "src/numerics/library_threads.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <initializer_list>

namespace drape {

namespace {

using SetIntFunction = void (*)(int);

// Calls `name(value)` if the function is in a loaded library and none of `user_variables` is set.
bool CallUnlessUserChose(const char* name, int value,
                         std::initializer_list<const char*> user_variables) {
  for (const char* variable : user_variables) {
    if (std::getenv(variable) != nullptr) return false;
  }
  const auto function = reinterpret_cast<SetIntFunction>(dlsym(RTLD_DEFAULT, name));
  if (function == nullptr) return false;
  function(value);
  return true;
}

LibraryThreads Configure() {
  LibraryThreads result;
  // max-active-levels 0 makes every parallel region inactive (one thread), the num_threads(4)
  // clauses in CHOLMOD included, which OMP_NUM_THREADS cannot do.
  result.openmp_single = CallUnlessUserChose("omp_set_max_active_levels", 0,
                                             {"OMP_MAX_ACTIVE_LEVELS", "OMP_THREAD_LIMIT"});
  result.openblas_single =
      CallUnlessUserChose("openblas_set_num_threads", 1, {"OPENBLAS_NUM_THREADS"});
  return result;
}

}  // namespace

LibraryThreads RunLibrariesOnOneThread() {
  static const LibraryThreads configured = Configure();
  return configured;
}

namespace {

constexpr char kChoiceMarker[] = "DRAPE_CHOSE_OPENBLAS_CORETYPE";

bool HasAvx512() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
}

bool HasAvx2AndFma() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

}  // namespace

BlasKernels LoadedBlasKernels() {
  BlasKernels kernels;
  const auto corename = reinterpret_cast<char* (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (corename != nullptr && corename() != nullptr) kernels.core = corename();
  kernels.chosen_by_drape = std::getenv(kChoiceMarker) != nullptr;
  return kernels;
}

std::string BlasKernelsText() {
  const BlasKernels kernels = LoadedBlasKernels();
  if (kernels.core.empty()) return "unknown";
  return kernels.core + (kernels.chosen_by_drape ? " (chosen by drape)" : "");
}

std::string FasterBlasCore(const std::string& core, bool avx512, bool avx2_fma) {
  if (core != "Prescott" && core != "prescott") return "";
  if (avx512) return "SkylakeX";
  if (avx2_fma) return "Haswell";
  return "";
}

void RestartWithFasterBlasKernels(char** argv) {
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr) return;
  const std::string faster = FasterBlasCore(LoadedBlasKernels().core, HasAvx512(), HasAvx2AndFma());
  if (faster.empty()) return;
  if (setenv("OPENBLAS_CORETYPE", faster.c_str(), 1) != 0) return;
  setenv(kChoiceMarker, "1", 1);
  execv("/proc/self/exe", argv);
  unsetenv("OPENBLAS_CORETYPE");  // not run again: go on with the kernels loaded
  unsetenv(kChoiceMarker);
}

}  // namespace drape
