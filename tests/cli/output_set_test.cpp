// OutputSet (cli/src/output_files.hpp) on its own: what each kind of path becomes, and that the
// outputs of a run appear together or not at all.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "cli_test_files.hpp"
#include "errors.hpp"
#include "output_files.hpp"

namespace ncbridge::cli {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) { return ncbridge::testing::fresh_test_directory("cli_output_set", name); }

using ncbridge::testing::slurp;

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputSet, NothingIsVisibleBeforeCommitAndBothFilesAfter) {
  const fs::path dir = fresh_directory("commit");
  put(dir / "a.stp", "old a");
  {
    OutputSet outputs;
    OutputFile& a = outputs.add((dir / "a.stp").string(), "-o");
    OutputFile& b = outputs.add((dir / "b.json").string(), "--report");
    a.write("new a");
    b.write(std::string(300000, 'b'));  // past the buffer
    EXPECT_EQ(slurp(dir / "a.stp"), "old a");
    EXPECT_EQ(listing(dir), std::vector<std::string>{"a.stp"});  // the temporaries have no name
    outputs.commit();
    EXPECT_EQ(a.bytes_written(), 5u);
  }
  EXPECT_EQ(slurp(dir / "a.stp"), "new a");
  EXPECT_EQ(slurp(dir / "b.json"), std::string(300000, 'b'));
  EXPECT_EQ(listing(dir), (std::vector<std::string>{"a.stp", "b.json"}));
}

TEST(OutputSet, AnErrorBeforeCommitLeavesOldFilesAndNoTemporary) {
  const fs::path dir = fresh_directory("abandon");
  put(dir / "a.stp", "old a");
  {
    OutputSet outputs;
    outputs.add((dir / "a.stp").string(), "-o").write("new a");
    outputs.add((dir / "b.json").string(), "--report").write("b");
  }  // destroyed without commit: the run failed
  EXPECT_EQ(slurp(dir / "a.stp"), "old a");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"a.stp"});
}

TEST(OutputSet, AFailedRenameGivesTheFilesAlreadyRenamedTheirOldContentsBack) {
  const fs::path dir = fresh_directory("rollback");
  fs::create_directories(dir / "sub");
  put(dir / "a.stp", "old a");
  OutputSet outputs;
  outputs.add((dir / "a.stp").string(), "-o").write("new a");
  outputs.add((dir / "new.stp").string(), "--other").write("new file");
  outputs.add((dir / "sub" / "b.json").string(), "--report").write("b");
  fs::remove(dir / "sub");  // the last output's directory goes away after the check
  EXPECT_THROW(outputs.commit(), OutputError);
  EXPECT_EQ(slurp(dir / "a.stp"), "old a");
  EXPECT_EQ(listing(dir), std::vector<std::string>{"a.stp"});  // no new.stp, no backup, no temporary
}

TEST(OutputSet, ASymbolicLinkIsFollowedAndStays) {
  const fs::path dir = fresh_directory("symlink");
  put(dir / "real.stp", "old");
  fs::create_symlink("real.stp", dir / "link.stp");
  fs::create_symlink("link.stp", dir / "link2.stp");  // a chain
  fs::create_symlink("missing.stp", dir / "dangling.stp");
  OutputSet outputs;
  outputs.add((dir / "link2.stp").string(), "-o").write("new");
  outputs.add((dir / "dangling.stp").string(), "--report").write("created");
  outputs.commit();
  EXPECT_TRUE(fs::is_symlink(dir / "link.stp"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.stp"));
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.stp"));
  EXPECT_EQ(slurp(dir / "real.stp"), "new");
  EXPECT_EQ(slurp(dir / "missing.stp"), "created");
}

TEST(OutputSet, AReplacedFileKeepsItsPermissionsAndOwner) {
  const fs::path dir = fresh_directory("permissions");
  put(dir / "a.stp", "old");
  fs::permissions(dir / "a.stp", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // Root replacing someone else's file leaves it theirs.
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::chown((dir / "a.stp").c_str(), 4321, 4321), 0);
  }
  OutputSet outputs;
  outputs.add((dir / "a.stp").string(), "-o").write("new");
  outputs.commit();
  EXPECT_EQ(slurp(dir / "a.stp"), "new");
  EXPECT_EQ(fs::status(dir / "a.stp").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "a.stp").c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, root ? 4321u : ::geteuid());
  EXPECT_EQ(st.st_gid, root ? 4321u : st.st_gid);
}

