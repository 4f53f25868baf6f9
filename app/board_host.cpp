#include "app/board_host.h"

#include <cstdio>

namespace fog::app {

std::string BoardHostControl::apply(const protocol::HostCommand& c) {
  engaged_ = true;
  char b[200];
  switch (c.opcode) {
    case protocol::HostOpcode::kSetPulseEquivalent:
      pulseEquivalentDeg_ = c.pulseEquivalentDeg;
      std::snprintf(b, sizeof b, "pulse equivalent %.9g deg", c.pulseEquivalentDeg);
      return b;
    case protocol::HostOpcode::kStopStreaming: streaming_ = false; return "stop streaming";
    case protocol::HostOpcode::kStartStreaming: streaming_ = true; return "start streaming";
    case protocol::HostOpcode::kMarkTestPoint:
      marker_ = c;
      statusDue_ = true;
      std::snprintf(b, sizeof b, "mark test point %u axis %u phase %u %.6f Hz %.6f deg flags %u",
                    static_cast<unsigned>(c.testPoint), static_cast<unsigned>(c.axis), static_cast<unsigned>(c.phase),
                    c.nominalFrequencyMicroHz / 1e6, c.nominalAmplitudeMicroDeg / 1e6, static_cast<unsigned>(c.flags));
      return b;
  }
  return "unknown";
}

void BoardHostControl::rewrite(const protocol::Frame& f, std::vector<std::uint8_t>& out) {
  if (const auto* s = std::get_if<protocol::StatusPayload>(&f.payload)) {
    protocol::StatusPayload p = *s;
    if (pulseEquivalentDeg_) p.pulseEquivalentDeg = *pulseEquivalentDeg_;
    if (marker_) {
      p.testPoint = marker_->testPoint;
      p.axis = marker_->axis;
      p.phase = marker_->phase;
      p.nominalFrequencyMicroHz = marker_->nominalFrequencyMicroHz;
      p.nominalAmplitudeMicroDeg = marker_->nominalAmplitudeMicroDeg;
      p.flags = marker_->flags;
    }
    writer_.status(f.counter, p, out);
  } else if (const auto* t = std::get_if<protocol::TablePayload>(&f.payload)) {
    if (streaming_) writer_.table(f.counter, *t, out);
  } else if (const auto* i = std::get_if<protocol::ImuPayload>(&f.payload)) {
    if (streaming_) writer_.imu(f.counter, *i, out);
  }
}

void BoardHostControl::process(std::span<const std::uint8_t> clean, std::vector<std::uint8_t>& out) {
  frames_.clear();
  decoder_.push(clean, frames_);
  if (!engaged_) {
    // Pass-through; keep the writer's sequences in step for when commands come.
    out.insert(out.end(), clean.begin(), clean.end());
    std::vector<std::uint8_t> scratch;
    for (const auto& d : frames_) {
      scratch.clear();
      rewrite(d.frame, scratch);
      lastCounter_ = d.frame.counter;
      if (const auto* s = std::get_if<protocol::StatusPayload>(&d.frame.payload)) lastStatus_ = *s;
    }
    return;
  }
  if (statusDue_) {
    // A marker is announced at once (the board sends a STATUS on every change).
    statusDue_ = false;
    rewrite(protocol::Frame{protocol::FrameType::kStatus, 0, lastCounter_, lastStatus_}, out);
  }
  for (const auto& d : frames_) {
    rewrite(d.frame, out);
    lastCounter_ = d.frame.counter;
    if (const auto* s = std::get_if<protocol::StatusPayload>(&d.frame.payload)) lastStatus_ = *s;
  }
}

}  // namespace fog::app
