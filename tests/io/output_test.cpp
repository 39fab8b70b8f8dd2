// The output facility (io/files.hpp): every kind of path an output flag may name. Device nodes and FIFOs
// are made in a scratch folder (mknod needs root; those tests skip without it); /dev is never touched.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"

namespace fs = std::filesystem;
using namespace rbcstab;

namespace {

struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() / ("rbcstab_output_test_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
  // Names in the folder that look like temporaries of the facility.
  std::vector<std::string> strays() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(".tmp-") != std::string::npos) out.push_back(e.path().string());
    return out;
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool make_char_device(const std::string& path, unsigned major, unsigned minor) {
  return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(major, minor)) == 0;
}

mode_t kind_of(const std::string& path) {
  struct stat st {};
  EXPECT_EQ(::lstat(path.c_str(), &st), 0) << path;
  return st.st_mode & S_IFMT;
}

template <class E>
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception of the expected type";
  return "";
}

}  // namespace

TEST(Output, RegularFileIsReplacedAtomicallyAndKeepsItsPermissions) {
  Scratch s;
  const std::string p = s / "a.csv";
  write_file_atomic(p, "one\n", "--csv");
  EXPECT_EQ(slurp(p), "one\n");
  ASSERT_EQ(::chmod(p.c_str(), 0640), 0);
  struct stat before {};
  ASSERT_EQ(::stat(p.c_str(), &before), 0);
  write_file_atomic(p, "two\n", "--csv");
  struct stat after {};
  ASSERT_EQ(::stat(p.c_str(), &after), 0);
  EXPECT_EQ(slurp(p), "two\n");
  EXPECT_NE(before.st_ino, after.st_ino);  // a new file renamed over the old one, not rewritten in place
  EXPECT_EQ(after.st_mode & 07777, 0640u);
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, DashWritesStandardOutput) {
  ::testing::internal::CaptureStdout();
  write_file_atomic("-", "to stdout\n", "--trajectory");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "to stdout\n");
}

TEST(Output, FifoIsWrittenThroughToItsReaderAndKept) {
  Scratch s;
  const std::string p = s / "pipe";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(p); });
  const std::string content(200000, 'x');  // larger than a pipe buffer: the writer must wait for the reader
  write_file_atomic(p, content, "--trajectory");
  reader.join();
  EXPECT_EQ(got, content);
  EXPECT_EQ(kind_of(p), mode_t(S_IFIFO));
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, CharDeviceIsWrittenThroughAndKept) {
  Scratch s;
  const std::string p = s / "null";
  if (!make_char_device(p, 1, 3)) GTEST_SKIP() << "mknod not permitted here (needs root)";
  write_file_atomic(p, "discarded\n", "--trajectory");
  EXPECT_EQ(kind_of(p), mode_t(S_IFCHR));
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, FullDeviceIsAnOutputErrorNamingFlagAndPath) {
  Scratch s;
  const std::string p = s / "full";
  if (!make_char_device(p, 1, 7)) GTEST_SKIP() << "mknod not permitted here (needs root)";
  const std::string msg = message_of<OutputError>([&] { write_file_atomic(p, "x\n", "--trajectory"); });
  EXPECT_NE(msg.find("--trajectory"), std::string::npos) << msg;
  EXPECT_NE(msg.find(p), std::string::npos) << msg;
  EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
  EXPECT_EQ(kind_of(p), mode_t(S_IFCHR));
}

TEST(Output, SymbolicLinkIsFollowedItsTargetReplacedTheLinkKept) {
  Scratch s;
  fs::create_directories(s.dir / "real");
  const std::string target = s / "real/t.csv";
  const std::string link = s / "link.csv";
  std::ofstream(target) << "old\n";
  fs::create_symlink("real/t.csv", link);  // relative: resolved against the link's folder
  write_file_atomic(link, "new\n", "--csv");
  EXPECT_EQ(kind_of(link), mode_t(S_IFLNK));
  EXPECT_EQ(slurp(target), "new\n");
  // A link to a link, and a dangling link: the final target is created.
  const std::string chain = s / "chain.csv";
  fs::create_symlink(link, chain);
  write_file_atomic(chain, "newer\n", "--csv");
  EXPECT_EQ(slurp(target), "newer\n");
  const std::string dangling = s / "dangling.csv";
  fs::create_symlink("real/created.csv", dangling);
  write_file_atomic(dangling, "made\n", "--csv");
  EXPECT_EQ(kind_of(dangling), mode_t(S_IFLNK));
  EXPECT_EQ(slurp(s / "real/created.csv"), "made\n");
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, SymbolicLinkToADeviceWritesThrough) {
  Scratch s;
  const std::string dev = s / "null";
  if (!make_char_device(dev, 1, 3)) GTEST_SKIP() << "mknod not permitted here (needs root)";
  const std::string link = s / "stdout_like";
  fs::create_symlink(dev, link);
  write_file_atomic(link, "x\n", "--trajectory");
  EXPECT_EQ(kind_of(link), mode_t(S_IFLNK));
  EXPECT_EQ(kind_of(dev), mode_t(S_IFCHR));
}

