#include "src/numerics/library_threads.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <initializer_list>
#include <mutex>

namespace drape {

namespace {

using SetIntFunction = void (*)(int);
using GetIntFunction = int (*)();

// Whether `name` is in a loaded library and none of `user_variables` is set.
bool OursToSet(const char* name, std::initializer_list<const char*> user_variables) {
  for (const char* variable : user_variables) {
    if (std::getenv(variable) != nullptr) return false;
  }
  return dlsym(RTLD_DEFAULT, name) != nullptr;
}

void CallSetter(const char* name, int value) {
  const auto function = reinterpret_cast<SetIntFunction>(dlsym(RTLD_DEFAULT, name));
  if (function != nullptr) function(value);
}

int CallGetter(const char* name) {
  const auto function = reinterpret_cast<GetIntFunction>(dlsym(RTLD_DEFAULT, name));
  return function == nullptr ? -1 : function();
}

// Which of the two settings are drape's to make: decided once, from the environment.
const LibraryThreads& OursToMake() {
  static const LibraryThreads ours = [] {
    LibraryThreads result;
    result.openmp_single =
        OursToSet("omp_set_max_active_levels", {"OMP_MAX_ACTIVE_LEVELS", "OMP_THREAD_LIMIT"});
    result.openblas_single = OursToSet("openblas_set_num_threads", {"OPENBLAS_NUM_THREADS"});
    return result;
  }();
  return ours;
}

// Whether CHOLMOD's regions run inline (GOMP_parallel, below): while OpenMP is held on one thread.
std::atomic<bool> openmp_held{false};

void HoldOnOneThread() {
  const LibraryThreads& ours = OursToMake();
  // max-active-levels 0 makes every parallel region inactive (one thread), the num_threads(4)
  // clauses in CHOLMOD included, which OMP_NUM_THREADS cannot do.
  if (ours.openmp_single) CallSetter("omp_set_max_active_levels", 0);
  if (ours.openblas_single) CallSetter("openblas_set_num_threads", 1);
  if (ours.openmp_single) openmp_held = true;
}

// The host's settings before the outermost LibrariesHeldOnOneThread, and how many are alive.
struct HostSettings {
  std::mutex mutex;
  int scopes = 0;
  int openmp_levels = -1;
  int openblas_threads = -1;
  bool openmp_held = false;
};

HostSettings& Host() {
  static HostSettings host;
  return host;
}

}  // namespace

LibraryThreads RunLibrariesOnOneThread() {
  [[maybe_unused]] static const bool held = [] {
    HoldOnOneThread();
    return true;
  }();
  return OursToMake();
}

LibrariesHeldOnOneThread::LibrariesHeldOnOneThread() {
  HostSettings& host = Host();
  const std::lock_guard<std::mutex> lock(host.mutex);
  if (host.scopes++ > 0) return;
  host.openmp_levels = CallGetter("omp_get_max_active_levels");
  host.openblas_threads = CallGetter("openblas_get_num_threads");
  host.openmp_held = openmp_held;
  HoldOnOneThread();
}

LibrariesHeldOnOneThread::~LibrariesHeldOnOneThread() {
  HostSettings& host = Host();
  const std::lock_guard<std::mutex> lock(host.mutex);
  if (--host.scopes > 0) return;
  const LibraryThreads& ours = OursToMake();
  openmp_held = host.openmp_held;
  if (ours.openmp_single && host.openmp_levels >= 0) {
    CallSetter("omp_set_max_active_levels", host.openmp_levels);
  }
  if (ours.openblas_single && host.openblas_threads > 0) {
    CallSetter("openblas_set_num_threads", host.openblas_threads);
  }
}

namespace {

std::atomic<long> inline_openmp_regions{0};

using ParallelFunction = void (*)(void (*)(void*), void*, unsigned, unsigned);

// libgomp's own GOMP_parallel, the next definition after drape's; null if none is loaded.
ParallelFunction LibgompParallel() {
  static const auto function =
      reinterpret_cast<ParallelFunction>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  return function;
}

}  // namespace

long InlineOpenMpRegions() { return inline_openmp_regions.load(); }

}  // namespace drape

// The entry point of `#pragma omp parallel` in GCC's OpenMP ABI (libgomp): `body(data)` on a team
// of `num_threads` threads (0: the default). See InlineOpenMpRegions (library_threads.h). Inline,
// the body sees what a team of one shows it: omp_get_thread_num() 0, omp_get_num_threads() 1, and
// a worksharing construct inside it is shared by the one thread.
extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned num_threads,
                              unsigned flags) {
  const drape::ParallelFunction libgomp = drape::LibgompParallel();
  if (libgomp != nullptr && !drape::openmp_held) {
    libgomp(body, data, num_threads, flags);
    return;
  }
  ++drape::inline_openmp_regions;
  body(data);
}

namespace drape {

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
