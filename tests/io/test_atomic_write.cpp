// The save behind every output: whole or not at all, durable, and keeping the file's mode and
// symbolic links (src/io/atomic_write.cpp).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "io/atomic_write.hpp"

namespace sphereset {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

mode_t modeOf(const fs::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0);
  return st.st_mode & 07777;
}

class AtomicWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("sphereset_atomic_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Files in the folder other than `keep` (temporary files left behind).
  int strays(const std::set<std::string>& keep) const {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir_))
      if (!keep.count(e.path().filename().string())) ++n;
    return n;
  }
  fs::path dir_;
};

TEST_F(AtomicWrite, AnExistingFileKeepsItsMode) {
  const fs::path f = dir_ / "set.txt";
  ASSERT_TRUE(writeFileAtomically(f.string(), "old\n"));
  ASSERT_EQ(::chmod(f.c_str(), 0600), 0);
  ASSERT_TRUE(writeFileAtomically(f.string(), "new\n"));
  EXPECT_EQ(slurp(f), "new\n");
  EXPECT_EQ(modeOf(f), 0600u);
  ASSERT_EQ(::chmod(f.c_str(), 0640), 0);
  ASSERT_TRUE(writeFileAtomically(f.string(), "newer\n"));
  EXPECT_EQ(modeOf(f), 0640u);
}

TEST_F(AtomicWrite, ANewFileHonoursTheUmask) {
  const mode_t old = ::umask(077);
  const Status st = writeFileAtomically((dir_ / "a.txt").string(), "x");
  ::umask(022);
  const Status st2 = writeFileAtomically((dir_ / "b.txt").string(), "x");
  ::umask(old);
  ASSERT_TRUE(st);
  ASSERT_TRUE(st2);
  EXPECT_EQ(modeOf(dir_ / "a.txt"), 0600u);
  EXPECT_EQ(modeOf(dir_ / "b.txt"), 0644u);
}

// A sphere file that is a symbolic link used to be replaced by a regular file, the real target
// never updated: the write goes through the link, which stays a link.
TEST_F(AtomicWrite, ASymbolicLinkIsWrittenThrough) {
  fs::create_directories(dir_ / "real");
  const fs::path real = dir_ / "real" / "set.txt", link = dir_ / "link.txt";
  ASSERT_TRUE(writeFileAtomically(real.string(), "old\n"));
  ASSERT_EQ(::chmod(real.c_str(), 0600), 0);
  fs::create_symlink(fs::path("real") / "set.txt", link);  // relative, as users make them
  ASSERT_TRUE(writeFileAtomically(link.string(), "through\n"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(slurp(real), "through\n");
  EXPECT_EQ(modeOf(real), 0600u);
  // A chain of links, and a dangling one (its target is created).
  const fs::path link2 = dir_ / "link2.txt";
  fs::create_symlink(link, link2);
  ASSERT_TRUE(writeFileAtomically(link2.string(), "chain\n"));
  EXPECT_EQ(slurp(real), "chain\n");
  const fs::path dangling = dir_ / "dangling.txt";
  fs::create_symlink(dir_ / "real" / "new.txt", dangling);
  ASSERT_TRUE(writeFileAtomically(dangling.string(), "made\n"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dangling)));
  EXPECT_EQ(slurp(dir_ / "real" / "new.txt"), "made\n");
  // A loop is refused with a message, nothing written.
  fs::create_symlink(dir_ / "loop_b", dir_ / "loop_a");
  fs::create_symlink(dir_ / "loop_a", dir_ / "loop_b");
  const Status loop = writeFileAtomically((dir_ / "loop_a").string(), "x");
  ASSERT_FALSE(loop);
  EXPECT_NE(loop.error().message.find("too many levels of symbolic links"), std::string::npos)
      << loop.error().message;
}

// A write that fails half way (here the file-size limit stops it, as a full disk would) leaves
// the old file whole and no temporary file behind.
TEST_F(AtomicWrite, AnInterruptedWriteLeavesTheOldFileWhole) {
  const fs::path f = dir_ / "set.txt";
  const std::string old(1000, 'o');
  ASSERT_TRUE(writeFileAtomically(f.string(), old));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit lim{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    const Status st = writeFileAtomically(f.string(), std::string(100000, 'n'));
    const bool named = !st && st.error().message.find("write failed") != std::string::npos;
    ::_exit(named ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the failed write was not reported";
  EXPECT_EQ(slurp(f), old);
  EXPECT_EQ(strays({"set.txt"}), 0);
}

TEST_F(AtomicWrite, AFolderOrAMissingFolderIsRefused) {
  const Status folder = writeFileAtomically(dir_.string(), "x");
  EXPECT_FALSE(folder);
  const Status missing = writeFileAtomically((dir_ / "no" / "such.txt").string(), "x");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("cannot create a file"), std::string::npos);
}

}  // namespace
}  // namespace sphereset
