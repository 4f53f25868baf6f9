#include "core/table/remote_table.h"

#include <cmath>

#include "core/table/scpi.h"

namespace fog::table {

namespace {

using Clock = std::chrono::steady_clock;

std::string axisWord(Axis a) { return axisLabel(a); }

Result<AxisMode> parseMode(const std::string& word) {
  if (word == "REST") return AxisMode::kRest;
  if (word == "POS") return AxisMode::kPositioning;
  if (word == "SWING") return AxisMode::kSwinging;
  if (word == "STOP") return AxisMode::kStopping;
  if (word == "ESTOP") return AxisMode::kEmergencyStop;
  return corruptData("unknown axis mode '" + word.substr(0, 20) + "'");
}

}  // namespace

RemoteTable::RemoteTable(std::unique_ptr<ByteTransport> link, RemoteOptions options, TableLogFn log)
    : link_(std::move(link)), options_(options), log_(std::move(log)) {}

Result<std::unique_ptr<RemoteTable>> RemoteTable::connect(std::unique_ptr<ByteTransport> link, RemoteOptions options,
                                                          TableLogFn log) {
  std::unique_ptr<RemoteTable> t(new RemoteTable(std::move(link), options, std::move(log)));
  FOG_ASSIGN_OR_RETURN(auto id, t->query("*IDN?"));
  if (scpi::splitFields(id).size() != 4)
    return corruptData("the table controller at " + t->link_->description() + " answered *IDN? with '" +
                       id.substr(0, 80) + "', not MAKER,MODEL,SERIAL,VERSION; is it a table controller?");
  t->identity_ = id;
  // *CLS takes no confirmation query of its own: it empties the queue.
  FOG_RETURN_IF_ERROR(t->send("*CLS", false));
  FOG_RETURN_IF_ERROR(t->command("SYST:HEART:TIM " + scpi::formatNumber(options.heartbeatTimeoutS)));
  return t;
}

std::string RemoteTable::description() const {
  return "remote " + link_->description() + (identity_.empty() ? "" : " (" + identity_ + ")");
}

void RemoteTable::note(const std::string& kind, const std::string& text, bool quiet) {
  if (log_ && !quiet) log_(kind, text);
}

Status RemoteTable::outOfStep(Status why) {
  broken_ = Status(why.code(), why.message() + "; the table link is out of step");
  note("event", broken_.message(), false);
  return broken_;
}

Status RemoteTable::send(const std::string& line, bool quiet) {
  if (!broken_.isOk()) return broken_;
  note("command", line, quiet);
  if (auto s = link_->write(line + "\n"); !s.isOk()) return outOfStep(s);
  return Status::ok();
}

Result<std::string> RemoteTable::readLine(const std::string& forWhat) {
  const auto giveUp = Clock::now() + options_.replyTimeout;
  for (;;) {
    const auto nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      std::string line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      for (char c : line) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u >= 0x7f)
          return outOfStep(corruptData("the table controller's reply to '" + forWhat +
                                       "' holds a control or non-ASCII byte"));
      }
      return line;
    }
    if (buffer_.size() > scpi::kMaxLineBytes)
      return outOfStep(corruptData("the table controller's reply to '" + forWhat + "' is longer than " +
                                   std::to_string(scpi::kMaxLineBytes) + " bytes without a line end"));
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(giveUp - Clock::now());
    if (left.count() <= 0)
      return outOfStep(ioError("no reply from the table controller at " + link_->description() + " to '" + forWhat +
                               "' within " + std::to_string(options_.replyTimeout.count()) + " ms"));
    auto got = link_->read(buffer_, left);
    if (!got) return outOfStep(got.status());
  }
}

Result<std::string> RemoteTable::query(const std::string& line, bool quiet) {
  FOG_RETURN_IF_ERROR(send(line, quiet));
  FOG_ASSIGN_OR_RETURN(auto reply, readLine(line));
  note("reply", reply, quiet);
  return reply;
}

