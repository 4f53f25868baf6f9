// The acquisition run: recording, decoding, live batches, stop and source
// failure, on the simulator and on scripted sources.

#include "core/acquisition/acquisition.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/acquisition/simulator_source.h"
#include "core/analysis/delay_analysis.h"
#include "core/protocol/frame.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"
#include "session_test_util.h"

namespace fog::acquisition {
namespace {

using std::chrono::milliseconds;

// Hands out a fixed byte stream in pieces, then ends, fails, or falls silent.
class ScriptedSource : public ByteSource {
 public:
  enum class Then { kEnd, kFail, kSilence };
  ScriptedSource(std::vector<std::uint8_t> bytes, Then then, std::size_t piece = 4096)
      : bytes_(std::move(bytes)), then_(then), piece_(piece) {}

  Result<ReadOutcome> read(std::vector<std::uint8_t>& out, milliseconds timeout) override {
    if (at_ < bytes_.size()) {
      const std::size_t n = std::min(piece_, bytes_.size() - at_);
      out.insert(out.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(at_),
                 bytes_.begin() + static_cast<std::ptrdiff_t>(at_ + n));
      at_ += n;
      return ReadOutcome{n, then_ == Then::kEnd && at_ == bytes_.size()};
    }
    if (then_ == Then::kFail) return ioError("serial port /dev/ttyTEST vanished");
    std::this_thread::sleep_for(timeout);
    return ReadOutcome{0, false};
  }
  std::string description() const override { return "scripted"; }

 private:
  std::vector<std::uint8_t> bytes_;
  Then then_;
  std::size_t piece_;
  std::size_t at_ = 0;
};

AcquisitionOptions sessionOptions(const std::string& path) {
  AcquisitionOptions o;
  o.sessionPath = path;
  o.info.operatorName = "acquisition test";
  o.info.plan = fog::test::shortPlan();
  return o;
}

TEST(Acquisition, SimulatorRunIsRecordedDecodedAndAnalysedLikeADirectDecode) {
  fog::test::ScratchDir dir;
  model::SimConfig config;
  config.seed = 3;
  auto source = SimulatorSource::create(config, fog::test::shortPlan(), 0.0);
  ASSERT_TRUE(source.isOk());
  std::size_t batchedFrames = 0;
  auto r = acquire(**source, sessionOptions(dir.file("s.fbs")), nullptr,
                   [&](AcquisitionBatch&& b) { batchedFrames += b.frames.size(); });
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_TRUE(r->complete);
  EXPECT_EQ(r->sessionPath, dir.file("s.fbs"));

  // The same bytes as the one-shot simulation, stored exactly.
  auto direct = model::simulate(config, fog::test::shortPlan());
  ASSERT_TRUE(direct.isOk());
  auto reader = session::SessionReader::open(dir.file("s.fbs"));
  ASSERT_TRUE(reader.isOk()) << reader.status().message();
  EXPECT_TRUE((*reader)->complete());
  EXPECT_EQ((*reader)->info().source, "simulator, seed 3, as fast as possible");
  EXPECT_TRUE(*(*reader)->rawBytes() == direct->bytes);
  auto decoded = protocol::decodeRecording(direct->bytes);
  ASSERT_TRUE(decoded.isOk());
  fog::test::expectSameRecording(r->recording, *decoded);
  fog::test::expectSameRecording(*(*reader)->recording(), *decoded);
  // Every decoded frame reached the observer, once.
  EXPECT_EQ(batchedFrames, decoded->health.tableFrames + decoded->health.imuFrames + decoded->health.statusFrames);
  // The analysis is the one of the decoded data, and it is stored.
  ASSERT_TRUE(r->report.isOk()) << r->report.status().message();
  auto expected = analysis::analyzeRecording(*decoded, AcquisitionOptions{}.constants);
  ASSERT_TRUE(expected.isOk());
  EXPECT_EQ(r->report->points.at(0).lagMs, expected->points.at(0).lagMs);
  EXPECT_EQ((*reader)->results()->size(), 1u);
}

TEST(Acquisition, RealTimePacingFollowsTheWallClock) {
  // 1 Hz / 3 deg for 1 s after 0.5 s settling: about 1.5 s of stream at 1x.
  TestPlan plan = fog::test::shortPlan();
  plan.points[0].durationS = 2.0;
  plan.points[0].settleS = 0.5;
  auto source = SimulatorSource::create(model::SimConfig{}, plan, 1.0);
  ASSERT_TRUE(source.isOk());
  const double streamS = (*source)->totalS();
  const auto start = std::chrono::steady_clock::now();
  auto r = acquire(**source, AcquisitionOptions{}, nullptr);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.isOk());
  EXPECT_TRUE(r->complete);
  EXPECT_GE(took, 0.9 * streamS);  // never ahead of the clock (late is allowed)
}

TEST(Acquisition, StopKeepsEverythingReceivedAndSaysSo) {
  fog::test::ScratchDir dir;
  std::atomic<bool> stop{false};
  model::SimConfig config;
  // 12 s of stream at 20x: batches arrive while it runs.
  auto source = SimulatorSource::create(config, fog::test::shortPlan(), 20.0);
  ASSERT_TRUE(source.isOk());
  std::uint64_t bytesAtStop = 0;
  auto r = acquire(**source, sessionOptions(dir.file("s.fbs")), &stop, [&](AcquisitionBatch&& b) {
    if (b.bytesReceived > 100000 && !stop) {
      stop = true;
      bytesAtStop = b.bytesReceived;
    }
  });
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE(r->complete);
  EXPECT_NE(r->incompleteReason.find("stopped by the operator after"), std::string::npos) << r->incompleteReason;
  EXPECT_EQ(r->bytesReceived, bytesAtStop);
  auto reader = session::SessionReader::open(dir.file("s.fbs"));
  ASSERT_TRUE(reader.isOk());
  EXPECT_FALSE((*reader)->complete());
  EXPECT_EQ((*reader)->incompleteReason(), r->incompleteReason);
  // What was received is stored, and is a prefix of the full stream.
  auto full = model::simulate(config, fog::test::shortPlan());
  auto raw = (*reader)->rawBytes();
  ASSERT_TRUE(raw.isOk());
  ASSERT_EQ(raw->size(), bytesAtStop);
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), full->bytes.begin()));
  EXPECT_TRUE((*reader)->hasStoredRecording());
}

