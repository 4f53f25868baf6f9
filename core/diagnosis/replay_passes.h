#pragma once
// Replays of the simulated chain and passes over a recording's samples made
// by the diagnosis, counted so that a test can fail when it starts simulating
// or walking a recording again (tests/core/diagnosis/replay_passes_test.cpp):
// a diagnosis' time is its replays times a replay's cost, and a replay's cost
// is the simulation plus the passes over its samples. The timing audit's
// replay of the nominal chain, a whole simulation for one pass over its
// stamps, was such a replay (core/analysis/sample_passes.h has the same idea
// for the delay analysis).
//
// Counted: every recording simulateRecording() builds (a replay, whether
// Replay::run() or another caller asked for it), and every pass that
// extractFeatures() and auditTiming() make over one test point's table
// samples or IMU samples, the session's own included. One relaxed atomic add per
// replay or pass, never per sample, so it is always compiled in. The counts
// are process-wide: read them only where one diagnosis runs.

#include <cstdint>

#include "core/analysis/sample_passes.h"

namespace fog::diagnosis {

struct ReplayPassCounts {
  std::uint64_t replays = 0, tablePasses = 0, imuPasses = 0;
};

void countReplay();
void countRecordingPass(analysis::SampleStream stream);
// The counts since the program started.
ReplayPassCounts replayPassCounts();

}  // namespace fog::diagnosis
