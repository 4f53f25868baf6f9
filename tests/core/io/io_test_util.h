#pragma once
// Temporary directories and small files for the import/export tests.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fog::io::testing {

// This process's scratch directory under gtest's temp dir (two build trees
// may run the same test at once). Removed at exit when every test passed,
// kept as evidence otherwise.
inline std::filesystem::path scratchRoot() {
  return std::filesystem::path(::testing::TempDir()) / ("fog_io." + std::to_string(::getpid()));
}

class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Failed()) std::filesystem::remove_all(scratchRoot());
  }
};
inline ::testing::Environment* const kScratchCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

// A fresh, empty directory in the scratch directory, named after the test.
inline std::string freshDir(const std::string& suffix = "") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      scratchRoot() / (std::string(info->test_suite_name()) + "." + info->name() + suffix);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline void writeText(const std::string& dir, const std::string& name, const std::string& text) {
  std::ofstream out(std::filesystem::path(dir) / name, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << name << " in " << dir;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace fog::io::testing
