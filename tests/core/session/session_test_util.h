#pragma once
// Shared by the session tests: a scratch folder per test, a short simulated
// run, and exact comparison of recordings.

#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

#include <sqlite3.h>

#include "core/common/recording.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace fog::test {

// A fresh, empty folder for the running test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("fog_session_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// 1 Hz / 3 deg on Z for 8 s after 2 s of settling (so the stream also holds
// frames outside the recording phase): about 0.4 MB of raw stream.
inline TestPlan shortPlan() {
  TestPoint p;
  p.axis = Axis::kZ;
  p.frequencyHz = 1.0;
  p.amplitudeDeg = 3.0;
  p.durationS = 8.0;
  p.settleS = 2.0;
  TestPlan plan;
  plan.points.push_back(p);
  return plan;
}

inline const model::SimulatedRun& shortRun() {
  static const model::SimulatedRun run = [] {
    model::SimConfig c;
    c.seed = 3;
    auto r = model::simulate(c, shortPlan());
    EXPECT_TRUE(r.isOk()) << r.status().message();
    return std::move(r).value();
  }();
  return run;
}

inline bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Every field, doubles compared bit for bit.
inline void expectSameRecording(const Recording& a, const Recording& b) {
  EXPECT_TRUE(sameBits(a.counterHz, b.counterHz));
  EXPECT_EQ(a.counterBits, b.counterBits);
  EXPECT_TRUE(sameBits(a.pulseEquivalentDeg, b.pulseEquivalentDeg));
  EXPECT_EQ(a.health.tableFrames, b.health.tableFrames);
  EXPECT_EQ(a.health.imuFrames, b.health.imuFrames);
  EXPECT_EQ(a.health.statusFrames, b.health.statusFrames);
  EXPECT_EQ(a.health.checksumFailures, b.health.checksumFailures);
  EXPECT_EQ(a.health.bytesSkipped, b.health.bytesSkipped);
  EXPECT_EQ(a.health.lostFrames, b.health.lostFrames);
  EXPECT_EQ(a.health.duplicateFrames, b.health.duplicateFrames);
  EXPECT_EQ(a.health.outOfOrderFrames, b.health.outOfOrderFrames);
  EXPECT_EQ(a.health.counterWraps, b.health.counterWraps);
  ASSERT_EQ(a.testPoints.size(), b.testPoints.size());
  for (std::size_t p = 0; p < a.testPoints.size(); ++p) {
    const auto& x = a.testPoints[p];
    const auto& y = b.testPoints[p];
    EXPECT_EQ(x.index, y.index);
    EXPECT_EQ(x.axis, y.axis);
    EXPECT_TRUE(sameBits(x.nominalFrequencyHz, y.nominalFrequencyHz));
    EXPECT_TRUE(sameBits(x.nominalAmplitudeDeg, y.nominalAmplitudeDeg));
    ASSERT_EQ(x.table.size(), y.table.size());
    ASSERT_EQ(x.imu.size(), y.imu.size());
    std::size_t tableDiff = 0, imuDiff = 0;
    for (std::size_t i = 0; i < x.table.size(); ++i) {
      bool same = sameBits(x.table[i].timeS, y.table[i].timeS);
      for (std::size_t k = 0; k < 3; ++k) same = same && sameBits(x.table[i].angleDeg[k], y.table[i].angleDeg[k]);
      tableDiff += !same;
    }
    for (std::size_t i = 0; i < x.imu.size(); ++i) {
      bool same = sameBits(x.imu[i].timeS, y.imu[i].timeS) && sameBits(x.imu[i].temperatureC, y.imu[i].temperatureC) &&
                  x.imu[i].lostBefore == y.imu[i].lostBefore;
      for (std::size_t k = 0; k < 3; ++k)
        same = same && sameBits(x.imu[i].incrementDeg[k], y.imu[i].incrementDeg[k]);
      imuDiff += !same;
    }
    EXPECT_EQ(tableDiff, 0u) << "table samples differ in test point " << p;
    EXPECT_EQ(imuDiff, 0u) << "IMU samples differ in test point " << p;
  }
}

inline std::vector<std::uint8_t> readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeFile(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// A finished session of shortRun() with its decoded samples stored, as a
// run --out leaves it; `complete` false marks it stopped by the operator.
inline std::string recordedSession(const ScratchDir& dir, const std::string& name, const SessionInfo& info = {},
                                   bool complete = true) {
  const std::string path = dir.file(name);
  auto w = session::SessionWriter::create(path, info);
  EXPECT_TRUE(w.isOk()) << w.status().message();
  const auto& bytes = shortRun().bytes;
  EXPECT_TRUE((*w)->appendRaw(bytes.data(), bytes.size()).isOk());
  auto rec = protocol::decodeRecording(bytes);
  EXPECT_TRUE(rec.isOk());
  EXPECT_TRUE((*w)->storeRecording(*rec).isOk());
  EXPECT_TRUE((*w)->finish(complete, complete ? "" : "stopped by the operator").isOk());
  return path;
}

// Edits a session behind the reader's back (SQLite and the blob checksums
// stay valid unless `sql` changes them), as a crafted or damaged file would.
inline void runSql(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  char* err = nullptr;
  EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "");
  sqlite3_free(err);
  sqlite3_close(db);
}

}  // namespace fog::test
