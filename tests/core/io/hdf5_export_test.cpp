// The HDF5 export's error paths (hdf5_export.h): every failure is a Status
// with words, never a crash, an HDF5 stack dump or a partial OUT.h5; and the
// SHA-256 it states is the standard one. The values themselves are checked
// against the CSV export by tests/hdf5 (h5py).

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include <sys/resource.h>

#include "core/common/sha256.h"
#include "core/io/hdf5_export.h"
#include "io_test_util.h"

namespace fog::io {
namespace {

namespace fs = std::filesystem;
using testing::freshDir;

// A recording the exporter accepts (a pulse equivalent, one test point).
Recording smallRecording(std::size_t samples) {
  Recording rec;
  rec.pulseEquivalentDeg = 1e-6;
  TestPointData p;
  p.nominalFrequencyHz = 1.0;
  p.nominalAmplitudeDeg = 3.0;
  for (std::size_t i = 0; i < samples; ++i) {
    p.table.push_back({0.001 * static_cast<double>(i), {0.5, 0.25, 0.125}});
    p.imu.push_back({0.001 * static_cast<double>(i), {1e-6, 2e-6, 3e-6}, 25.0, 0});
  }
  rec.testPoints.push_back(p);
  return rec;
}

bool anyPartial(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".partial") return true;
  return false;
}

TEST(Hdf5Export, AMissingFolderIsAClearIoError) {
  const std::string dir = freshDir();
  const SessionInfo info;
  const Recording rec = smallRecording(10);
  Hdf5ExportInput in;
  in.info = &info;
  in.recording = &rec;
  const std::string path = dir + "/no/such/folder/out.h5";
  const Status s = exportHdf5(path, in, false);
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_NE(s.message().find("cannot create"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("no/such/folder"), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(path));
}

TEST(Hdf5Export, AnExistingFileIsReplacedOnlyWhenAllowed) {
  const std::string dir = freshDir();
  const SessionInfo info;
  const Recording rec = smallRecording(10);
  Hdf5ExportInput in;
  in.info = &info;
  in.recording = &rec;
  const std::string path = dir + "/out.h5";
  std::ofstream(path) << "not ours";
  const Status refused = exportHdf5(path, in, false);
  EXPECT_EQ(refused.code(), StatusCode::kInvalidArgument) << refused.message();
  EXPECT_NE(refused.message().find("already exists"), std::string::npos) << refused.message();
  EXPECT_EQ(fs::file_size(path), 8u);  // untouched
  const Status replaced = exportHdf5(path, in, true);
  EXPECT_TRUE(replaced.isOk()) << replaced.message();
  EXPECT_GT(fs::file_size(path), 8u);
  EXPECT_FALSE(anyPartial(dir));
  EXPECT_EQ(exportHdf5(dir, in, true).code(), StatusCode::kInvalidArgument);  // a folder is never the file
}

// A file already named like the temporary file is not the export's: it is
// left as it was, and the export uses the next free name.
TEST(Hdf5Export, AForeignPartialFileIsNeverTruncated) {
  const std::string dir = freshDir();
  const SessionInfo info;
  const Recording rec = smallRecording(10);
  Hdf5ExportInput in;
  in.info = &info;
  in.recording = &rec;
  const std::string path = dir + "/out.h5";
  std::ofstream(path + ".partial") << "someone's";
  const Status s = exportHdf5(path, in, false);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_GT(fs::file_size(path), 0u);
  EXPECT_EQ(fs::file_size(path + ".partial"), 9u);
  EXPECT_FALSE(fs::exists(path + ".1.partial"));
}

// A file size limit (RLIMIT_FSIZE, SIGXFSZ ignored) makes writes fail with
// EFBIG the way a full disk fails them with ENOSPC: the failure must come back
// as a kIoError with words, the partial file must be gone, and the process
// must live on (HDF5 1.10 crashed at exit after a failed write of its own,
// which is why the file is built in memory: hdf5_export.cpp).
TEST(Hdf5Export, AWriteThatFailsMidwayLeavesNoFile) {
  const std::string dir = freshDir();
  const SessionInfo info;
  const Recording rec = smallRecording(200000);  // ~10 MB of datasets
  Hdf5ExportInput in;
  in.info = &info;
  in.recording = &rec;
  const std::string path = dir + "/out.h5";
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 64 * 1024;
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const Status s = exportHdf5(path, in, false);
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, oldHandler);
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_NE(s.message().find("could not write all of"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("disk full?"), std::string::npos) << s.message();
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(anyPartial(dir));
}

TEST(Hdf5Export, Sha256IsFips180) {
  const std::string dir = freshDir();
  auto hash = [&](const std::string& text) {
    const std::string p = dir + "/f";
    std::ofstream(p, std::ios::binary) << text;
    auto r = sha256OfFile(p);
    EXPECT_TRUE(r.isOk());
    return r.isOk() ? r.value() : std::string();
  };
  // FIPS 180-2 appendix B examples and the empty message.
  EXPECT_EQ(hash(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(hash("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(hash("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(hash(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_FALSE(sha256OfFile(dir + "/missing").isOk());
}

}  // namespace
}  // namespace fog::io
