#include "src/numerics/library_threads.h"

#include <dlfcn.h>

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

}  // namespace drape