TEST(Acquisition, SourceFailureEndsTheRunIncompleteWithEverythingKept) {
  fog::test::ScratchDir dir;
  const auto& bytes = fog::test::shortRun().bytes;
  ScriptedSource source(bytes, ScriptedSource::Then::kFail);
  auto r = acquire(source, sessionOptions(dir.file("s.fbs")), nullptr);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE(r->complete);
  EXPECT_NE(r->incompleteReason.find("serial port /dev/ttyTEST vanished (after"), std::string::npos)
      << r->incompleteReason;
  // The whole stream had arrived before the port vanished: it is analysed.
  EXPECT_TRUE(r->report.isOk());
  auto reader = session::SessionReader::open(dir.file("s.fbs"));
  ASSERT_TRUE(reader.isOk());
  EXPECT_FALSE((*reader)->complete());
  EXPECT_TRUE(*(*reader)->rawBytes() == bytes);
  EXPECT_EQ((*reader)->results()->size(), 1u);
}

// The memory budget (test_plan.h): a source that sends more samples than a
// run may hold (a board sending faster or longer than planned) ends the run
// there as incomplete, with everything received kept and analysed.
TEST(Acquisition, ASourceBeyondTheSampleBudgetEndsTheRunIncompleteKeepingWhatItSent) {
  fog::test::ScratchDir dir;
  const auto& bytes = fog::test::shortRun().bytes;
  ScriptedSource source(bytes, ScriptedSource::Then::kSilence);
  auto options = sessionOptions(dir.file("s.fbs"));
  options.maxSamples = 6000;  // 4 s of the standard rates; the stream holds 12 s
  auto r = acquire(source, options, nullptr);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE(r->complete);
  EXPECT_NE(r->incompleteReason.find("memory budget of 6000 table and IMU samples"), std::string::npos)
      << r->incompleteReason;
  EXPECT_LT(r->bytesReceived, bytes.size());
  EXPECT_EQ(r->sessionBytes, r->bytesReceived);
  std::size_t held = 0;
  for (const auto& tp : r->recording.testPoints) held += tp.table.size() + tp.imu.size();
  EXPECT_LE(held, 6000u + 4096u);  // at most one read beyond the budget
  auto reader = session::SessionReader::open(dir.file("s.fbs"));
  ASSERT_TRUE(reader.isOk());
  EXPECT_FALSE((*reader)->complete());
  EXPECT_EQ((*reader)->incompleteReason(), r->incompleteReason);
}

// A simulated plan that the plan's 1-h limit allows at the standard rates but
// that would exceed the sample budget at higher ones is refused before it runs.
TEST(Acquisition, ASimulatedRunBeyondTheSampleBudgetIsRefusedBeforeItStarts) {
  model::SimConfig config;
  TestPlan plan;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 3000.0, 0.0, 0.0});
  EXPECT_TRUE(SimulatorSource::create(config, plan, 0.0).isOk());
  config.encoder.samplePeriodS = 0.25e-3;  // 4 kHz table: 15 M samples
  config.encoder.readDelayS = std::min(config.encoder.readDelayS, 0.1e-3);
  auto refused = SimulatorSource::create(config, plan, 0.0);
  ASSERT_FALSE(refused.isOk());
  EXPECT_EQ(refused.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(refused.status().message().find("at most 6e+06"), std::string::npos) << refused.status().message();
}

