// Atomic writes: the file is replaced whole or not at all, no temporary is left, and no
// planted file or link can redirect or stall the write (atomic_write.h).
#include "shpack/io/atomic_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>

#include "io_test_files.h"

namespace shpack::io {
namespace {

using shpack_io_test::read_bytes;
using shpack_io_test::ScratchDir;

std::string text_of(const std::filesystem::path& path) {
  const std::vector<char> bytes = read_bytes(path);
  return {bytes.begin(), bytes.end()};
}

// The folder's entries other than `expected`: leftover temporaries.
std::vector<std::string> extra_files(const std::filesystem::path& dir, const std::string& expected) {
  std::vector<std::string> extra;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename() != expected) extra.push_back(entry.path().filename().string());
  return extra;
}

TEST(AtomicWrite, CreatesTheFile) {
  const ScratchDir dir;
  const IoStatus st = write_file_atomically(dir / "out.json", "{}\n");
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(text_of(dir / "out.json"), "{}\n");
  EXPECT_TRUE(extra_files(dir.path(), "out.json").empty());
}

TEST(AtomicWrite, ReplacesAnExistingFile) {
  const ScratchDir dir;
  ASSERT_TRUE(write_file_atomically(dir / "out.json", "old, and longer than the new text").ok());
  ASSERT_TRUE(write_file_atomically(dir / "out.json", "new").ok());
  EXPECT_EQ(text_of(dir / "out.json"), "new");
  EXPECT_TRUE(extra_files(dir.path(), "out.json").empty());
}

TEST(AtomicWrite, MissingFolderFailsWithoutTrace) {
  const ScratchDir dir;
  const IoStatus st = write_file_atomically(dir / "no" / "out.json", "{}");
  EXPECT_EQ(st.code, IoErrc::WriteFailed);
  EXPECT_EQ(st.message.rfind((dir / "no" / "out.json").string() + ": cannot create ", 0), 0u) << st.message;
  EXPECT_TRUE(extra_files(dir.path(), "").empty());
}

TEST(AtomicWrite, DirectoryTargetIsRefusedAndKept) {
  // A folder in the way: an error naming it, the folder and its contents as they were, and
  // no temporary.
  const ScratchDir dir;
  std::filesystem::create_directory(dir / "out.json");
  shpack_io_test::write_bytes(dir / "out.json" / "keep.txt", {'k'});
  const IoStatus st = write_file_atomically(dir / "out.json", "{}");
  EXPECT_EQ(st.code, IoErrc::WriteFailed);
  EXPECT_EQ(st.message, (dir / "out.json").string() + ": is a directory");
  EXPECT_TRUE(std::filesystem::is_directory(dir / "out.json"));
  EXPECT_EQ(text_of(dir / "out.json" / "keep.txt"), "k");
  EXPECT_TRUE(extra_files(dir.path(), "out.json").empty());
}

// The temporary the old writer used: "<path>.tmp.<pid>", opened with fopen("wb").
std::filesystem::path old_temporary(const std::filesystem::path& path) {
  std::filesystem::path temp = path;
  return temp += ".tmp." + std::to_string(::getpid());
}

TEST(AtomicWrite, PlantedLinkAtAPredictableTemporaryIsNotFollowed) {
  // Someone who can write the folder plants a link where the temporary used to go; a write
  // (as root, say) must not go through it onto the file it points to.
  const ScratchDir dir;
  shpack_io_test::write_bytes(dir / "victim.txt", {'v'});
  std::filesystem::create_symlink(dir / "victim.txt", old_temporary(dir / "out.json"));
  const IoStatus st = write_file_atomically(dir / "out.json", "new");
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(text_of(dir / "victim.txt"), "v");
  EXPECT_EQ(text_of(dir / "out.json"), "new");
  EXPECT_TRUE(std::filesystem::is_symlink(old_temporary(dir / "out.json")));  // not ours: left alone
}

TEST(AtomicWrite, PlantedFifoAtAPredictableTemporaryDoesNotStallTheWrite) {
  // Opening a FIFO for writing waits for a reader: forever. The write runs in a child,
  // which must be done within 20 s.
  const ScratchDir dir;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::mkfifo(old_temporary(dir / "out.json").c_str(), 0600) != 0) _exit(2);  // the child's pid
    ::alarm(20);  // the stall ends the child with SIGALRM
    _exit(write_file_atomically(dir / "out.json", "new").ok() ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the write stalled on the planted FIFO";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(text_of(dir / "out.json"), "new");
}

TEST(AtomicWrite, KeepsTheModeOfTheReplacedFile) {
  const ScratchDir dir;
  ASSERT_TRUE(write_file_atomically(dir / "out.json", "old").ok());
  ASSERT_EQ(::chmod((dir / "out.json").c_str(), 0640), 0);
  ASSERT_TRUE(write_file_atomically(dir / "out.json", "new").ok());
  struct stat st {};
  ASSERT_EQ(::stat((dir / "out.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);
  EXPECT_EQ(text_of(dir / "out.json"), "new");
}

TEST(AtomicWrite, NewFileGetsTheUmaskMode) {
  const ScratchDir dir;
  const mode_t mask = ::umask(022);
  ::umask(mask);
  ASSERT_TRUE(write_file_atomically(dir / "out.json", "new").ok());
  struct stat st {};
  ASSERT_EQ(::stat((dir / "out.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0666u & ~mask);
}

TEST(AtomicWrite, ALinkTargetReplacesTheLinkItself) {
  // The documented rule: the link becomes the new regular file; the file it pointed to keeps
  // its contents (a link planted in a shared folder cannot aim the write elsewhere).
  const ScratchDir dir;
  shpack_io_test::write_bytes(dir / "real.json", {'k'});
  std::filesystem::create_symlink(dir / "real.json", dir / "link.json");
  ASSERT_TRUE(write_file_atomically(dir / "link.json", "new").ok());
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "link.json"));
  EXPECT_EQ(text_of(dir / "link.json"), "new");
  EXPECT_EQ(text_of(dir / "real.json"), "k");
}

TEST(AtomicWrite, AFifoTargetIsWrittenInPlace) {
  const ScratchDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const int reader = ::open((dir / "pipe").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const IoStatus st = write_file_atomically(dir / "pipe", "through the pipe");
  ASSERT_TRUE(st.ok()) << st.message;
  char buffer[64] = {};
  EXPECT_EQ(::read(reader, buffer, sizeof buffer), 16);
  ::close(reader);
  EXPECT_EQ(std::string(buffer), "through the pipe");
  struct stat after {};
  ASSERT_EQ(::lstat((dir / "pipe").c_str(), &after), 0);
  EXPECT_TRUE(S_ISFIFO(after.st_mode)) << "the FIFO was replaced by a file";
  EXPECT_TRUE(extra_files(dir.path(), "pipe").empty());
}

TEST(AtomicWrite, DescriptorNames) {
  EXPECT_EQ(output_descriptor("-"), 1);
  EXPECT_EQ(output_descriptor("/dev/stdout"), 1);
  EXPECT_EQ(output_descriptor("/dev/stderr"), 2);
  EXPECT_EQ(output_descriptor("/dev/fd/7"), 7);
  EXPECT_EQ(output_descriptor("/proc/self/fd/3"), 3);
  EXPECT_EQ(output_descriptor("./-"), -1);
  EXPECT_EQ(output_descriptor("/dev/fd/x"), -1);
  EXPECT_EQ(output_descriptor("out.json"), -1);
}

}  // namespace
}  // namespace shpack::io
