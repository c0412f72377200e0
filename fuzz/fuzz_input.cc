// The fuzz target's input handling (see fuzz/fuzz_input.h).
#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "src/model/model.h"
#include "src/scene/scene_loader.h"
#include "src/scene/scene_size.h"

namespace drape_fuzz {
namespace {

// Meshes above this many nodes are loaded but not built: the build is linear in the nodes, and
// a large one only slows the fuzzer down (the loader's own limit is checked on every input).
constexpr long kMaxBuiltNodes = 20000;

constexpr char kMeshMarker[] = "\n---mesh---\n";
// The bytes after the marker, under each name a scene can give (src/scene/mesh_file.h).
constexpr const char* kMeshFiles[] = {"mesh.obj", "mesh.ply", "mesh.stl"};

// A folder of this process's own for the scene and its mesh files (InputFolder): removed by the
// process that made it, not by a forked child that inherited it.
class ProcessFolder {
 public:
  ProcessFolder() : owner_(getpid()) {
    const char* tmp = std::getenv("TMPDIR");
    path_ = std::filesystem::path(tmp ? tmp : "/tmp") / ("drape_fuzz_" + std::to_string(owner_));
    std::filesystem::create_directories(path_);
  }
  ~ProcessFolder() {
    std::error_code ignored;
    if (getpid() == owner_) std::filesystem::remove_all(path_, ignored);
  }
  ProcessFolder(const ProcessFolder&) = delete;
  ProcessFolder& operator=(const ProcessFolder&) = delete;
  pid_t owner() const { return owner_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  pid_t owner_;
  std::filesystem::path path_;
};

const std::filesystem::path& Folder() {
  static std::unique_ptr<ProcessFolder> folder;
  if (!folder || folder->owner() != getpid()) folder = std::make_unique<ProcessFolder>();
  return folder->path();
}

void WriteBytes(const std::filesystem::path& path, const char* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
}

// Writes the scene (and the mesh files, removed when the input has none); returns the scene's
// path.
std::string WriteInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t marker = input.find(kMeshMarker);
  const std::filesystem::path scene = Folder() / "scene.yaml";
  std::error_code ignored;
  if (marker == std::string::npos) {
    WriteBytes(scene, input.data(), input.size());
    for (const char* name : kMeshFiles) std::filesystem::remove(Folder() / name, ignored);
  } else {
    WriteBytes(scene, input.data(), marker + 1);
    const size_t mesh = marker + sizeof(kMeshMarker) - 1;
    for (const char* name : kMeshFiles) {
      WriteBytes(Folder() / name, input.data() + mesh, input.size() - mesh);
    }
  }
  return scene.string();
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

int RunInput(const uint8_t* data, size_t size) {
  const std::string path = WriteInput(data, size);
  try {
    const drape::Scene scene = drape::LoadScene(path);
    if (drape::EstimatedNodes(scene.mesh) > kMaxBuiltNodes) return -2;
    const drape::Model model = drape::BuildModel(scene);
    CheckFinite(model);
    return model.num_nodes;
  } catch (const drape::InputError&) {
    return -1;  // a refused scene: the expected outcome for most inputs
  }
}

std::string InputFolder() { return Folder().string(); }

}  // namespace drape_fuzz
