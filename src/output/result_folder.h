// A result folder written as a whole. A run's files are written into a hidden staging folder
// inside the result folder (.staging-<pid>), then moved in: first the previous summary.json is
// removed, then the files of the result kinds (ResultFileNames) that this run does not write,
// then every new file is renamed in, summary.json last. So a folder that has a summary.json holds
// only files of the run that wrote it; a run killed part way leaves no summary.json, and the next
// run removes its staging folder and temporaries. A lock (flock on .drape.lock in the folder)
// refuses a second run into the same folder while one holds it.
#ifndef DRAPE_SRC_OUTPUT_RESULT_FOLDER_H_
#define DRAPE_SRC_OUTPUT_RESULT_FOLDER_H_

#include <filesystem>
#include <string>
#include <vector>

namespace drape {

// Every file name a solve may write into its result folder: each output kind's files
// (src/scene/output_kinds.h), the trace's for each method that records one, scene.yaml, and the
// trace's name of older versions (kinetic.csv), so that an older run's is removed too.
const std::vector<std::string>& ResultFileNames();

// Holds the folder's lock for its lifetime; creates the folder. Throws std::runtime_error when
// another process holds it ("another drape run is writing into ..."). Taking it again in the same
// process (the command, then the writers) is allowed.
//
// With `remove_if_unused`, the folders the lock had to create are removed again when it is released
// unless KeepFolder() was called: a run that takes the lock before it solves and then fails (a
// model error found at solve time) leaves no folder behind.
class ResultFolderLock {
 public:
  explicit ResultFolderLock(const std::filesystem::path& directory, bool remove_if_unused = false);
  ~ResultFolderLock();
  ResultFolderLock(const ResultFolderLock&) = delete;
  ResultFolderLock& operator=(const ResultFolderLock&) = delete;
  void KeepFolder() { created_.clear(); }

 private:
  std::string key_;
  int descriptor_ = -1;            // -1: the lock was already held in this process
  std::filesystem::path created_;  // the outermost folder created, to remove (empty: none)
};

class ResultFolder {
 public:
  // Locks `directory`, removes what killed runs left there, and creates the staging folder.
  explicit ResultFolder(const std::filesystem::path& directory);
  // Removes the staging folder if Commit was not reached.
  ~ResultFolder();
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  // Moves the staged files in (see above).
  void Commit();

 private:
  std::filesystem::path directory_;
  ResultFolderLock lock_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_RESULT_FOLDER_H_