TEST(Output, DirectoryAndMissingFolderAreOutputErrorsNamingFlagAndPath) {
  Scratch s;
  const std::string dir = s / "dd";
  fs::create_directories(dir);
  std::string msg = message_of<OutputError>([&] { write_file_atomic(dir, "x", "--csv"); });
  EXPECT_NE(msg.find("--csv"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'" + dir + "'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("is a directory"), std::string::npos) << msg;
  const std::string missing = s / "no/such/folder/x.csv";
  msg = message_of<OutputError>([&] { write_file_atomic(missing, "x", "--trajectory"); });
  EXPECT_NE(msg.find("--trajectory"), std::string::npos) << msg;
  EXPECT_NE(msg.find(missing), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  msg = message_of<OutputError>([&] { write_file_atomic("", "x", ""); });
  EXPECT_NE(msg.find("output"), std::string::npos) << msg;
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, ASetIsWrittenTogetherOrNotAtAll) {
  Scratch s;
  const std::string csv = s / "p.csv", json = s / "p.json";
  write_files_atomic({{csv, "c1\n", "--out"}, {json, "j1\n", "--out"}});
  EXPECT_EQ(slurp(csv), "c1\n");
  EXPECT_EQ(slurp(json), "j1\n");
  // A bad second path: found before anything is written.
  EXPECT_THROW(write_files_atomic({{csv, "c2\n", "--out"}, {s / "no/p.json", "j2\n", "--out"}}), OutputError);
  EXPECT_EQ(slurp(csv), "c1\n");
  // A write that fails after the first file was staged: the first stays as it was, its temporary is gone.
  const std::string full = s / "full";
  if (make_char_device(full, 1, 7)) {
    EXPECT_THROW(write_files_atomic({{csv, "c3\n", "--out"}, {full, "j3\n", "--out"}}), OutputError);
    EXPECT_EQ(slurp(csv), "c1\n");
  }
  EXPECT_TRUE(s.strays().empty());
}

TEST(Output, TemporariesOfDeadProcessesAreRemovedOthersKept) {
  Scratch s;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // reaped: its pid names no process now
  const std::string dead_file = s / (".r.csv.tmp-" + std::to_string(child) + "-ab12");
  const fs::path dead_dir = s.dir / (".r.csv.tmp-" + std::to_string(child) + "-cd34");
  const std::string live = s / (".r.csv.tmp-" + std::to_string(::getppid()) + "-ef56");
  const std::string other = s / (".q.csv.tmp-" + std::to_string(child) + "-ab12");
  for (const std::string& p : {dead_file, live, other}) std::ofstream(p) << "x";
  fs::create_directories(dead_dir / "inner");
  write_file_atomic(s / "r.csv", "r\n", "--csv");
  EXPECT_FALSE(fs::exists(dead_file));
  EXPECT_FALSE(fs::exists(dead_dir));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));  // another output's temporaries are left to that output's next write
  EXPECT_EQ(staging_prefix("r.csv", ".tmp-"), ".r.csv.tmp-" + std::to_string(::getpid()) + "-");
}

TEST(Output, AnAppendedFileMustBeARegularFile) {
  Scratch s;
  require_file_output(s / "new.journal", "--journal");
  const std::string pipe = s / "pipe";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  for (const std::string& p : {pipe, std::string("-"), s.dir.string()}) {
    const std::string msg = message_of<OutputError>([&] { require_file_output(p, "--journal"); });
    EXPECT_NE(msg.find("--journal: cannot write '" + p + "'"), std::string::npos) << msg;
  }
}
