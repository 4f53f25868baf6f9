#include "core/analysis/sample_passes.h"

#include <atomic>

namespace fog::analysis {

namespace {
std::atomic<std::uint64_t> tablePasses{0}, gyroPasses{0};
}  // namespace

void countPass(SampleStream stream, unsigned passes) {
  (stream == SampleStream::kTable ? tablePasses : gyroPasses).fetch_add(passes, std::memory_order_relaxed);
}

SamplePassCounts samplePassCounts() {
  return {tablePasses.load(std::memory_order_relaxed), gyroPasses.load(std::memory_order_relaxed)};
}

}  // namespace fog::analysis