TEST(OutputSet, DevNullIsWrittenNowhereAndStaysACharacterDevice) {
  OutputSet outputs;
  OutputFile& out = outputs.add("/dev/null", "-o");
  EXPECT_EQ(out.kind(), OutputFile::Kind::Discard);
  out.write("anything");
  outputs.commit();
  struct stat st {};
  ASSERT_EQ(::lstat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(OutputSet, ACharacterDeviceIsWrittenThroughAndItsErrorsReported) {
  // /dev/full: every write fails with ENOSPC. Written through, not replaced, and the error is
  // an OutputError; the other output of the run does not appear.
  const fs::path dir = fresh_directory("full");
  OutputSet outputs;
  OutputFile& out = outputs.add("/dev/full", "-o");
  EXPECT_EQ(out.kind(), OutputFile::Kind::Device);
  out.write("text");
  outputs.add((dir / "r.json").string(), "--report").write("{}");
  try {
    outputs.commit();
    FAIL() << "writing /dev/full succeeded";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(listing(dir).empty());
  struct stat st {};
  ASSERT_EQ(::lstat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(OutputSet, AFifoIsWrittenThrough) {
  const fs::path dir = fresh_directory("fifo");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  OutputSet outputs;
  OutputFile& out = outputs.add(fifo.string(), "-o");
  EXPECT_TRUE(out.is_stream());
  out.write("through the pipe");
  outputs.commit();
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(OutputSet, DirectoriesSocketsAndBlockDevicesAreRefusedBeforeAnythingIsWritten) {
  const fs::path dir = fresh_directory("refused");
  OutputSet outputs;
  EXPECT_THROW(outputs.add(dir.string(), "-o"), OutputError);
  EXPECT_THROW(outputs.add((dir / "no" / "such" / "dir" / "a.stp").string(), "-o"), OutputError);
  EXPECT_THROW(outputs.add("", "-o"), UsageError);

  const fs::path socket_path = dir / "sock";
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(s, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(socket_path.string().size(), sizeof address.sun_path);
  std::strcpy(address.sun_path, socket_path.c_str());
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  try {
    outputs.add(socket_path.string(), "-o");
    ADD_FAILURE() << "a socket was accepted";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("socket"), std::string::npos) << e.what();
  }
  ::close(s);

  EXPECT_TRUE(outputs.empty());
}

TEST(OutputSet, ABlockDeviceIsRefusedFromItsTypeAlone) {
  std::optional<fs::path> block;  // any in /dev: nothing is opened, the type refuses it
  for (const auto& e : fs::directory_iterator("/dev")) {
    if (e.is_block_file()) {
      block = e.path();
      break;
    }
  }
  if (!block) GTEST_SKIP() << "no block device in /dev on this machine";
  const fs::path dir = fresh_directory("block");
  fs::create_symlink(*block, dir / "disk.stp");  // also through a link
  OutputSet outputs;
  for (const fs::path& p : {*block, dir / "disk.stp"}) {
    try {
      outputs.add(p.string(), "-o");
      ADD_FAILURE() << "a block device was accepted: " << p;
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find("block device"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(outputs.empty());
}

TEST(OutputSet, AReadOnlyDirectoryOrFileIsRefusedWhenChecked) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes anywhere: permission bits cannot refuse it";
  const fs::path dir = fresh_directory("read_only");
  fs::create_directories(dir / "locked");
  fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
  put(dir / "ro.stp", "keep");
  fs::permissions(dir / "ro.stp", fs::perms::owner_read);
  OutputSet outputs;
  EXPECT_THROW(outputs.add((dir / "locked" / "a.stp").string(), "-o"), OutputError);
  EXPECT_THROW(outputs.add((dir / "ro.stp").string(), "-o"), OutputError);
  fs::permissions(dir / "locked", fs::perms::owner_all);
}

TEST(OutputSet, TwoOutputsToOnePlaceOrAnOutputThatIsAnInputAreUsageErrors) {
  const fs::path dir = fresh_directory("same");
  put(dir / "program.ngc", "G0 X1\nM2\n");
  fs::create_symlink("a.stp", dir / "alias.stp");
  OutputSet outputs;
  outputs.add((dir / "a.stp").string(), "-o");
  EXPECT_THROW(outputs.add((dir / "a.stp").string(), "--report"), UsageError);
  EXPECT_THROW(outputs.add((dir / "." / "alias.stp").string(), "--report"), UsageError);
  outputs.add("-", "--html");
  EXPECT_THROW(outputs.add("/dev/stdout", "--report"), UsageError);  // standard output twice
  outputs.add("/dev/null", "--a");
  outputs.add("/dev/null", "--b");  // discarding twice is fine
  OutputSet run;
  run.add((dir / "program.ngc").string(), "-o");
  EXPECT_THROW(run.protect(dir / "program.ngc"), UsageError);
  OutputSet later;
  later.protect(dir / "program.ngc");
  EXPECT_THROW(later.add((dir / "program.ngc").string(), "-o"), UsageError);
  EXPECT_EQ(slurp(dir / "program.ngc"), "G0 X1\nM2\n");
}

TEST(OutputSet, OutputDirectoryIsCreatedWhenMissing) {
  const fs::path dir = fresh_directory("output_dir");
  EXPECT_EQ(prepare_output_directory((dir / "a" / "b").string(), "--output-dir"), dir / "a" / "b");
  EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
  EXPECT_NO_THROW(prepare_output_directory((dir / "a" / "b").string(), "--output-dir"));  // exists: fine
  put(dir / "file", "x");
  EXPECT_THROW(prepare_output_directory((dir / "file").string(), "--output-dir"), OutputError);
}

}  // namespace
}  // namespace ncbridge::cli
