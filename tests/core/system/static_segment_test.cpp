// Static segments (table at rest) end to end: the simulator holds the table
// and emits them as test points, the decoder delivers them with their kind,
// the delay analysis skips them without calling them failures, and session
// files and the CSV layout keep them.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/common/units.h"
#include "core/io/csv_export.h"
#include "core/io/csv_import.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace fog {
namespace {

// Static on Z for 30 s, a 1 Hz / 3 deg swing on Z, static on X for 10 s.
TestPlan mixedPlan() {
  TestPlan plan;
  plan.points.push_back(TestPoint::staticSegment(Axis::kZ, 30.0, 1.0));
  plan.points.push_back({Axis::kZ, 1.0, 3.0, 6.0, 1.0, 0.0});
  plan.points.push_back(TestPoint::staticSegment(Axis::kX, 10.0));
  return plan;
}

model::SimConfig quietBiasConfig() {
  model::SimConfig c;
  c.seed = 9;
  c.fog.biasInstabilityDegPerH = 0.0;  // the mean rate is then bias + Earth rate + ARW only
  return c;
}

struct Decoded {
  model::SimulatedRun run;
  Recording rec;
};

const Decoded& decoded() {
  static const Decoded d = [] {
    auto run = model::simulate(quietBiasConfig(), mixedPlan());
    EXPECT_TRUE(run.isOk()) << run.status().toString();
    auto rec = protocol::decodeRecording(run->bytes);
    EXPECT_TRUE(rec.isOk()) << rec.status().toString();
    return Decoded{*run, *rec};
  }();
  return d;
}

TEST(StaticSegment, SimulatorHoldsTheTableAndTheGyroSeesBiasAndEarthRate) {
  const Recording& rec = decoded().rec;
  ASSERT_EQ(rec.testPoints.size(), 3u);
  EXPECT_EQ(rec.testPoints[0].kind, TestPointKind::kStatic);
  EXPECT_EQ(rec.testPoints[1].kind, TestPointKind::kSwing);
  EXPECT_EQ(rec.testPoints[2].kind, TestPointKind::kStatic);
  EXPECT_EQ(rec.testPoints[0].nominalFrequencyHz, 0.0);
  EXPECT_EQ(rec.testPoints[0].nominalAmplitudeDeg, 0.0);
  const auto& st = rec.testPoints[0];
  // 30 s at 1 kHz table / 500 Hz IMU (frame edges: +-1).
  EXPECT_NEAR(static_cast<double>(st.table.size()), 30000.0, 2.0);
  EXPECT_NEAR(static_cast<double>(st.imu.size()), 15000.0, 2.0);
  for (const auto& t : st.table)
    for (int a = 0; a < kAxisCount; ++a) ASSERT_EQ(t.angleDeg[static_cast<std::size_t>(a)], 0.0);
  // The table after the swing holds still too (exactly, to the encoder's micro-degree).
  const auto& last = rec.testPoints[2].table;
  for (const auto& t : last) ASSERT_EQ(t.angleDeg, last.front().angleDeg);
  // Mean Z rate = bias 0.15 deg/h + Earth -15.041067 sin 40 deg (z down); ARW 0.004
  // deg/sqrt(h) over 30 s leaves 0.044 deg/h (1 sigma): 5 sigma allowed.
  double sum = 0.0;
  for (const auto& s : st.imu) sum += s.incrementDeg[2];
  const double rateDegPerH = sum / (st.imu.back().timeS - st.imu.front().timeS + 2e-3) * 3600.0;
  const double expected = 0.15 - kEarthRateDegPerH * std::sin(40.0 * kRadPerDeg);
  EXPECT_NEAR(rateDegPerH, expected, 0.22);
}

TEST(StaticSegment, DelayAnalysisSkipsStaticSegmentsWithoutFailures) {
  auto report = analysis::analyzeRecording(decoded().rec, BenchConstants{});
  ASSERT_TRUE(report.isOk()) << report.status().toString();
  ASSERT_EQ(report->points.size(), 1u);
  EXPECT_EQ(report->points[0].index, 1);
  EXPECT_TRUE(report->failedPoints.empty());
  ASSERT_EQ(report->staticSegments.size(), 2u);
  EXPECT_EQ(report->staticSegments[0].axis, Axis::kZ);
  EXPECT_NEAR(report->staticSegments[0].durationS, 30.0, 0.01);
  const std::string text = analysis::formatReportText(*report, {});
  EXPECT_NE(text.find("Test point 1: static segment, Z axis"), std::string::npos) << text;
  EXPECT_EQ(text.find("no delay from"), std::string::npos) << text;
  const auto json = nlohmann::json::parse(analysis::formatReportJson(*report, {}));
  EXPECT_EQ(json.at("static_segments").size(), 2u);
  EXPECT_EQ(json.at("failed_points").size(), 0u);
  EXPECT_EQ(json.at("test_points").size(), 1u);
}

TEST(StaticSegment, OnlyStaticSegmentsSayUseTheNoiseCommand) {
  TestPlan plan;
  plan.points.push_back(TestPoint::staticSegment(Axis::kX, 5.0));
  auto run = model::simulate(quietBiasConfig(), plan);
  ASSERT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();
  auto report = analysis::analyzeRecording(*rec, BenchConstants{});
  ASSERT_FALSE(report.isOk());
  EXPECT_EQ(report.status().code(), StatusCode::kInsufficientData);
  EXPECT_NE(report.status().message().find("fogbench-cli noise"), std::string::npos);
}

std::filesystem::path scratch(const std::string& name) {
  auto p = std::filesystem::temp_directory_path() / ("fog_static_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  return p;
}

TEST(StaticSegment, SessionFileKeepsTheKindInPlanAndStoredSamples) {
  const auto dir = scratch("session");
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "s.fbs").string();
  SessionInfo info;
  info.plan = mixedPlan();
  {
    auto w = session::SessionWriter::create(path, info);
    ASSERT_TRUE(w.isOk()) << w.status().toString();
    const auto& bytes = decoded().run.bytes;
    ASSERT_TRUE((*w)->appendRaw(bytes.data(), bytes.size()).isOk());
    ASSERT_TRUE((*w)->storeRecording(decoded().rec).isOk());
    ASSERT_TRUE((*w)->finish(true, "").isOk());
  }
  auto r = session::SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().toString();
  ASSERT_EQ((*r)->info().plan.points.size(), 3u);
  EXPECT_EQ((*r)->info().plan.points[0].kind, TestPointKind::kStatic);
  EXPECT_EQ((*r)->info().plan.points[1].kind, TestPointKind::kSwing);
  EXPECT_EQ((*r)->schemaVersion(), session::kSchemaVersion);  // static segments bumped nothing
  ASSERT_TRUE((*r)->hasStoredRecording());
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk());
  ASSERT_EQ(rec->testPoints.size(), 3u);
  EXPECT_EQ(rec->testPoints[0].kind, TestPointKind::kStatic);
  EXPECT_EQ(rec->testPoints[1].kind, TestPointKind::kSwing);
  EXPECT_EQ(rec->testPoints[2].kind, TestPointKind::kStatic);
  std::filesystem::remove_all(dir);
}

