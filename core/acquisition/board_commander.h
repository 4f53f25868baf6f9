#pragma once
// The host side of the host-to-board direction (docs/protocol.md, "Host to
// board"): the bench (fogbench-cli and the desktop bench) tells a real
// sampling board the gyro's pulse equivalent, starts and stops its stream and
// marks the test points of a table-driven run. Optional by design: the commands go out through the
// source's queue (ByteSource::queueForDevice) and nothing ever waits for an
// answer, so a board that only streams records exactly as before.
//
// Thread-safe: the plan runner's thread marks points while the acquisition
// thread reads the port.

#include <functional>
#include <mutex>
#include <string>

#include "core/acquisition/byte_source.h"
#include "core/common/test_plan.h"
#include "core/protocol/host_command.h"

namespace fog::acquisition {

class BoardCommander {
 public:
  // `source` may be null (commands off); `log` receives one line per command
  // sent ("start streaming", "mark test point 1 (X 1 Hz / 3 deg) recording").
  BoardCommander(ByteSource* source, std::function<void(const std::string&)> log = {});

  bool enabled() const { return source_ != nullptr; }
  void setPulseEquivalent(double degPerPulse);
  void startStreaming();
  void stopStreaming();
  // `index` 0-based (the plan's order); kIdle/kSettling/kRecording for a point.
  void markPoint(int index, const TestPoint& point, protocol::TestPhase phase);
  // The plan is over: no test point, phase done.
  void markDone();
  int sent() const;

 private:
  void send(const protocol::HostCommand& command, const std::string& what);

  ByteSource* source_;
  std::function<void(const std::string&)> log_;
  mutable std::mutex mutex_;
  std::uint16_t sequence_ = 0;
  int sent_ = 0;
};

}  // namespace fog::acquisition
