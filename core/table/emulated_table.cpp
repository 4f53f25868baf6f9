#include "core/table/emulated_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/units.h"

namespace fog::table {

namespace {
constexpr double kForever = std::numeric_limits<double>::infinity();
double sgn(double v) { return v < 0.0 ? -1.0 : 1.0; }
std::size_t ix(Axis a) { return static_cast<std::size_t>(a); }
}  // namespace

double EmulatedTable::Piece::duration() const {
  switch (kind) {
    case kMove: {
      const double d = std::abs(p1 - p0);
      if (d == 0.0) return 0.0;
      const double ta = v / a;
      return 2.0 * ta + std::max(0.0, d - v * v / a) / v;
    }
    case kStop: return std::abs(v) / a;
    default: return kForever;
  }
}

double EmulatedTable::Piece::ref(double t) const {
  const double dt = std::max(0.0, t - t0);
  switch (kind) {
    case kHold: return p0;
    case kMove: {
      const double d = p1 - p0, s = sgn(d), D = std::abs(d);
      if (D == 0.0) return p0;
      const double ta = v / a, total = duration(), tc = total - 2.0 * ta;
      if (dt >= total) return p1;
      if (dt < ta) return p0 + s * 0.5 * a * dt * dt;
      if (dt < ta + tc) return p0 + s * (0.5 * a * ta * ta + v * (dt - ta));
      const double dd = total - dt;
      return p1 - s * 0.5 * a * dd * dd;
    }
    case kSwing: {
      const double x = ramp > 0.0 ? std::min(1.0, dt / ramp) : 1.0;
      const double g = x * x * (3.0 - 2.0 * x);
      return p0 + amp * g * std::sin(w * dt + phase);
    }
    case kStop: {
      const double T = duration();
      const double tt = std::min(dt, T);
      return p0 + v * tt - sgn(v) * 0.5 * a * tt * tt;
    }
  }
  return p0;
}

double EmulatedTable::Piece::refRate(double t) const {
  const double dt = std::max(0.0, t - t0);
  switch (kind) {
    case kHold: return 0.0;
    case kMove: {
      const double d = p1 - p0, s = sgn(d);
      if (d == 0.0) return 0.0;
      const double ta = v / a, total = duration(), tc = total - 2.0 * ta;
      if (dt >= total) return 0.0;
      if (dt < ta) return s * a * dt;
      if (dt < ta + tc) return s * v;
      return s * a * (total - dt);
    }
    case kSwing: {
      const bool ramping = ramp > 0.0 && dt < ramp;
      const double x = ramping ? dt / ramp : 1.0;
      const double g = x * x * (3.0 - 2.0 * x);
      const double dg = ramping ? 6.0 * x * (1.0 - x) / ramp : 0.0;
      return amp * (dg * std::sin(w * dt + phase) + g * w * std::cos(w * dt + phase));
    }
    case kStop: {
      const double T = duration();
      return dt >= T ? 0.0 : v - sgn(v) * a * dt;
    }
  }
  return 0.0;
}

EmulatedTable::EmulatedTable(EmulatedTableParams params) : params_(params) {
  for (auto& list : pieces_) list.push_back(Piece{});
}

const EmulatedTable::Piece& EmulatedTable::pieceAt(Axis axis, double t) const {
  const auto& list = pieces_[ix(axis)];
  for (auto it = list.rbegin(); it != list.rend(); ++it)
    if (it->t0 <= t) return *it;
  return list.front();
}

void EmulatedTable::push(Axis axis, Piece p) {
  auto& list = pieces_[ix(axis)];
  list.push_back(p);
  // History needed: back to the servo lag plus what a board looks into the past.
  while (list.size() > 16) list.pop_front();
}

double EmulatedTable::angleDeg(Axis axis, double t) const {
  const double tr = t - params_.servoLagS;
  return pieceAt(axis, tr).ref(tr);
}

double EmulatedTable::rateDegPerS(Axis axis, double t) const {
  const double tr = t - params_.servoLagS;
  return pieceAt(axis, tr).refRate(tr);
}

AxisMode EmulatedTable::mode(Axis axis, double t) const {
  // The commanded reference's mode, as a controller reports it: an axis told
  // to swing reports SWING at once, not a servo lag later.
  const Piece& p = pieceAt(axis, t);
  const bool moving = t - p.t0 < p.duration();
  switch (p.kind) {
    case Piece::kHold: return emergency_[ix(axis)] ? AxisMode::kEmergencyStop : AxisMode::kRest;
    case Piece::kMove: return moving ? AxisMode::kPositioning : AxisMode::kRest;
    case Piece::kSwing: return AxisMode::kSwinging;
    case Piece::kStop:
      if (emergency_[ix(axis)]) return AxisMode::kEmergencyStop;
      return moving ? AxisMode::kStopping : AxisMode::kRest;
  }
  return AxisMode::kUnknown;
}

Status EmulatedTable::moveTo(Axis axis, double positionDeg, double t) {
  const Piece& cur = pieceAt(axis, t);
  if (std::abs(cur.refRate(t)) > 0.0 || cur.kind == Piece::kSwing)
    return Status(StatusCode::kInvalidArgument, std::string("axis ") + axisLabel(axis) + " is moving; stop it first");
  if (std::abs(positionDeg) > params_.limits.maxPositionDeg)
    return outOfRange("position beyond the table's range");
  Piece p;
  p.kind = Piece::kMove;
  p.t0 = t;
  p.p0 = cur.ref(t);
  p.p1 = positionDeg;
  p.a = params_.positionAccelDegPerS2;
  const double D = std::abs(p.p1 - p.p0);
  p.v = std::min(params_.positionRateDegPerS, std::sqrt(D * p.a));
  if (p.v <= 0.0) {
    p.kind = Piece::kHold;
    p.p0 = positionDeg;
  }
  push(axis, p);
  return Status::ok();
}

Status EmulatedTable::startSwing(Axis axis, const SwingSpec& s, double t) {
  const Piece& cur = pieceAt(axis, t);
  if (std::abs(cur.refRate(t)) > 0.0 || cur.kind == Piece::kSwing)
    return Status(StatusCode::kInvalidArgument, std::string("axis ") + axisLabel(axis) + " is moving; stop it first");
  if (std::abs(cur.ref(t) - s.centreDeg) > 1e-6)
    return Status(StatusCode::kInvalidArgument,
                  std::string("axis ") + axisLabel(axis) + " is not at the swing centre; position it first");
  Piece p;
  p.kind = Piece::kSwing;
  p.t0 = t;
  p.p0 = s.centreDeg;
  p.amp = s.amplitudeDeg;
  p.w = kTwoPi * s.frequencyHz;
  p.ramp = std::max(1.0, std::ceil(params_.rampPeriods)) / s.frequencyHz;
  p.phase = s.startPhaseDeg * kTwoPi / 360.0;
  push(axis, p);
  return Status::ok();
}

void EmulatedTable::stop(Axis axis, double t, double accel) {
  const Piece& cur = pieceAt(axis, t);
  Piece p;
  p.t0 = t;
  p.p0 = cur.ref(t);
  p.v = cur.refRate(t);
  if (p.v == 0.0) {
    p.kind = Piece::kHold;
  } else {
    p.kind = Piece::kStop;
    p.a = accel;
  }
  push(axis, p);
}

// ---------------------------------------------------------------------------

TableServer::TableServer(EmulatedTable& table, ServerFaults faults, std::string identity)
    : table_(table), faults_(std::move(faults)), identity_(std::move(identity)) {}

void TableServer::pushError(int code, const std::string& text) {
  if (errors_.size() >= 16) {
    errors_.back() = {scpi::kQueueOverflow, scpi::standardErrorText(scpi::kQueueOverflow)};
    return;
  }
  errors_.emplace_back(code, text.empty() ? std::string(scpi::standardErrorText(code))
                                          : std::string(scpi::standardErrorText(code)) + "; " + text);
}

std::string TableServer::blocked() const {
  if (estop_) return "emergency stop engaged";
  if (interlockOpen_) return "interlock open";
  if (heartbeatLost_) return "heartbeat lost";
  return {};
}

void TableServer::stopAll(double t, double accel) {
  for (int a = 0; a < kAxisCount; ++a) table_.stop(static_cast<Axis>(a), t, accel);
}

void TableServer::tick(double tableS, double wallS) {
  if (heartbeatTimeoutS_ > 0.0 && !heartbeatLost_ && wallS - lastLineWallS_ > heartbeatTimeoutS_) {
    heartbeatLost_ = true;
    stopAll(tableS, table_.params().stopAccelDegPerS2);
    pushError(scpi::kHeartbeatLost, "the host was quiet for more than " + scpi::formatNumber(heartbeatTimeoutS_) +
                                        " s; table brought to rest");
    event("heartbeat: host quiet for more than " + scpi::formatNumber(heartbeatTimeoutS_) +
          " s; table brought to rest at table time " + scpi::formatNumber(tableS) + " s");
  }
  if (faults_.interlockAfterStartS >= 0.0 && firstSwingS_ >= 0.0 && !interlockDone_ && !interlockOpen_ &&
      tableS >= firstSwingS_ + faults_.interlockAfterStartS) {
    interlockOpen_ = true;
    stopAll(tableS, table_.params().emergencyAccelDegPerS2);
    pushError(scpi::kInterlockOpen, "tripped; table stopped");
    event("interlock: tripped at table time " + scpi::formatNumber(tableS) + " s; table stopped");
  }
  if (interlockOpen_ && tableS >= firstSwingS_ + faults_.interlockAfterStartS + faults_.interlockForS) {
    interlockOpen_ = false;
    interlockDone_ = true;
    event("interlock: closed again at table time " + scpi::formatNumber(tableS) + " s");
  }
}

std::optional<std::string> TableServer::handleLine(const std::string& line, double tableS, double wallS) {
  lastLineWallS_ = wallS;  // any line is a sign of life
  auto parsed = scpi::parseLine(line);
  if (!parsed) {
    pushError(scpi::kSyntaxError, parsed.status().message());
    return std::nullopt;
  }
  const auto& c = *parsed;
  std::string header;
  for (const auto& k : c.keywords) header += (header.empty() ? "" : ":") + k;
  if (!faults_.refuseHeader.empty() && refusedSoFar_ < faults_.refuseCount) {
    std::string want = faults_.refuseHeader;
    for (char& ch : want) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    if (header == want) {
      ++refusedSoFar_;
      pushError(scpi::kRefusedByController, header + " refused (injected fault)");
      event("refused: " + c.text);
      return c.query ? std::optional<std::string>("") : std::nullopt;
    }
  }
  return execute(c, tableS);
}

namespace {

Axis axisOf(const scpi::Command& c) {
  return c.keywords[1] == "X" ? Axis::kX : c.keywords[1] == "Y" ? Axis::kY : Axis::kZ;
}

bool isAxisCommand(const scpi::Command& c) {
  return c.keywords.size() == 3 && scpi::keywordIs(c.keywords[0], "AXIS") &&
         scpi::matches(c, "AXIS:#:" + c.keywords[2]);
}

const char* modeWord(AxisMode m) {
  switch (m) {
    case AxisMode::kRest: return "REST";
    case AxisMode::kPositioning: return "POS";
    case AxisMode::kSwinging: return "SWING";
    case AxisMode::kStopping: return "STOP";
    case AxisMode::kEmergencyStop: return "ESTOP";
    default: return "REST";
  }
}

// Why a swing cannot be configured on an axis with these limits, or "".
std::string swingRefusal(const auto& L, const auto& l, double f, double amp, double centre, double phase) {
  const double w = kTwoPi * f;
  if (!(f > 0.0) || !(amp > 0.0)) return "frequency and amplitude must be > 0";
  if (!(phase > -360.0 && phase < 360.0)) return "start phase must be within -360 .. 360 deg";
  if (amp > l.maxAmplitudeDeg) return "amplitude beyond " + scpi::formatNumber(l.maxAmplitudeDeg) + " deg";
  if (f > l.maxFrequencyHz) return "frequency beyond " + scpi::formatNumber(l.maxFrequencyHz) + " Hz";
  if (w * amp > l.maxRateDegPerS) return "peak rate beyond " + scpi::formatNumber(l.maxRateDegPerS) + " deg/s";
  if (w * w * amp > l.maxAccelDegPerS2)
    return "peak acceleration beyond " + scpi::formatNumber(l.maxAccelDegPerS2) + " deg/s^2";
  if (std::abs(centre) + amp > L.maxPositionDeg) return "swing leaves the position range";
  return {};
}

}  // namespace

bool TableServer::wantArgs(const scpi::Command& c, std::size_t n) {
  if (c.args.size() < n) {
    pushError(scpi::kMissingParameter);
    return false;
  }
  if (c.args.size() > n) {
    pushError(scpi::kParameterNotAllowed);
    return false;
  }
  return true;
}

bool TableServer::numbers(const scpi::Command& c, std::vector<double>& out) {
  for (const auto& a : c.args) {
    auto v = scpi::number(a);
    if (!v) {
      pushError(scpi::kDataOutOfRange, v.status().message());
      return false;
    }
    out.push_back(*v);
  }
  return true;
}

std::optional<std::string> TableServer::execute(const scpi::Command& c, double t) {
  if (c.query) return query(c, t);
  if (systemCommand(c, t)) return std::nullopt;
  if (isAxisCommand(c) && axisCommand(c, t)) return std::nullopt;
  pushError(scpi::kUndefinedHeader, c.text);
  return std::nullopt;
}

std::string TableServer::query(const scpi::Command& c, double t) {
  using scpi::matches;
  if (!c.args.empty()) {
    pushError(scpi::kParameterNotAllowed);
    return std::string();
  }
  if (matches(c, "*IDN")) return identity_;
  if (matches(c, "*OPC")) return std::string("1");
  if (matches(c, "SYSTem:ERRor[:NEXT]")) {
    if (errors_.empty()) return scpi::formatError(0, "No error");
    auto e = errors_.front();
    errors_.pop_front();
    return scpi::formatError(e.first, e.second);
  }
  if (matches(c, "SYSTem:HEARTbeat:TIMeout")) return scpi::formatNumber(heartbeatTimeoutS_);
  if (matches(c, "SYSTem:STATus")) {
    return std::string(interlockOpen_ ? "1" : "0") + "," + (estop_ ? "1" : "0") + "," + (heartbeatLost_ ? "1" : "0") +
           ",NONE";
  }
  if (isAxisCommand(c)) {
    const auto& L = table_.params().limits;
    const Axis a = axisOf(c);
    const auto& l = L.axes[static_cast<std::size_t>(a)];
    if (matches(c, "AXIS:#:POSition")) return scpi::formatNumber(table_.angleDeg(a, t));
    if (matches(c, "AXIS:#:RATE")) return scpi::formatNumber(table_.rateDegPerS(a, t));
    if (matches(c, "AXIS:#:MODE")) return std::string(modeWord(table_.mode(a, t)));
    if (matches(c, "AXIS:#:STATe"))
      return std::string(modeWord(table_.mode(a, t))) + "," + scpi::formatNumber(table_.angleDeg(a, t)) + "," +
             scpi::formatNumber(table_.rateDegPerS(a, t));
    if (matches(c, "AXIS:#:LIMits"))
      return scpi::formatNumber(l.maxAmplitudeDeg) + "," + scpi::formatNumber(l.maxFrequencyHz) + "," +
             scpi::formatNumber(l.maxRateDegPerS) + "," + scpi::formatNumber(l.maxAccelDegPerS2) + "," +
             scpi::formatNumber(L.maxPositionDeg);
    if (matches(c, "AXIS:#:SWING")) {
      const auto& s = swings_[static_cast<std::size_t>(a)];
      if (!s) return std::string("0,0,0,0");
      return scpi::formatNumber(s->frequencyHz) + "," + scpi::formatNumber(s->amplitudeDeg) + "," +
             scpi::formatNumber(s->centreDeg) + "," + scpi::formatNumber(s->startPhaseDeg);
    }
  }
  pushError(scpi::kUndefinedHeader, c.text);
  return std::string();  // an empty line: the query has no answer (the error queue says why)
}

bool TableServer::systemCommand(const scpi::Command& c, double t) {
  using scpi::matches;
  if (matches(c, "*RST")) {
    if (!wantArgs(c, 0)) return true;
    stopAll(t, table_.params().stopAccelDegPerS2);
    swings_ = {};
    heartbeatTimeoutS_ = 0.0;
    return true;
  }
  if (matches(c, "*CLS")) {
    if (!wantArgs(c, 0)) return true;
    errors_.clear();
    heartbeatLost_ = false;
    return true;
  }
  if (matches(c, "SYSTem:HEARTbeat")) {
    wantArgs(c, 0);
    return true;
  }
  if (matches(c, "SYSTem:HEARTbeat:TIMeout")) {
    std::vector<double> v;
    if (!wantArgs(c, 1) || !numbers(c, v)) return true;
    if (v[0] < 0.0 || v[0] > 3600.0) {
      pushError(scpi::kDataOutOfRange, "heartbeat timeout must be 0 .. 3600 s");
      return true;
    }
    heartbeatTimeoutS_ = v[0];
    return true;
  }
  if (matches(c, "STOP")) {
    if (wantArgs(c, 0)) stopAll(t, table_.params().stopAccelDegPerS2);
    return true;
  }
  if (matches(c, "SYSTem:ESTOP")) {
    if (!wantArgs(c, 0)) return true;
    estop_ = true;
    stopAll(t, table_.params().emergencyAccelDegPerS2);
    for (int a = 0; a < kAxisCount; ++a) table_.markEmergency(static_cast<Axis>(a), true);
    event("estop: engaged at table time " + scpi::formatNumber(t) + " s");
    return true;
  }
  if (matches(c, "SYSTem:ESTOP:RESet")) {
    if (!wantArgs(c, 0)) return true;
    for (int a = 0; a < kAxisCount; ++a)
      if (std::abs(table_.rateDegPerS(static_cast<Axis>(a), t)) > 0.0) {
        pushError(scpi::kSettingsConflict, "the table is still moving");
        return true;
      }
    estop_ = false;
    for (int a = 0; a < kAxisCount; ++a) table_.markEmergency(static_cast<Axis>(a), false);
    return true;
  }
  return false;
}

bool TableServer::axisCommand(const scpi::Command& c, double t) {
  using scpi::matches;
  const auto& L = table_.params().limits;
  const Axis a = axisOf(c);
  const auto& l = L.axes[static_cast<std::size_t>(a)];
  const auto refuseMotion = [&] {
    if (blocked().empty()) return false;
    pushError(estop_ ? scpi::kEmergencyStop : interlockOpen_ ? scpi::kInterlockOpen : scpi::kHeartbeatLost);
    return true;
  };
  if (matches(c, "AXIS:#:STOP")) {
    if (wantArgs(c, 0)) table_.stop(a, t, table_.params().stopAccelDegPerS2);
    return true;
  }
  if (matches(c, "AXIS:#:SWING")) {
    std::vector<double> v;
    // F,A,C or F,A,C,PHASE (the start phase, deg; 0 when left out).
    if (!wantArgs(c, c.args.size() == 4 ? 4 : 3) || !numbers(c, v)) return true;
    const double phase = v.size() == 4 ? v[3] : 0.0;
    if (auto why = swingRefusal(L, l, v[0], v[1], v[2], phase); !why.empty()) {
      pushError(scpi::kDataOutOfRange, why);
      return true;
    }
    swings_[static_cast<std::size_t>(a)] = SwingSpec{v[0], v[1], v[2], phase};
    return true;
  }
  if (matches(c, "AXIS:#:POSition")) {
    std::vector<double> v;
    if (!wantArgs(c, 1) || !numbers(c, v) || refuseMotion()) return true;
    if (auto s = table_.moveTo(a, v[0], t); !s.isOk())
      pushError(s.code() == StatusCode::kOutOfRange ? scpi::kDataOutOfRange : scpi::kSettingsConflict, s.message());
    return true;
  }
  if (matches(c, "AXIS:#:START")) {
    if (!wantArgs(c, 0) || refuseMotion()) return true;
    const auto& s = swings_[static_cast<std::size_t>(a)];
    if (!s) {
      pushError(scpi::kSettingsConflict, "no swing configured (AXIS:" + c.keywords[1] + ":SWING)");
      return true;
    }
    if (auto st = table_.startSwing(a, *s, t); !st.isOk()) {
      pushError(scpi::kSettingsConflict, st.message());
      return true;
    }
    if (firstSwingS_ < 0.0) firstSwingS_ = t;
    ++swingsStarted_;
    event("swing: " + std::string(axisLabel(a)) + " " + scpi::formatNumber(s->frequencyHz) + " Hz " +
          scpi::formatNumber(s->amplitudeDeg) + " deg about " + scpi::formatNumber(s->centreDeg) + " deg" +
          (s->startPhaseDeg != 0.0 ? " phase " + scpi::formatNumber(s->startPhaseDeg) + " deg" : std::string()) +
          " started at table time " + scpi::formatNumber(t) + " s");
    return true;
  }
  return false;
}

}  // namespace fog::table
