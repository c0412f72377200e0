#include "src/scene/file_paths.h"

#include <filesystem>

namespace drape {

std::string ResolvePath(const std::string& directory, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path given(path);
  if (given.is_absolute()) return given.lexically_normal().string();
  return (fs::path(directory) / given).lexically_normal().string();
}

std::string DirectoryOf(const std::string& path) {
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return directory.empty() ? "." : directory;
}

std::string DefaultResultFolder(const std::string& directory, const std::string& name) {
  return ResolvePath(directory, "out/" + name);
}

}  // namespace drape
