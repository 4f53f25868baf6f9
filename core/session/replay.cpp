#include "session/replay.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <variant>
#include <vector>

#include "protocol/recording_builder.h"

namespace fog::session {

Result<ReplayResult> replay(std::span<const std::uint8_t> bytes, const ReplayOptions& options,
                            const std::function<void(const ReplayChunk&)>& onChunk) {
  using Clock = std::chrono::steady_clock;
  const bool paced = options.speed > 0.0 && std::isfinite(options.speed);
  const std::size_t chunk = std::max<std::size_t>(options.chunkBytes, 1);
  auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

  protocol::Decoder decoder;
  protocol::RecordingBuilder builder;
  std::vector<protocol::DecodedFrame> frames;
  ReplayResult result;
  bool haveFirst = false;
  std::int64_t firstTicks = 0;
  double counterHz = 10e6;  // the board's default until a STATUS frame says otherwise
  const auto start = Clock::now();

  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    if (cancelled()) {
      result.cancelled = true;
      break;
    }
    const auto piece = bytes.subspan(at, std::min(chunk, bytes.size() - at));
    frames.clear();
    decoder.push(piece, frames);
    builder.add(frames);
    for (const auto& f : frames) {
      if (const auto* st = std::get_if<protocol::StatusPayload>(&f.frame.payload); st && st->counterHz > 0)
        counterHz = st->counterHz;
      if (!haveFirst) {
        haveFirst = true;
        firstTicks = f.ticks;
      }
    }
    if (!frames.empty()) result.streamDurationS = static_cast<double>(frames.back().ticks - firstTicks) / counterHz;
    result.bytesFed += piece.size();
    // Pace: this chunk's frames are due when their board time, scaled by the
    // speed, has elapsed on the wall clock since the replay started.
    if (paced) {
      const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(result.streamDurationS / options.speed));
      while (Clock::now() < due && !cancelled())
        std::this_thread::sleep_for(std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
    }
    if (onChunk) onChunk({piece, frames, result.bytesFed, bytes.size(), result.streamDurationS});
  }

  const auto health = decoder.health();
  if (result.cancelled) {
    result.recording = builder.finish(health);
    return result;
  }
  // Same verdicts as protocol::decodeRecording, so a replay and a direct
  // decode fail alike.
  if (builder.framesAdded() == 0)
    return corruptData("no valid sampling-board frames found in " + std::to_string(bytes.size()) +
                       " bytes; is this a fogbench raw stream, or is the baud rate wrong?");
  result.recording = builder.finish(health);
  const bool usable = std::any_of(result.recording.testPoints.begin(), result.recording.testPoints.end(),
                                  [](const TestPointData& tp) { return !tp.table.empty() && !tp.imu.empty(); });
  if (!usable)
    return insufficientData("the stream holds no test point with both table and IMU samples");
  return result;
}

}  // namespace fog::session
