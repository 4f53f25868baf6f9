// Input files are read in bounded time and memory: only regular files, their
// size checked before a byte is read.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/common/file_read.h"

namespace fog {
namespace {

namespace fs = std::filesystem;

class FileRead : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fog-file-read-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(FileRead, ARegularFileWithinItsBoundIsReadWhole) {
  std::ofstream(path("a.bin"), std::ios::binary) << "abc\0def";
  auto bytes = readRegularFile(path("a.bin"), 3, "a test file");
  ASSERT_TRUE(bytes.isOk()) << bytes.status().toString();
  EXPECT_EQ(bytes->size(), 3u);
  auto text = readRegularTextFile(path("a.bin"), 3, "a test file");
  ASSERT_TRUE(text.isOk());
  EXPECT_EQ(*text, "abc");
}

TEST_F(FileRead, AFileBeyondItsBoundIsRefusedBeforeItIsRead) {
  std::ofstream(path("big.bin"), std::ios::binary) << std::string(5000, 'x');
  auto r = readRegularFile(path("big.bin"), 4096, "a test file");
  ASSERT_FALSE(r.isOk());
  EXPECT_NE(r.status().message().find("holds 5000 bytes, more than the 4 KiB that a test file may hold"),
            std::string::npos)
      << r.status().message();
}

// /dev/zero and /dev/urandom (behind a link named like a session) were read
// until bad_alloc at 2.15 GB; a FIFO hung the reader.
TEST_F(FileRead, ADeviceOrAFifoIsRefusedWithoutReadingIt) {
  fs::create_symlink("/dev/zero", path("zero.fbs"));
  auto zero = readRegularFile(path("zero.fbs"), 1u << 20, "a raw stream");
  ASSERT_FALSE(zero.isOk());
  EXPECT_NE(zero.status().message().find("zero.fbs (a link to /dev/zero) is a device, not a raw stream"),
            std::string::npos)
      << zero.status().message();
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0600), 0);
  auto fifo = readRegularFile(path("pipe"), 1u << 20, "a raw stream");  // would block if it were opened
  ASSERT_FALSE(fifo.isOk());
  EXPECT_NE(fifo.status().message().find("is a FIFO (named pipe), not a raw stream"), std::string::npos);
  auto folder = readRegularFile(dir_.string(), 1u << 20, "a raw stream");
  ASSERT_FALSE(folder.isOk());
  EXPECT_NE(folder.status().message().find("is a folder"), std::string::npos);
  auto missing = readRegularFile(path("none"), 1u << 20, "a raw stream");
  ASSERT_FALSE(missing.isOk());
  EXPECT_EQ(missing.status().code(), StatusCode::kIoError);
  EXPECT_NE(missing.status().message().find("does not exist"), std::string::npos);
}

TEST(ByteCount, WritesWholeUnits) {
  EXPECT_EQ(byteCount(512ull << 20), "512 MiB");
  EXPECT_EQ(byteCount(4096), "4 KiB");
  EXPECT_EQ(byteCount(1000), "1000 bytes");
}

}  // namespace
}  // namespace fog
