// libFuzzer target: the scene loader and the model builder on arbitrary bytes. A scene must load
// (or be refused with an InputError), and a loaded scene must build into a model whose positions,
// masses and rest state are finite (or be refused with an InputError). Anything else — a crash,
// a hang, a sanitizer report, another exception — is a bug. Built with -DDRAPE_FUZZ=ON and clang;
// run by .ci/fuzz.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "src/model/model.h"
#include "src/scene/scene_loader.h"
#include "src/scene/scene_size.h"

namespace {

// Meshes above this many nodes are loaded but not built: the build is linear in the nodes, and
// a large one only slows the fuzzer down (the loader's own limit is checked on every input).
constexpr long kMaxBuiltNodes = 20000;

std::string ScenePath() {
  static const std::string path = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp ? tmp : "/tmp") + "/drape_fuzz_" + std::to_string(getpid()) + ".yaml";
  }();
  return path;
}

void CheckFinite(const drape::Model& model) {
  for (double x : model.positions) {
    if (!std::isfinite(x)) {
      std::fprintf(stderr, "non-finite position in a built model\n");
      std::abort();
    }
  }
  for (double m : model.mass) {
    if (!std::isfinite(m)) {
      std::fprintf(stderr, "non-finite mass in a built model\n");
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  {
    std::ofstream out(ScenePath(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const drape::Scene scene = drape::LoadScene(ScenePath());
    if (drape::EstimatedNodes(scene.mesh) > kMaxBuiltNodes) return 0;
    CheckFinite(drape::BuildModel(scene));
  } catch (const drape::InputError&) {
    // A refused scene: the expected outcome for most inputs.
  }
  return 0;
}
