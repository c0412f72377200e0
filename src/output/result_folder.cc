#include "src/output/result_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>

#include "src/scene/output_kinds.h"
#include "src/scene/solver_methods.h"

namespace drape {

namespace fs = std::filesystem;

namespace {

constexpr const char* kLockName = ".drape.lock";
constexpr const char* kStagingPrefix = ".staging-";

// Folders locked by this process (flock conflicts between two descriptors of one process too).
std::set<std::string>& HeldLocks() {
  static std::set<std::string> held;
  return held;
}
std::mutex& HeldLocksMutex() {
  static std::mutex mutex;
  return mutex;
}

bool ProcessAlive(long pid) { return pid > 0 && (::kill(pid, 0) == 0 || errno == EPERM); }

// The pid at the end of ".staging-<pid>" or ".<name>.tmp<pid>"; 0 if none.
long TrailingPid(const std::string& name) {
  const size_t digits = name.find_last_not_of("0123456789");
  if (digits == std::string::npos || digits + 1 == name.size()) return 0;
  return std::stol(name.substr(digits + 1));
}

bool IsTemporaryOfAResultFile(const std::string& name) {
  for (const auto& result : ResultFileNames()) {
    const std::string prefix = "." + result + ".tmp";
    if (name.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// Staging folders and temporary files left by runs that are no longer alive.
void RemoveLeftovers(const fs::path& directory) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    const bool staging = name.rfind(kStagingPrefix, 0) == 0;
    if (!staging && !IsTemporaryOfAResultFile(name)) continue;
    const long pid = TrailingPid(name);
    if (pid == ::getpid() || ProcessAlive(pid)) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

void Rename(const fs::path& from, const fs::path& to) {
  std::error_code error;
  fs::rename(from, to, error);
  if (error) throw std::runtime_error("cannot write " + to.string() + ": " + error.message());
}

}  // namespace

const std::vector<std::string>& ResultFileNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> files;
    auto add = [&files](const std::string& file) {
      if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    };
    for (const OutputKindRow& row : OutputKinds()) {
      for (const std::string& pattern : row.files) {
        if (OutputFileName(pattern, "") == pattern) {
          add(pattern);
          continue;
        }
        for (const SolverMethod& method : SolverMethods()) {
          if (method.records_trace) add(OutputFileName(pattern, method.name));
        }
      }
    }
    add(kSolvedSceneFile);
    add("kinetic.csv");  // the trace's name before the per-method names (format version 1)
    return files;
  }();
  return names;
}

ResultFolderLock::ResultFolderLock(const fs::path& directory, bool remove_if_unused) {
  if (remove_if_unused) {
    const fs::path folder = fs::absolute(directory);
    for (fs::path p = folder; !p.empty() && p != p.root_path(); p = p.parent_path()) {
      std::error_code ignored;
      if (fs::exists(p, ignored)) break;
      created_ = p;
    }
  }
  fs::create_directories(directory);
  key_ = fs::weakly_canonical(directory).string();
  std::lock_guard<std::mutex> guard(HeldLocksMutex());
  if (HeldLocks().count(key_)) return;  // held by this process already
  const fs::path lock_path = directory / kLockName;
  descriptor_ = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (descriptor_ < 0) {
    throw std::runtime_error("cannot write into " + directory.string() + ": " +
                             std::strerror(errno));
  }
  if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
    ::close(descriptor_);
    descriptor_ = -1;
    throw std::runtime_error("another drape run is writing into " + directory.string() +
                             " (it holds " + lock_path.string() + "); wait for it or use --out");
  }
  HeldLocks().insert(key_);
}

ResultFolderLock::~ResultFolderLock() {
  if (descriptor_ >= 0) {
    std::lock_guard<std::mutex> guard(HeldLocksMutex());
    HeldLocks().erase(key_);
    ::close(descriptor_);  // releases the flock
  }
  std::error_code ignored;
  if (!created_.empty()) fs::remove_all(created_, ignored);
}

ResultFolder::ResultFolder(const fs::path& directory) : directory_(directory), lock_(directory) {
  RemoveLeftovers(directory_);
  staging_ = directory_ / (kStagingPrefix + std::to_string(::getpid()));
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  fs::create_directory(staging_);
}

ResultFolder::~ResultFolder() {
  std::error_code ignored;
  if (!committed_) fs::remove_all(staging_, ignored);
}

void ResultFolder::Commit() {
  std::set<std::string> staged;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    staged.insert(entry.path().filename().string());
  }
  std::error_code ignored;
  fs::remove(directory_ / "summary.json", ignored);  // the folder is incomplete from here on
  for (const auto& name : ResultFileNames()) {
    if (!staged.count(name)) fs::remove(directory_ / name, ignored);
  }
  for (const auto& name : staged) {
    if (name != "summary.json") Rename(staging_ / name, directory_ / name);
  }
  if (staged.count("summary.json")) {
    Rename(staging_ / "summary.json", directory_ / "summary.json");
  }
  fs::remove_all(staging_, ignored);
  committed_ = true;
}

}  // namespace drape
