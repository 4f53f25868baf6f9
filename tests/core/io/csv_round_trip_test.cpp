// Export -> import -> analyse reproduces the original analysis of a simulated
// session to the last printed digit (in fact bit for bit: every number is
// written as its shortest round-trip text), for the paper's two conditions.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/io/csv_export.h"
#include "core/io/csv_import.h"
#include "io_test_util.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::io {
namespace {

using testing::freshDir;
using testing::readText;

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::string field;
    std::istringstream l(line);
    while (std::getline(l, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

void roundTrip(const model::SimConfig& config, const TestPlan& plan) {
  auto run = model::simulate(config, plan);
  ASSERT_TRUE(run.isOk()) << run.status().toString();
  auto rec = protocol::decodeRecording(run->bytes);
  ASSERT_TRUE(rec.isOk()) << rec.status().toString();

  SessionInfo info;
  info.operatorName = "J. Doe";
  info.imuModel = "FOG-IMU 3";
  info.imuSerial = "0042";
  info.source = "simulator, seed " + std::to_string(config.seed);
  info.softwareVersion = "test";
  info.createdUtc = "2026-11-22T02:45:00Z";
  info.notes = "round trip, \"quoted\" and, commas";
  info.plan = plan;
  const auto constants = info.bench;
  auto original = analysis::analyzeRecording(*rec, constants);
  ASSERT_TRUE(original.isOk()) << original.status().toString();

  const std::string dir = freshDir();
  const Status exported = exportCsv(dir, info, *rec, &*original, /*overwrite=*/true);
  ASSERT_TRUE(exported.isOk()) << exported.toString();

  auto imported = importCsvDirectory(dir);
  ASSERT_TRUE(imported.isOk()) << imported.status().toString();
  const SessionInfo& back = imported->info;
  EXPECT_EQ(back.operatorName, info.operatorName);
  EXPECT_EQ(back.imuModel, info.imuModel);
  EXPECT_EQ(back.imuSerial, info.imuSerial);
  EXPECT_EQ(back.createdUtc, info.createdUtc);
  EXPECT_EQ(back.notes, info.notes);
  EXPECT_NE(back.source.find(info.source), std::string::npos) << back.source;
  ASSERT_EQ(back.plan.points.size(), plan.points.size());
  EXPECT_EQ(back.plan.points[0].durationS, plan.points[0].durationS);
  // The plan's frequency comes back as the data states it: the sampling
  // board carries it in micro-hertz.
  EXPECT_NEAR(back.plan.points[0].frequencyHz, plan.points[0].frequencyHz, 1e-6);
  EXPECT_EQ(imported->recording.testPoints[0].nominalFrequencyHz, rec->testPoints[0].nominalFrequencyHz);
  EXPECT_EQ(back.bench.boardDelayMs, info.bench.boardDelayMs);
  EXPECT_EQ(imported->recording.health.imuFrames, rec->health.imuFrames);

  auto again = analysis::analyzeRecording(imported->recording, back.bench);
  ASSERT_TRUE(again.isOk()) << again.status().toString();

  // The text report, every printed digit, with the same context.
  analysis::ReportContext context;
  context.source = info.source;
  for (const auto& t : run->truth) context.trueLagMs.push_back(t.lagS * 1e3);
  const std::string before = analysis::formatReportText(*original, context);
  EXPECT_EQ(analysis::formatReportText(*again, context), before);
  EXPECT_EQ(analysis::formatReportJson(*again, context), analysis::formatReportJson(*original, context));
  ASSERT_EQ(again->points.size(), original->points.size());
  const auto& p = original->points[0];
  EXPECT_EQ(again->points[0].lagMs, p.lagMs);  // bit for bit
  EXPECT_NE(before.find("measured lag"), std::string::npos);

  // report.json is formatReportJson with the session's source.
  analysis::ReportContext exportContext;
  exportContext.source = info.source;
  EXPECT_EQ(readText(dir + "/report.json"), analysis::formatReportJson(*original, exportContext));

  // fits.csv: five fits per test point; the joint row's lag is the report's.
  const auto fits = csvRows(readText(dir + "/fits.csv"));
  ASSERT_EQ(fits.size(), 1u + 5u * original->points.size());
  ASSERT_EQ(fits[0].size(), 21u);
  EXPECT_EQ(fits[0][17], "lag_ms");
  for (std::size_t r = 1; r < fits.size(); ++r) EXPECT_EQ(fits[r].size(), 21u) << "row " << r;
  EXPECT_EQ(fits[5][1], "table+gyro");
  EXPECT_EQ(std::stod(fits[5][17]), p.joint.lagS * 1e3);
  EXPECT_EQ(fits[3][2], "4-parameter");
  EXPECT_EQ(std::stod(fits[3][7]), p.tableFit.phaseMs);

  // residuals_1.csv: every table sample and every increment but the first,
  // whose RMS is the fits' residual RMS.
  const auto res = csvRows(readText(dir + "/residuals_1.csv"));
  ASSERT_EQ(res.size(), 1u + p.tableSamples + (p.imuSamples - 1));
  double table2 = 0.0, gyro2 = 0.0;
  std::size_t nt = 0, ng = 0;
  for (std::size_t r = 1; r < res.size(); ++r) {
    const double v = std::stod(res[r][2]);
    if (res[r][0] == "table") table2 += v * v, ++nt;
    else gyro2 += v * v, ++ng;
  }
  EXPECT_EQ(nt, p.tableSamples);
  EXPECT_NEAR(std::sqrt(table2 / static_cast<double>(nt)), p.tableFit.residualRmsDeg, 1e-9 * p.tableFit.residualRmsDeg);
  EXPECT_NEAR(std::sqrt(gyro2 / static_cast<double>(ng)), p.gyroFit.residualRmsDeg, 1e-9 * p.gyroFit.residualRmsDeg);
  // Tens of MB; kept only when an ASSERT above stopped the test early.
  std::filesystem::remove_all(dir);
}

TEST(CsvRoundTrip, SlowSwing0p1Hz10DegReproducesTheReport) {
  model::SimConfig config;
  config.seed = 7;
  roundTrip(config, TestPlan::paperSlow());
}

TEST(CsvRoundTrip, FastSwing1Hz3DegReproducesTheReport) {
  model::SimConfig config;
  config.seed = 11;
  config.fog.setOwnDelayS(0.2967e-3);
  roundTrip(config, TestPlan::paperFast());
}

}  // namespace
}  // namespace fog::io
