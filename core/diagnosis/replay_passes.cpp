#include "core/diagnosis/replay_passes.h"

#include <atomic>

namespace fog::diagnosis {

namespace {
std::atomic<std::uint64_t> replays{0}, tablePasses{0}, imuPasses{0};
}  // namespace

void countReplay() { replays.fetch_add(1, std::memory_order_relaxed); }

void countRecordingPass(analysis::SampleStream stream) {
  (stream == analysis::SampleStream::kTable ? tablePasses : imuPasses).fetch_add(1, std::memory_order_relaxed);
}

ReplayPassCounts replayPassCounts() {
  return {replays.load(std::memory_order_relaxed), tablePasses.load(std::memory_order_relaxed),
          imuPasses.load(std::memory_order_relaxed)};
}

}  // namespace fog::diagnosis
