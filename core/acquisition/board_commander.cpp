#include "core/acquisition/board_commander.h"

#include <cmath>
#include <cstdio>

namespace fog::acquisition {

namespace {

const char* phaseName(protocol::TestPhase p) {
  switch (p) {
    case protocol::TestPhase::kIdle: return "idle";
    case protocol::TestPhase::kSettling: return "settling";
    case protocol::TestPhase::kRecording: return "recording";
    case protocol::TestPhase::kDone: return "done";
  }
  return "?";
}

std::uint32_t micro(double v) {
  const double m = std::round(std::fabs(v) * 1e6);
  return m >= 4294967295.0 ? 4294967295u : static_cast<std::uint32_t>(m);
}

}  // namespace

BoardCommander::BoardCommander(ByteSource* source, std::function<void(const std::string&)> log)
    : source_(source), log_(std::move(log)) {}

void BoardCommander::send(const protocol::HostCommand& command, const std::string& what) {
  if (!source_) return;
  std::vector<std::uint8_t> bytes;
  {
    std::lock_guard lock(mutex_);
    protocol::appendHostCommand(command, sequence_++, bytes);
    if (!source_->queueForDevice(bytes)) return;
    ++sent_;
  }
  if (log_) log_(what);
}

void BoardCommander::setPulseEquivalent(double degPerPulse) {
  if (!(degPerPulse > 0.0) || !std::isfinite(degPerPulse)) return;
  protocol::HostCommand c;
  c.opcode = protocol::HostOpcode::kSetPulseEquivalent;
  c.pulseEquivalentDeg = degPerPulse;
  char b[80];
  std::snprintf(b, sizeof b, "set pulse equivalent %.9g deg", degPerPulse);
  send(c, b);
}

void BoardCommander::startStreaming() { send(protocol::HostCommand{protocol::HostOpcode::kStartStreaming}, "start streaming"); }

void BoardCommander::stopStreaming() { send(protocol::HostCommand{protocol::HostOpcode::kStopStreaming}, "stop streaming"); }

void BoardCommander::markPoint(int index, const TestPoint& point, protocol::TestPhase phase) {
  protocol::HostCommand c;
  c.opcode = protocol::HostOpcode::kMarkTestPoint;
  c.testPoint = static_cast<std::uint16_t>(index < 0 || index >= protocol::kNoTestPoint ? protocol::kNoTestPoint : index);
  c.axis = static_cast<std::uint8_t>(point.axis);
  c.phase = phase;
  c.nominalFrequencyMicroHz = point.isStatic() ? 0u : micro(point.frequencyHz);
  c.nominalAmplitudeMicroDeg = point.isStatic() ? 0u : micro(point.amplitudeDeg);
  c.flags = point.isStatic() ? protocol::kStatusFlagStatic : 0;
  const char axis = static_cast<char>('X' + static_cast<int>(point.axis));
  char b[160];
  std::snprintf(b, sizeof b, "mark test point %d (%c %.9g Hz / %.9g deg) %s", index + 1, axis,
                point.isStatic() ? 0.0 : point.frequencyHz, point.isStatic() ? 0.0 : point.amplitudeDeg, phaseName(phase));
  send(c, b);
}

void BoardCommander::markDone() {
  protocol::HostCommand c;
  c.opcode = protocol::HostOpcode::kMarkTestPoint;
  c.testPoint = protocol::kNoTestPoint;
  c.phase = protocol::TestPhase::kDone;
  send(c, "mark plan done");
}

int BoardCommander::sent() const {
  std::lock_guard lock(mutex_);
  return sent_;
}

}  // namespace fog::acquisition
