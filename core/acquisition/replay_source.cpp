#include "core/acquisition/replay_source.h"

#include <algorithm>
#include <cstdio>
#include <variant>

namespace fog::acquisition {

namespace {
// About 25 ms of a 1 kHz table + 500 Hz IMU stream: the size of a serial read.
constexpr std::size_t kChunkBytes = 1024;
}  // namespace

ReplaySource::ReplaySource(std::vector<std::uint8_t> bytes, double speed, std::string name, WallClock wall)
    : bytes_(std::move(bytes)), clock_(speed, std::move(wall)), name_(std::move(name)) {}

void ReplaySource::prepareChunk() {
  chunkEnd_ = std::min(bytes_.size(), position_ + kChunkBytes);
  frames_.clear();
  timing_.push(std::span<const std::uint8_t>(bytes_.data() + position_, chunkEnd_ - position_), frames_);
  for (const auto& f : frames_) {
    if (const auto* s = std::get_if<protocol::StatusPayload>(&f.frame.payload); s && s->counterHz > 0)
      counterHz_ = s->counterHz;
    if (!haveFirst_) {
      haveFirst_ = true;
      firstTicks_ = f.ticks;
    }
    chunkTimeS_ = static_cast<double>(f.ticks - firstTicks_) / counterHz_;
  }
  // A chunk without a complete frame (garbage, a split frame) is due at once.
}

Result<ReadOutcome> ReplaySource::read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) {
  if (position_ >= bytes_.size()) return ReadOutcome{0, true};
  if (chunkEnd_ <= position_) prepareChunk();
  if (!clock_.waitFor(chunkTimeS_, timeout)) return ReadOutcome{0, false};
  out.insert(out.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(position_),
             bytes_.begin() + static_cast<std::ptrdiff_t>(chunkEnd_));
  const std::size_t n = chunkEnd_ - position_;
  position_ = chunkEnd_;
  return ReadOutcome{n, position_ >= bytes_.size()};
}

std::string ReplaySource::description() const {
  char speed[48];
  if (clock_.asFastAsPossible()) std::snprintf(speed, sizeof speed, "as fast as possible");
  else std::snprintf(speed, sizeof speed, "%gx", clock_.speed());
  return "replay of " + name_ + " at " + speed;
}

}  // namespace fog::acquisition
