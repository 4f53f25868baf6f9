#pragma once
// The remote driver: a table controller that speaks the text protocol of
// docs/table-control.md over a ByteTransport (TCP or a serial line).
//
// Every setting command is followed by "SYST:ERR?": a command the controller
// refuses comes back as an error Status carrying the controller's own number
// and text ("the table controller refused 'AXIS:Y:START': 204,\"Refused by
// the controller\""), and its error queue is drained so the next command
// starts clean. Queries expect exactly one reply line within replyTimeout.
//
// Failure behaviour: a reply that does not arrive in time, a line longer than
// scpi::kMaxLineBytes, a reply that is not what the query promises (fields,
// numbers, modes) gives kIoError / kCorruptData naming the command and the
// reply; after one, the link is out of step and every later call fails at
// once, except stopAll() and emergencyStop(), which still send their command
// (unconfirmed) as a last resort. Nothing here crashes or hangs on any reply.
//
// Not thread-safe (TableController contract). `log` (may be empty) receives
// (kind, text): kind "command" for a line sent, "reply" for a line received,
// "status" for a state that differs from the last one logged. Routine polls
// (state queries, heartbeats and their "no error" confirmations) are not
// logged line by line; their result is, as "status" lines, when it changes.

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "core/table/table_controller.h"
#include "core/table/transport.h"

namespace fog::table {

struct RemoteOptions {
  std::chrono::milliseconds replyTimeout{2000};
  // Sent as SYST:HEART:TIM on connect: the controller stops the table when
  // the host is quiet longer than this (wall seconds). 0: off.
  double heartbeatTimeoutS = 2.0;
};

using TableLogFn = std::function<void(const std::string& kind, const std::string& text)>;

class RemoteTable : public TableController {
 public:
  // Identifies the controller (*IDN?), clears its error queue (*CLS) and sets
  // its heartbeat timeout. Fails if any of that fails.
  static Result<std::unique_ptr<RemoteTable>> connect(std::unique_ptr<ByteTransport> link, RemoteOptions options = {},
                                                      TableLogFn log = {});

  std::string description() const override;
  Result<std::string> identify() override;
  Result<TableLimits> limits() override;
  Result<TableState> state() override;
  Status configureSwing(Axis axis, const SwingSpec& swing) override;
  Status moveTo(Axis axis, double positionDeg) override;
  Status startSwing(Axis axis) override;
  Status stop(Axis axis) override;
  Status stopAll() override;
  Status emergencyStop() override;
  Status keepAlive() override;
  Status release() override;  // SYST:HEART:TIM 0
  // The protocol's AXIS:a:START ramps the amplitude up over one whole period
  // (docs/table-control.md): 1 / frequency.
  double swingRampS(const SwingSpec& swing) const override;

  // One query / one command, for tests and tools.
  Result<std::string> query(const std::string& line, bool quiet = false);
  Status command(const std::string& line, bool quiet = false);

 private:
  RemoteTable(std::unique_ptr<ByteTransport> link, RemoteOptions options, TableLogFn log);
  Status send(const std::string& line, bool quiet);
  Result<std::string> readLine(const std::string& forWhat);
  void note(const std::string& kind, const std::string& text, bool quiet);
  Status outOfStep(Status why);

  std::unique_ptr<ByteTransport> link_;
  RemoteOptions options_;
  TableLogFn log_;
  std::string buffer_;
  std::string identity_;
  std::string lastStatusLine_;
  Status broken_;
};

}  // namespace fog::table
