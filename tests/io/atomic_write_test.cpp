// Atomic writes: the file is replaced whole or not at all, and no temporary is left.
#include "shpack/io/atomic_write.h"

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

TEST(AtomicWrite, FailedRenameKeepsTheTargetAndRemovesTheTemporary) {
  // A folder in the way: the temporary is written, the rename fails, the folder and its
  // contents stay as they were, and the temporary is gone.
  const ScratchDir dir;
  std::filesystem::create_directory(dir / "out.json");
  shpack_io_test::write_bytes(dir / "out.json" / "keep.txt", {'k'});
  const IoStatus st = write_file_atomically(dir / "out.json", "{}");
  EXPECT_EQ(st.code, IoErrc::WriteFailed);
  EXPECT_EQ(st.message.find('\n'), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "out.json"));
  EXPECT_EQ(text_of(dir / "out.json" / "keep.txt"), "k");
  EXPECT_TRUE(extra_files(dir.path(), "out.json").empty());
}

}  // namespace
}  // namespace shpack::io
