#include "core/table/emergency_line.h"

#include "core/table/scpi.h"
#include "core/table/transport.h"

namespace fog::table {

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// Reads SYST:STAT? replies until one says the emergency stop is engaged or
// the time is up. Empty when confirmed, else why not.
std::string confirm(ByteTransport& link, std::chrono::milliseconds timeout) {
  if (auto s = link.write("SYST:STAT?\n"); !s.isOk()) return s.message();
  const auto giveUp = Clock::now() + timeout;
  std::string buffer;
  for (;;) {
    const auto nl = buffer.find('\n');
    if (nl != std::string::npos) {
      std::string line = buffer.substr(0, nl);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const auto f = scpi::splitFields(line);
      if (f.size() == 4 && f[1] == "1") return std::string();
      return "the controller answered SYST:STAT? with '" + line.substr(0, 80) + "', not the emergency stop engaged";
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(giveUp - Clock::now());
    if (left.count() <= 0 || buffer.size() > scpi::kMaxLineBytes)
      return "no answer to SYST:STAT? within " + std::to_string(timeout.count()) + " ms";
    if (auto got = link.read(buffer, left); !got) return got.status().message();
  }
}

// The command written on `link`; an emergency stop then confirmed (TCP
// only: on a serial line the reply could reach the other link's reader).
void writeAndConfirm(ByteTransport& link, const EmergencyLineOptions& options, Clock::time_point requested,
                     EmergencyOutcome& out) {
  const bool emergency = out.command == LineCommand::kEmergencyStop;
  const Status written = link.write(emergency ? "SYST:ESTOP\n" : "STOP\n");
  out.sentAt = Clock::now();
  out.sentAfterMs = msBetween(requested, out.sentAt);
  if (!written.isOk()) {
    out.why = written.message();
    return;
  }
  out.sent = true;
  out.why.clear();
  if (emergency && out.address.rfind("tcp:", 0) == 0) {
    out.why = confirm(link, options.confirmTimeout);
    out.confirmed = out.why.empty();
  }
}

// An armed link the controller has not closed. Bytes waiting on it (a late
// answer to an earlier confirmation) are dropped; a closed link reads as
// an error.
bool stillOpen(ByteTransport& link) {
  std::string stale;
  for (int i = 0; i < 16; ++i) {
    auto got = link.read(stale, std::chrono::milliseconds(0));
    if (!got) return false;
    if (*got == 0) return true;
    stale.clear();
  }
  return true;
}

}  // namespace

EmergencyOutcome sendEmergencyStop(const std::string& address, const EmergencyLineOptions& options,
                                   Clock::time_point requested, LineCommand command) {
  EmergencyOutcome out;
  out.address = address;
  out.command = command;
  auto link = openTransport(address, options.baud, options.connectTimeout, options.writeTimeout);
  if (!link) {
    out.sentAt = Clock::now();
    out.sentAfterMs = msBetween(requested, out.sentAt);
    out.why = link.status().message();
    return out;
  }
  writeAndConfirm(**link, options, requested, out);
  return out;
}

EmergencyLine::EmergencyLine(DoneFn done, EmergencyLineOptions options)
    : done_(std::move(done)), options_(options), thread_([this] { run(); }) {}

EmergencyLine::~EmergencyLine() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void EmergencyLine::arm(const std::string& address) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    armAddress_ = address;
    armPending_ = true;
  }
  wake_.notify_one();
}

void EmergencyLine::fire(const std::string& address, LineCommand command) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // A fire while one is pending keeps the first request time: the latency
    // reported is the operator's wait from the first click.
    if (!firePending_) {
      requested_ = Clock::now();
      fireCommand_ = command;
    } else if (command == LineCommand::kEmergencyStop) {
      fireCommand_ = command;
    }
    firePending_ = true;
    fireAddress_ = address;
  }
  wake_.notify_one();
}

std::string EmergencyLine::armedAt() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return armedAt_;
}

void EmergencyLine::run() {
  for (;;) {
    std::string address;
    Clock::time_point requested;
    LineCommand command = LineCommand::kEmergencyStop;
    bool fire = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return firePending_ || armPending_ || quit_; });
      if (!firePending_ && quit_) return;  // nothing left to send
      fire = firePending_;
      address = fire ? fireAddress_ : armAddress_;
      requested = requested_;
      command = fireCommand_;
      (fire ? firePending_ : armPending_) = false;
    }
    if (!fire) {
      rearm(address);
      continue;
    }
    const EmergencyOutcome outcome = send(address, requested, command);
    if (done_) done_(outcome);
    // The link that carried it is closed (an answer to its confirmation may
    // still come); a fresh one is armed unless a fire comes first.
    std::lock_guard<std::mutex> lock(mutex_);
    if (!armAddress_.empty()) armPending_ = true;
  }
}

void EmergencyLine::rearm(const std::string& address) {
  if (link_ && linkAddress_ == address && !address.empty() && stillOpen(*link_)) return;
  link_.reset();
  linkAddress_.clear();
  if (!address.empty()) {
    auto opened = openTransport(address, options_.baud, options_.connectTimeout, options_.writeTimeout);
    if (opened) {
      link_ = std::move(*opened);
      linkAddress_ = address;
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  armedAt_ = linkAddress_;
}

EmergencyOutcome EmergencyLine::send(const std::string& address, Clock::time_point requested, LineCommand command) {
  EmergencyOutcome out;
  out.command = command;
  if (link_ && linkAddress_ == address && stillOpen(*link_)) {
    out.address = address;
    out.armedLink = true;
    writeAndConfirm(*link_, options_, requested, out);
  }
  link_.reset();
  linkAddress_.clear();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    armedAt_.clear();
  }
  // Not armed there, or the armed link failed on the write: a link of its own, now.
  if (!out.sent) {
    const std::string armedWhy = out.why;
    out = sendEmergencyStop(address, options_, requested, command);
    if (!armedWhy.empty() && !out.sent) out.why = armedWhy + "; then " + out.why;
  }
  return out;
}

}  // namespace fog::table
