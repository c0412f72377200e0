#include "src/scene_loader.h"

namespace drape {
Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides) {
  throw InputError(path + ": scene loading is not implemented yet");
}
}  // namespace drape
