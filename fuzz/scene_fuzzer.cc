// libFuzzer target: the scene loader, the model builder and the OBJ and PLY mesh readers on
// arbitrary bytes (fuzz/fuzz_input.h says how an input becomes a scene and mesh files). Built by
// the sanitized build with clang (-DDRAPE_SANITIZE=ON -DCMAKE_CXX_COMPILER=clang++); run by
// .ci/fuzz.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  drape_fuzz::RunInput(data, size);
  return 0;
}