Status RemoteTable::command(const std::string& line, bool quiet) {
  FOG_RETURN_IF_ERROR(send(line, quiet));
  // Every command is confirmed through the error queue.
  FOG_RETURN_IF_ERROR(send("SYST:ERR?", true));
  FOG_ASSIGN_OR_RETURN(auto reply, readLine(line + "; SYST:ERR?"));
  auto entry = scpi::parseError(reply);
  if (!entry)
    return outOfStep(corruptData("the table controller's reply to 'SYST:ERR?' after '" + line +
                                 "': " + entry.status().message()));
  if (entry->code == scpi::kNoError) return Status::ok();
  if (quiet) note("command", line, false);  // a quiet command that failed is logged after all
  note("reply", reply, false);
  // Drain the queue (bounded) so the next command starts clean.
  std::string more;
  for (int i = 0; i < 32; ++i) {
    FOG_RETURN_IF_ERROR(send("SYST:ERR?", true));
    FOG_ASSIGN_OR_RETURN(auto next, readLine("SYST:ERR?"));
    auto e = scpi::parseError(next);
    if (!e) return outOfStep(corruptData("the table controller's reply to 'SYST:ERR?': " + e.status().message()));
    if (e->code == scpi::kNoError) break;
    note("reply", next, false);
    more += "; then " + next;
  }
  const StatusCode code = entry->code == scpi::kDataOutOfRange ? StatusCode::kOutOfRange : StatusCode::kInvalidArgument;
  return Status(code, "the table controller refused '" + line + "': " + reply + more);
}

Result<std::string> RemoteTable::identify() {
  FOG_ASSIGN_OR_RETURN(auto id, query("*IDN?"));
  identity_ = id;
  return id;
}

Result<TableLimits> RemoteTable::limits() {
  TableLimits l;
  for (int a = 0; a < kAxisCount; ++a) {
    const std::string q = "AXIS:" + axisWord(static_cast<Axis>(a)) + ":LIM?";
    FOG_ASSIGN_OR_RETURN(auto reply, query(q));
    auto v = scpi::numbers(reply, 5);
    if (!v) return outOfStep(corruptData("the table controller's reply to '" + q + "': " + v.status().message()));
    auto& ax = l.axes[static_cast<std::size_t>(a)];
    ax.maxAmplitudeDeg = (*v)[0];
    ax.maxFrequencyHz = (*v)[1];
    ax.maxRateDegPerS = (*v)[2];
    ax.maxAccelDegPerS2 = (*v)[3];
    l.maxPositionDeg = a == 0 ? (*v)[4] : std::min(l.maxPositionDeg, (*v)[4]);
    for (double x : *v)
      if (!(x > 0.0)) return outOfStep(corruptData("the table controller's reply to '" + q + "' ('" + reply +
                                                   "') holds a limit that is not > 0"));
  }
  return l;
}

