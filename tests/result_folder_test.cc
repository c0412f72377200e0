// A result folder written as a whole (src/output/result_folder.h): files of an earlier run that
// this one does not write are removed, leftovers of killed runs are cleaned, and a second run
// into a folder another one holds is refused. Before, a killed or second run
// left a folder mixing two runs' files, and hidden temporaries that no later run removed.
#include "src/output/result_folder.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "tests/scratch_folder.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

class ResultFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("result_folder_test");
    directory_ = scratch_->path();
  }
  void TearDown() override { scratch_.reset(); }

  void Write(const fs::path& path, const std::string& text) const { std::ofstream(path) << text; }
  std::string Read(const std::string& name) const {
    std::ifstream file(directory_ / name);
    return std::string(std::istreambuf_iterator<char>(file), {});
  }
  std::set<std::string> Entries() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) {
      names.insert(entry.path().filename().string());
    }
    return names;
  }

  std::optional<testing::ScratchFolder> scratch_;
  fs::path directory_;
};

// A pid that no process has (above the kernel's pid_max default of 2^22).
constexpr long kDeadPid = 9999999;

TEST_F(ResultFolderTest, AnEarlierRunsFilesOfTheResultKindsGoAndOthersStay) {
  Write(directory_ / "summary.json", "old");
  Write(directory_ / "mesh.vtk", "old");
  Write(directory_ / "notes.txt", "the user's");
  {
    ResultFolder folder(directory_);
    Write(folder.staging() / "summary.json", "new");
    Write(folder.staging() / "nodes.csv", "new");
    folder.Commit();
  }
  EXPECT_EQ(Entries(),
            (std::set<std::string>{".drape.lock", "summary.json", "nodes.csv", "notes.txt"}));
  EXPECT_EQ(Read("summary.json"), "new");
  EXPECT_EQ(Read("notes.txt"), "the user's");
}

TEST_F(ResultFolderTest, ARunThatDoesNotCommitLeavesTheFolderAsItWas) {
  Write(directory_ / "summary.json", "old");
  {
    ResultFolder folder(directory_);
    Write(folder.staging() / "summary.json", "new");
  }  // e.g. a writer threw
  EXPECT_EQ(Entries(), (std::set<std::string>{".drape.lock", "summary.json"}));
  EXPECT_EQ(Read("summary.json"), "old");
}

TEST_F(ResultFolderTest, LeftoversOfKilledRunsAreRemoved) {
  const std::string dead = std::to_string(kDeadPid);
  fs::create_directory(directory_ / (".staging-" + dead));
  Write(directory_ / (".staging-" + dead) / "mesh.vtk", "half");
  Write(directory_ / (".mesh.vtk.tmp" + dead), "half");
  Write(directory_ / (".nodes.csv.tmp" + std::to_string(::getpid() == 1 ? 2 : 1)), "alive");
  {
    ResultFolder folder(directory_);
    folder.Commit();
  }
  // Only pid 1 (or 2), which is alive, keeps its temporary.
  EXPECT_EQ(Entries().count(".staging-" + dead), 0u);
  EXPECT_EQ(Entries().count(".mesh.vtk.tmp" + dead), 0u);
  EXPECT_EQ(Entries().size(), 2u);  // .drape.lock and the live process' temporary
}

TEST_F(ResultFolderTest, ASecondRunIntoAHeldFolderIsRefused) {
  fs::create_directories(directory_);
  const int other = ::open((directory_ / ".drape.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(other, 0);
  ASSERT_EQ(::flock(other, LOCK_EX | LOCK_NB), 0);  // as another process would hold it
  EXPECT_THROW(ResultFolder folder(directory_), std::runtime_error);
  ::close(other);
  EXPECT_NO_THROW(ResultFolder folder(directory_));
}

// The command takes the lock before it solves (src/cli/cli.cc); a run that then fails before
// writing leaves no folder the lock created, and one that writes keeps it.
TEST_F(ResultFolderTest, ALockTakenBeforeTheSolveRemovesTheFoldersItCreatedUnlessKept) {
  const fs::path created = directory_ / "new", folder = created / "deeper";
  {
    ResultFolderLock lock(folder, /*remove_if_unused=*/true);
    EXPECT_TRUE(fs::exists(folder / ".drape.lock"));
  }
  EXPECT_FALSE(fs::exists(created));
  {
    ResultFolderLock lock(folder, /*remove_if_unused=*/true);
    lock.KeepFolder();
  }
  EXPECT_TRUE(fs::exists(folder));
  {
    ResultFolderLock lock(folder, /*remove_if_unused=*/true);  // existed: not removed
  }
  EXPECT_TRUE(fs::exists(folder));
}

}  // namespace
}  // namespace drape
