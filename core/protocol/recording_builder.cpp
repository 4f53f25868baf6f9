#include "core/protocol/recording_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

namespace fog::protocol {

void RecordingBuilder::add(std::span<const DecodedFrame> frames) {
  for (const auto& f : frames) add(f);
}

void RecordingBuilder::onStatus(const StatusPayload& s) {
  if (s.counterHz > 0) counterHz_ = s.counterHz;
  if (s.counterBits >= 8 && s.counterBits <= 32) counterBits_ = s.counterBits;
  if (std::isfinite(s.pulseEquivalentDeg) && s.pulseEquivalentDeg > 0.0) pulseEquivalentDeg_ = s.pulseEquivalentDeg;
  if (!followMarkers_) return;
  collecting_ = s.phase == TestPhase::kRecording;
  if (!collecting_) return;
  if (!sawRecording_) {
    sawRecording_ = true;
    whole_ = Segment{};  // the fallback is no longer needed
  }
  if (segments_.empty() || segments_.back().testPoint != s.testPoint) {
    Segment seg;
    seg.testPoint = s.testPoint;
    seg.axis = s.axis < kAxisCount ? static_cast<Axis>(s.axis) : Axis::kX;
    seg.nominalFrequencyHz = s.nominalFrequencyMicroHz / 1e6;  // / 1e6, not * 1e-6: 100000 µHz is 0.1 Hz, not 0.09999999999999999
    seg.nominalAmplitudeDeg = s.nominalAmplitudeMicroDeg / 1e6;
    seg.kind = (s.flags & kStatusFlagStatic) != 0 ? TestPointKind::kStatic : TestPointKind::kSwing;
    segments_.push_back(std::move(seg));
  }
}

void RecordingBuilder::add(const DecodedFrame& f) {
  ++framesAdded_;
  if (!haveFirst_) {
    haveFirst_ = true;
    firstTicks_ = f.ticks;
  }
  const std::int64_t ticks = f.ticks - firstTicks_;
  Segment* targets[2] = {collecting_ ? &segments_.back() : nullptr, sawRecording_ ? nullptr : &whole_};
  for (auto* seg : targets) {
    if (!seg) continue;
    auto& h = seg->health;
    h.duplicateFrames += f.duplicatesBefore;
    h.checksumFailures += f.checksumFailuresBefore;
    h.outOfOrderFrames += f.outOfOrderBefore;
    h.bytesSkipped += f.bytesSkippedBefore;
    h.lostFrames += f.lostBefore;
    if (f.frame.type == FrameType::kTable) ++h.tableFrames;
    if (f.frame.type == FrameType::kImu) ++h.imuFrames;
  }
  if (const auto* s = std::get_if<StatusPayload>(&f.frame.payload)) {
    onStatus(*s);
    return;
  }
  if (const auto* t = std::get_if<TablePayload>(&f.frame.payload)) {
    TableSample r;
    r.timeS = static_cast<double>(ticks);  // converted by finish()
    for (int a = 0; a < kAxisCount; ++a) r.angleDeg[a] = t->angleMicroDeg[a] * 1e-6;
    for (auto* seg : targets)
      if (seg) seg->table.push_back(r);
  } else if (const auto* m = std::get_if<ImuPayload>(&f.frame.payload)) {
    ImuSample r;
    r.timeS = static_cast<double>(ticks);  // converted by finish()
    for (int a = 0; a < kAxisCount; ++a) r.incrementDeg[a] = m->pulses[a];
    r.temperatureC = m->temperatureCentiC / 100.0;
    r.lostBefore = f.lostBefore;
    for (auto* seg : targets) {
      if (!seg) continue;
      if (seg->pulseEquivalents.empty() || seg->pulseEquivalents.back().second != pulseEquivalentDeg_)
        seg->pulseEquivalents.emplace_back(seg->imu.size(), pulseEquivalentDeg_);
      seg->imu.push_back(r);
    }
  }
}

Result<Recording> RecordingBuilder::finish(const StreamHealth& health, double benchPulseEquivalentDeg) {
  // The stream's own statement wins; the bench's constant only stands in
  // for a stream that never states one.
  const bool benchKnows = std::isfinite(benchPulseEquivalentDeg) && benchPulseEquivalentDeg > 0.0;
  const double fallback = pulseEquivalentDeg_ > 0.0 ? pulseEquivalentDeg_ : benchKnows ? benchPulseEquivalentDeg : 0.0;
  Recording rec;
  rec.counterHz = counterHz_;
  rec.counterBits = counterBits_;
  rec.pulseEquivalentDeg = fallback;
  rec.health = health;

  if (!sawRecording_) {
    // No test plan in the stream: the largest swing names the axis.
    std::array<double, kAxisCount> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (const auto& t : whole_.table)
      for (int a = 0; a < kAxisCount; ++a) {
        lo[a] = std::min(lo[a], t.angleDeg[a]);
        hi[a] = std::max(hi[a], t.angleDeg[a]);
      }
    int best = 0;
    for (int a = 1; a < kAxisCount; ++a)
      if (hi[a] - lo[a] > hi[best] - lo[best]) best = a;
    whole_.testPoint = 0;
    whole_.axis = static_cast<Axis>(best);
    segments_.clear();
    segments_.push_back(std::move(whole_));
  }

  const bool anyImu = std::any_of(segments_.begin(), segments_.end(), [](const Segment& s) { return !s.imu.empty(); });
  if (anyImu && !(fallback > 0.0)) {
    *this = RecordingBuilder{};
    return invalidArgument("the stream does not state its gyro pulse equivalent (degrees per pulse): give "
                           "--pulse-equivalent-deg or set it in the bench constants");
  }

  const double secondsPerTick = 1.0 / counterHz_;
  for (auto& seg : segments_) {
    if (seg.table.empty() && seg.imu.empty()) continue;
    TestPointData tp;
    tp.index = seg.testPoint;
    tp.axis = seg.axis;
    tp.nominalFrequencyHz = seg.nominalFrequencyHz;
    tp.nominalAmplitudeDeg = seg.nominalAmplitudeDeg;
    tp.kind = seg.kind;
    tp.health = seg.health;
    tp.table = std::move(seg.table);
    for (auto& t : tp.table) t.timeS *= secondsPerTick;
    tp.imu = std::move(seg.imu);
    for (std::size_t c = 0; c < seg.pulseEquivalents.size(); ++c) {
      const auto [from, known] = seg.pulseEquivalents[c];
      const std::size_t to = c + 1 < seg.pulseEquivalents.size() ? seg.pulseEquivalents[c + 1].first : tp.imu.size();
      const double scale = known > 0.0 ? known : fallback;
      for (std::size_t k = from; k < to; ++k)
        for (double& v : tp.imu[k].incrementDeg) v *= scale;
    }
    for (auto& m : tp.imu) m.timeS *= secondsPerTick;
    rec.testPoints.push_back(std::move(tp));
  }

  *this = RecordingBuilder{};
  return rec;
}

void StreamDecoder::push(std::span<const std::uint8_t> bytes) {
  // Pieces keep the intermediate frame list small.
  constexpr std::size_t kChunk = 1 << 16;
  for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
    frames_.clear();
    decoder_.push(bytes.subspan(at, std::min(kChunk, bytes.size() - at)), frames_);
    builder_.add(frames_);
  }
  bytes_ += bytes.size();
}

