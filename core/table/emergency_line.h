#pragma once
// The stops' own path to a table controller (docs/table-control.md, "The
// emergency stop never waits"). The bench's rule: a safety path never waits.
// Whatever else holds the controller — a poll waiting for its reply, a
// connect under way, a controller hung in the middle of a reply — an
// emergency stop or an ordinary stop sent here goes out on a link of its own: over TCP a
// connection of its own to the same HOST:PORT; on a serial device the device
// opened a second time (its one line shares the wire with the other link's
// lines; each goes out in one write, so lines do not mix).
//
// Armed: the line opens that link when it is armed (the panel arms it once
// its controller has answered) and keeps it, so that firing only writes — a
// controller that hangs later, and whose queue of connections to accept
// may fill up, still gets it, as its kernel takes what is written on a
// connection already open. Before a write the armed link is checked
// (closed by the controller: opened again); not armed, or armed elsewhere,
// a fire opens a link then (connectTimeout).
//
// The sequence of a fire: the command's line written (writeTimeout):
// `sent`, with the time from the request to the end of that write. An
// emergency stop ("SYST:ESTOP") over TCP then asks "SYST:STAT?" and waits up
// to confirmTimeout for the ESTOP flag: `confirmed`. An ordinary stop
// ("STOP": every axis decelerates to rest, not latched) is not confirmed
// here: the controller's state says it has no flag for it, and the panel's
// own link sends and confirms the same stop when the controller answers. (A read-only query, so it takes nothing from the
// controller's error queue, which another connection's command may be
// waiting to read; on a serial line it does not ask, as the reply could
// reach the other link's reader instead.) The link is then closed, and a
// fresh one armed again if the line is still armed.
//
// A controller that accepts only one connection refuses this one: `sent` is
// false with the reason, and the caller's other path (its own connection's
// queue) is what is left. Nothing here throws; every step is bounded.

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace fog::table {

class ByteTransport;

struct EmergencyLineOptions {
  std::chrono::milliseconds connectTimeout{300};
  std::chrono::milliseconds writeTimeout{200};
  std::chrono::milliseconds confirmTimeout{1000};
  int baud = 115200;  // a controller on a serial line
};

// What the line sends: the emergency stop (latched at the controller) or the
// ordinary stop of every axis.
enum class LineCommand { kEmergencyStop, kStopAll };

struct EmergencyOutcome {
  std::string address;
  LineCommand command = LineCommand::kEmergencyStop;
  bool sent = false;         // the command's line ("SYST:ESTOP", "STOP") written whole on the line's own link
  bool armedLink = false;    // ... on the link opened when the line was armed (else one opened to send it)
  double sentAfterMs = 0.0;  // from the request to the end of that write (or to the failure)
  std::chrono::steady_clock::time_point sentAt{};  // the end of that write (or the failure)
  bool confirmed = false;    // kEmergencyStop: the controller then reported its emergency stop engaged
  std::string why;           // not sent or not confirmed: why ("cannot connect to …", "no answer within 1000 ms")
};

// Sends the command on a link of its own, opened now, on the calling thread
// (bounded by the three timeouts). `requested`: when the operator asked
// (sentAfterMs counts from it).
EmergencyOutcome sendEmergencyStop(const std::string& address, const EmergencyLineOptions& options = {},
                                   std::chrono::steady_clock::time_point requested = std::chrono::steady_clock::now(),
                                   LineCommand command = LineCommand::kEmergencyStop);

// The stops on a thread of their own that is always ready, so that a caller
// (the GUI thread) never waits for a connect or a write.
//
// Thread-safety: arm() and fire() from any thread, never blocking (they wake
// the line's thread; a fire goes before an arm). `done` runs on the line's
// thread once per send; fires that arrive while a send is under way are
// served by one more send right after it. Pending fires merge into one: an
// emergency stop takes the place of an ordinary stop still pending (it
// stops every axis too), never the other way round. The destructor serves a fire
// still pending (it is a safety action) and waits for the step under way:
// bounded by the three timeouts.
class EmergencyLine {
 public:
  using DoneFn = std::function<void(const EmergencyOutcome&)>;
  explicit EmergencyLine(DoneFn done, EmergencyLineOptions options = {});
  ~EmergencyLine();
  EmergencyLine(const EmergencyLine&) = delete;
  EmergencyLine& operator=(const EmergencyLine&) = delete;

  // Opens (and keeps) the line's own link to `address`; empty: closes it.
  void arm(const std::string& address);
  void fire(const std::string& address, LineCommand command = LineCommand::kEmergencyStop);
  // The address the line holds a link to now, empty when none (for tests).
  std::string armedAt() const;

 private:
  void run();
  void rearm(const std::string& address);
  EmergencyOutcome send(const std::string& address, std::chrono::steady_clock::time_point requested,
                        LineCommand command);

  DoneFn done_;
  EmergencyLineOptions options_;
  // The line's thread only.
  std::unique_ptr<ByteTransport> link_;
  std::string linkAddress_;

  std::condition_variable wake_;
  mutable std::mutex mutex_;  // guards the members from here to thread_
  bool firePending_ = false;
  LineCommand fireCommand_ = LineCommand::kEmergencyStop;
  bool armPending_ = false;
  bool quit_ = false;
  std::string fireAddress_, armAddress_, armedAt_;
  std::chrono::steady_clock::time_point requested_;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace fog::table
