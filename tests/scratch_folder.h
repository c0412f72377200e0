// The tests' temporary folders: one owner for making a fresh empty folder under the system's
// temporary directory and for removing it. The name is drape_<tag>_<pid>_<n>, n counting the
// folders this process made, so that two tests in one process and two processes (ctest -j2) never
// share one; a name already taken (a stale folder of an earlier process with the same pid) is
// skipped, never emptied. MPI tests make the folder in the test process and hand its path to
// mpirun, so every rank uses the same folder.
#pragma once

#include <unistd.h>

#include <atomic>
#include <deque>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace drape::testing {

class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& tag) : path_(MakeFreshFolder(tag)) {}
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& name) const { return path_ / name; }

 private:
  static std::filesystem::path MakeFreshFolder(const std::string& tag) {
    static std::atomic<unsigned> made{0};
    const std::string stem = "drape_" + tag + "_" + std::to_string(::getpid()) + "_";
    while (true) {
      const auto candidate =
          std::filesystem::temp_directory_path() / (stem + std::to_string(made++));
      if (std::filesystem::create_directory(candidate)) return candidate;  // throws on failure
    }
  }

  std::filesystem::path path_;
};

// A scratch folder that lasts until the process ends and is removed then: for helpers that hand
// out a folder's path rather than its owner.
inline const std::filesystem::path& ScratchFolderUntilExit(const std::string& tag) {
  static std::deque<ScratchFolder> folders;  // a deque: the folders never move
  return folders.emplace_back(tag).path();
}

// A scratch folder holding one file, `name`, with `text`: for tests that need a single input file.
class ScratchFile {
 public:
  ScratchFile(const std::string& tag, const std::string& name, const std::string& text)
      : folder_(tag), path_(folder_ / name) {
    std::ofstream(path_) << text;
  }

  const std::filesystem::path& path() const { return path_; }

 private:
  ScratchFolder folder_;
  std::filesystem::path path_;
};

}  // namespace drape::testing