Result<TableState> RemoteTable::state() {
  TableState s;
  FOG_ASSIGN_OR_RETURN(auto sys, query("SYST:STAT?", true));
  const auto f = scpi::splitFields(sys);
  auto flag = [&](const std::string& v) -> Result<bool> {
    if (v == "0") return false;
    if (v == "1") return true;
    return corruptData("'" + v.substr(0, 20) + "' is not 0 or 1");
  };
  if (f.size() != 4) return outOfStep(corruptData("the table controller's reply to 'SYST:STAT?' ('" + sys.substr(0, 80) +
                                                  "') is not INTERLOCK,ESTOP,HEARTBEAT_LOST,FAULTS"));
  auto i = flag(f[0]), e = flag(f[1]), h = flag(f[2]);
  for (auto* r : {&i, &e, &h})
    if (!*r) return outOfStep(corruptData("the table controller's reply to 'SYST:STAT?' ('" + sys.substr(0, 80) +
                                          "'): " + r->status().message()));
  s.interlockOpen = *i;
  s.emergencyStopped = *e;
  s.heartbeatLost = *h;
  if (f[3] != "NONE") {
    std::size_t from = 0;
    for (;;) {
      const auto plus = f[3].find('+', from);
      s.faults.push_back(f[3].substr(from, plus == std::string::npos ? std::string::npos : plus - from));
      if (plus == std::string::npos) break;
      from = plus + 1;
    }
  }
  std::string summary = sys;
  for (int a = 0; a < kAxisCount; ++a) {
    const std::string q = "AXIS:" + axisWord(static_cast<Axis>(a)) + ":STAT?";
    FOG_ASSIGN_OR_RETURN(auto reply, query(q, true));
    const auto fields = scpi::splitFields(reply);
    if (fields.size() != 3)
      return outOfStep(corruptData("the table controller's reply to '" + q + "' ('" + reply.substr(0, 80) +
                                   "') is not MODE,POSITION_DEG,RATE_DEG_S"));
    auto mode = parseMode(fields[0]);
    auto pos = scpi::number(fields[1]);
    auto rate = scpi::number(fields[2]);
    if (!mode || !pos || !rate)
      return outOfStep(corruptData("the table controller's reply to '" + q + "' ('" + reply.substr(0, 80) + "'): " +
                                   (!mode ? mode.status() : !pos ? pos.status() : rate.status()).message()));
    auto& ax = s.axes[static_cast<std::size_t>(a)];
    ax.mode = *mode;
    ax.positionDeg = *pos;
    ax.rateDegPerS = *rate;
    summary += std::string("; ") + axisLabel(static_cast<Axis>(a)) + " " + fields[0];
  }
  // The status log: one line whenever modes, flags or faults change.
  if (summary != lastStatusLine_) {
    lastStatusLine_ = summary;
    std::string line = "interlock " + f[0] + ", estop " + f[1] + ", heartbeat lost " + f[2] + ", faults " + f[3];
    for (int a = 0; a < kAxisCount; ++a) {
      const auto& ax = s.axes[static_cast<std::size_t>(a)];
      line += std::string("; ") + axisLabel(static_cast<Axis>(a)) + " " + axisModeName(ax.mode) + " " +
              scpi::formatNumber(ax.positionDeg) + " deg " + scpi::formatNumber(ax.rateDegPerS) + " deg/s";
    }
    note("status", line, false);
  }
  return s;
}

Status RemoteTable::configureSwing(Axis axis, const SwingSpec& swing) {
  // The start phase is sent only when the plan sets one, so a controller
  // that knows only F,A,C runs every plan without phases.
  std::string line = "AXIS:" + axisWord(axis) + ":SWING " + scpi::formatNumber(swing.frequencyHz) + "," +
                     scpi::formatNumber(swing.amplitudeDeg) + "," + scpi::formatNumber(swing.centreDeg);
  if (swing.startPhaseDeg != 0.0) {
    line += ',';
    line += scpi::formatNumber(swing.startPhaseDeg);
  }
  return command(line);
}
Status RemoteTable::moveTo(Axis axis, double positionDeg) {
  return command("AXIS:" + axisWord(axis) + ":POS " + scpi::formatNumber(positionDeg));
}
Status RemoteTable::startSwing(Axis axis) { return command("AXIS:" + axisWord(axis) + ":START"); }
Status RemoteTable::stop(Axis axis) { return command("AXIS:" + axisWord(axis) + ":STOP"); }

Status RemoteTable::stopAll() {
  if (!broken_.isOk()) {
    // Last resort: the command goes out unconfirmed (the reply stream is out of step).
    if (link_->write("STOP\n").isOk()) note("command", "STOP (unconfirmed: the link is out of step)", false);
    return broken_;
  }
  return command("STOP");
}

Status RemoteTable::emergencyStop() {
  if (!broken_.isOk()) {
    if (link_->write("SYST:ESTOP\n").isOk()) note("command", "SYST:ESTOP (unconfirmed: the link is out of step)", false);
    return broken_;
  }
  return command("SYST:ESTOP");
}

Status RemoteTable::keepAlive() { return command("SYST:HEART", true); }

Status RemoteTable::release() { return command("SYST:HEART:TIM 0"); }

double RemoteTable::swingRampS(const SwingSpec& swing) const {
  return swing.frequencyHz > 0.0 && std::isfinite(swing.frequencyHz) ? 1.0 / swing.frequencyHz : 0.0;
}

}  // namespace fog::table