TEST(StaticSegment, CsvExportAndImportKeepTheKind) {
  const auto dir = scratch("csv");
  SessionInfo info;
  info.plan = mixedPlan();
  auto report = analysis::analyzeRecording(decoded().rec, info.bench);
  ASSERT_TRUE(report.isOk());
  ASSERT_TRUE(io::exportCsv(dir.string(), info, decoded().rec, &*report, true).isOk());
  auto back = io::importCsvDirectory(dir.string());
  ASSERT_TRUE(back.isOk()) << back.status().toString();
  ASSERT_EQ(back->info.plan.points.size(), 3u);
  EXPECT_EQ(back->info.plan.points[0].kind, TestPointKind::kStatic);
  EXPECT_EQ(back->info.plan.points[1].kind, TestPointKind::kSwing);
  EXPECT_EQ(back->info.plan.points[2].kind, TestPointKind::kStatic);
  ASSERT_EQ(back->recording.testPoints.size(), 3u);
  EXPECT_EQ(back->recording.testPoints[0].kind, TestPointKind::kStatic);
  EXPECT_EQ(back->recording.testPoints[1].kind, TestPointKind::kSwing);
  auto again = analysis::analyzeRecording(back->recording, back->info.bench);
  ASSERT_TRUE(again.isOk()) << again.status().toString();
  EXPECT_EQ(again->staticSegments.size(), 2u);
  EXPECT_EQ(again->points[0].lagMs, report->points[0].lagMs);  // bit for bit
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fog