TEST(Acquisition, SilenceIsReportedInTheBatches) {
  const auto& bytes = fog::test::shortRun().bytes;
  ScriptedSource source(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 20000),
                        ScriptedSource::Then::kSilence);
  std::atomic<bool> stop{false};
  AcquisitionOptions o;
  o.stallWarning = milliseconds(100);
  double silent = 0.0;
  auto r = acquire(source, o, &stop, [&](AcquisitionBatch&& b) {
    silent = std::max(silent, b.silentForS);
    if (b.silentForS > 0.3) stop = true;
  });
  ASSERT_TRUE(r.isOk());
  EXPECT_GT(silent, 0.3);
  EXPECT_FALSE(r->complete);
}

TEST(Acquisition, ANewSessionNeverOverwritesAFile) {
  fog::test::ScratchDir dir;
  fog::test::writeFile(dir.file("s.fbs"), {1, 2, 3});
  ScriptedSource source(fog::test::shortRun().bytes, ScriptedSource::Then::kEnd);
  auto r = acquire(source, sessionOptions(dir.file("s.fbs")), nullptr);
  ASSERT_FALSE(r.isOk());
  EXPECT_EQ(fog::test::readFile(dir.file("s.fbs")), (std::vector<std::uint8_t>{1, 2, 3}));
}

TEST(Acquisition, WithoutASessionNothingIsWritten) {
  ScriptedSource source(fog::test::shortRun().bytes, ScriptedSource::Then::kEnd, 777);
  auto r = acquire(source, AcquisitionOptions{}, nullptr);
  ASSERT_TRUE(r.isOk());
  EXPECT_TRUE(r->complete);
  EXPECT_TRUE(r->sessionPath.empty());
  EXPECT_TRUE(r->report.isOk());
}

TEST(Acquisition, AStallBeyondTheLimitEndsTheRunIncompleteSayingHowLong) {
  fog::test::ScratchDir dir;
  const auto& bytes = fog::test::shortRun().bytes;
  const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + 20000);
  ScriptedSource source(part, ScriptedSource::Then::kSilence);
  auto o = sessionOptions(dir.file("s.fbs"));
  o.stallLimit = milliseconds(300);
  const auto started = std::chrono::steady_clock::now();
  auto r = acquire(source, o, nullptr);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
  EXPECT_FALSE(r->complete);
  EXPECT_EQ(r->incompleteReason.rfind("no data for 0.3 s from scripted (after ", 0), 0u) << r->incompleteReason;
  auto reader = session::SessionReader::open(dir.file("s.fbs"));
  ASSERT_TRUE(reader.isOk());
  EXPECT_EQ((*reader)->incompleteReason(), r->incompleteReason);
  EXPECT_TRUE(*(*reader)->rawBytes() == part);
}

TEST(Acquisition, TheBoardsDoneStatusEndsALiveRunAsComplete) {
  // A live board never ends its stream: after the plan it falls silent here.
  ScriptedSource source(fog::test::shortRun().bytes, ScriptedSource::Then::kSilence);
  AcquisitionOptions o;
  o.endWhenBoardDone = true;
  o.stallLimit = milliseconds(3000);  // only if "done" were missed
  auto r = acquire(source, o, nullptr);
  ASSERT_TRUE(r.isOk());
  EXPECT_TRUE(r->complete) << r->incompleteReason;
  EXPECT_TRUE(r->report.isOk());
}

TEST(Acquisition, ADoneStatusBeforeAnyRecordingDoesNotEndTheRun) {
  // A board still showing the end of its previous plan when the run starts.
  protocol::FrameWriter w;
  std::vector<std::uint8_t> bytes;
  protocol::StatusPayload done;
  done.phase = protocol::TestPhase::kDone;
  w.status(1000, done, bytes);
  ScriptedSource source(bytes, ScriptedSource::Then::kSilence);
  AcquisitionOptions o;
  o.endWhenBoardDone = true;
  o.stallLimit = milliseconds(200);
  auto r = acquire(source, o, nullptr);
  ASSERT_TRUE(r.isOk());
  EXPECT_FALSE(r->complete);
  EXPECT_EQ(r->incompleteReason.rfind("no data for", 0), 0u) << r->incompleteReason;
}

}  // namespace
}  // namespace fog::acquisition
