// How many replays a diagnosis runs and how many times it walks each
// recording (core/diagnosis/replay_passes.h): its time is replays times a
// replay's cost, and a replay's cost is the simulation plus its passes. The
// timing audit's own replay of the nominal chain (a whole simulation for one
// pass over its stamps) and a residual pass over every replay's IMU samples
// that only the first replay's view reads were such quiet costs. These tests
// fail when a replay or a pass is added; no timing is asserted.

#include "core/diagnosis/replay_passes.h"

#include <gtest/gtest.h>

#include "core/common/test_plan.h"
#include "core/diagnosis/diagnosis.h"
#include "core/diagnosis/diagnosis_stages.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis {
namespace {

struct Counted {
  Diagnosis d;
  ReplayPassCounts counts;
  std::uint64_t points = 0;  // test points the diagnosis used
};

// A clean session of the quick plan (seed 5), diagnosed with `options`; the
// counts are the diagnosis' own (the session is simulated and decoded
// before they are read).
Counted diagnoseQuickSession(const DiagnosisOptions& options) {
  const TestPlan plan = *presetPlan("quick");
  model::SimConfig c;
  c.seed = 5;
  auto run = model::simulate(c, plan);
  EXPECT_TRUE(run.isOk());
  auto rec = protocol::decodeRecording(run->bytes);
  EXPECT_TRUE(rec.isOk());
  SessionInfo info;
  info.plan = plan;
  Counted out;
  const ReplayPassCounts before = replayPassCounts();
  auto d = diagnose(*rec, &info, {}, options);
  const ReplayPassCounts after = replayPassCounts();
  EXPECT_TRUE(d.isOk()) << d.status().toString();
  out.d = *d;
  out.counts = {after.replays - before.replays, after.tablePasses - before.tablePasses,
                after.imuPasses - before.imuPasses};
  out.points = rec->testPoints.size();
  return out;
}

// Without refinement and pairs, the replays are the calibration's and the
// gap map's jobs, and nothing else: the nominal replay's timing audit is
// the first Monte Carlo replay's, not a replay of its own.
TEST(ReplayPasses, TheDiagnosisRunsItsStatedReplays) {
  DiagnosisOptions options;
  options.refineTop = 0;
  options.allowPairs = false;
  const Counted c = diagnoseQuickSession(options);
  ASSERT_GT(c.points, 0u);
  EXPECT_EQ(c.counts.replays, detail::kCalibrationReplays + detail::signatureJobs(options).size());
  // The session's timing and the nominal replay's are both still audited.
  EXPECT_GT(c.d.realTiming.imu.samples, 0u);
  EXPECT_EQ(c.d.simTiming.imu.samples, c.d.realTiming.imu.samples);
}

// Each replay walks each test point's table samples once and its IMU
// samples twice (the feature extraction: the frame interval's median, the
// fit); beyond that, per test point, the session's features (table once,
// IMU three times with the residual drawn), the first replay's residual
// (IMU once), the first replay's samples kept for the later replays to
// compare theirs with (FeatureSums: table and IMU once) and the two timing
// audits (table and IMU once each, the session's and the nominal replay's).
// A later replay whose stamps and readings are the first's compares them
// instead of summing: the same count. Whatever the refinement replays.
TEST(ReplayPasses, EachReplayWalksItsSamplesAFixedNumberOfTimes) {
  const Counted c = diagnoseQuickSession(DiagnosisOptions{});
  ASSERT_GT(c.points, 0u);
  ASSERT_GE(c.counts.replays, detail::kCalibrationReplays + detail::signatureJobs(DiagnosisOptions{}).size());
  EXPECT_EQ(c.counts.tablePasses, c.points * (c.counts.replays + 1 + 1 + 2));
  EXPECT_EQ(c.counts.imuPasses, c.points * (2 * c.counts.replays + 3 + 1 + 1 + 2));
}

}  // namespace
}  // namespace fog::diagnosis