void StreamDecoder::push(std::span<const Frame> frames) {
  frames_.clear();
  for (const Frame& f : frames) decoder_.push(f, frames_);
  builder_.add(frames_);
}

Result<Recording> StreamDecoder::finish() {
  const StreamHealth health = decoder_.health();
  if (builder_.framesAdded() == 0)
    return corruptData("no valid sampling-board frames found in " + std::to_string(bytes_) +
                       " bytes; is this a fogbench raw stream, or is the baud rate wrong?");
  FOG_ASSIGN_OR_RETURN(Recording rec, builder_.finish(health, benchPulseEquivalentDeg_));
  const bool usable = std::any_of(rec.testPoints.begin(), rec.testPoints.end(),
                                  [](const TestPointData& tp) { return !tp.table.empty() && !tp.imu.empty(); });
  if (!usable)
    return insufficientData("the stream holds " + std::to_string(health.tableFrames) + " table, " +
                            std::to_string(health.imuFrames) + " IMU and " + std::to_string(health.statusFrames) +
                            " status frames, but no test point has both table and IMU samples; "
                            "was a test point recorded while both the turntable and the IMU were connected?");
  return rec;
}

Result<Recording> decodeRecording(std::span<const std::uint8_t> bytes, double benchPulseEquivalentDeg) {
  StreamDecoder decoder(benchPulseEquivalentDeg);
  decoder.push(bytes);
  return decoder.finish();
}

}  // namespace fog::protocol
