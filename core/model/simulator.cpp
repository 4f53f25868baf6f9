#include "core/model/simulator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/common/units.h"
#include "core/model/attitude.h"
#include "core/model/gyro_filters.h"
#include "core/model/random.h"
#include "core/protocol/frame.h"

namespace fog::model {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The noise of one axis' FOG: bias, angle random walk and a Gauss-Markov
// bias wander, as an angle; the pulse count of its output.
struct GyroChannel {
  double constantRateDegPerS = 0.0;
  double arwDegPerSqrtS = 0.0;
  double wanderSigmaDegPerS = 0.0;
  double wanderCorrelationS = 1.0;

  double lastTimeS = 0.0;
  double arwAngleDeg = 0.0;     // Wiener process
  double wanderRateDegPerS = 0.0;
  double wanderAngleDeg = 0.0;  // integral of the wander rate
  std::int64_t lastCount = 0;

  // Noise angle at t (t increasing between calls): exact Wiener increments and
  // an exact Gauss-Markov update; the wander integral uses the rate at the
  // start of each 2 ms interval, accurate for correlation times of seconds.
  double noiseAngleDeg(double t, Random& rng) {
    const double dt = t - lastTimeS;
    if (dt > 0.0) {
      // The step's factors depend on dt alone. dt is a difference of two
      // stamps k P + c, so it takes a few values an ulp apart (the stamps'
      // rounding), not one: the factors of the last kSteps distinct dt are
      // kept and reused when dt is one of them exactly (bit for bit the same
      // values; an exp and two square roots per axis and sample were a tenth
      // of a diagnosis' replays).
      const Step& f = factorsFor(dt);
      arwAngleDeg += f.arwDeg * rng.normal();
      wanderAngleDeg += wanderRateDegPerS * dt;
      wanderRateDegPerS = wanderRateDegPerS * f.decay + f.wanderDegPerS * rng.normal();
      lastTimeS = t;
    }
    return constantRateDegPerS * t + arwAngleDeg + wanderAngleDeg;
  }

 private:
  struct Step {
    double dt = NAN;  // the step these factors are for (NaN: none yet)
    double arwDeg = 0.0, decay = 1.0, wanderDegPerS = 0.0;
  };
  static constexpr int kSteps = 8;

  const Step& factorsFor(double dt) {
    for (const Step& s : steps)
      if (s.dt == dt) return s;
    Step& s = steps[nextStep];
    nextStep = (nextStep + 1) % kSteps;
    s.dt = dt;
    s.arwDeg = arwDegPerSqrtS * std::sqrt(dt);
    s.decay = std::exp(-dt / wanderCorrelationS);
    s.wanderDegPerS = wanderSigmaDegPerS * std::sqrt(1.0 - s.decay * s.decay);
    return s;
  }

  std::array<Step, kSteps> steps{};
  int nextStep = 0;  // the entry the next new step replaces (oldest first)
};

std::uint32_t toCounter(double stampS, const SamplingBoardParams& b) {
  // The counter floors true time; the tiny offset keeps instants that fall
  // exactly on a tick (k * 1 ms) from landing one tick early through rounding.
  const double ticks = std::floor(std::max(stampS, 0.0) * b.counterHz + 1e-6);
  const std::uint64_t raw = static_cast<std::uint64_t>(ticks) + b.counterStart;
  const std::uint64_t mask = b.counterBits >= 64 ? ~0ULL : ((1ULL << b.counterBits) - 1ULL);
  return static_cast<std::uint32_t>(raw & mask);
}

std::int32_t toMicroDeg(double deg) { return static_cast<std::int32_t>(std::llround(deg * 1e6)); }

}  // namespace

class Simulator::Impl {
 public:
  Impl(const SimConfig& config, const Turntable& table, double slackS,
       std::vector<std::unique_ptr<Effect>>& effects, MotionTape* record, const MotionTape* play)
      : c_(config), table_(table), slackS_(slackS), effects_(effects), attitude_(config.earth, config.turntable),
        noiseRng_(Random::derive(config.seed, 0)), lostRng_(Random::derive(config.seed, 1)), filters_(config.fog) {
    // A tape holds the motion as planned: one is neither played nor recorded
    // where an effect may change it.
    if (std::none_of(effects_.begin(), effects_.end(), [](const auto& e) { return e->changesTableMotion(); })) {
      play_ = play;
      record_ = play ? nullptr : record;
    }
    for (int a = 0; a < kAxisCount; ++a) {
      GyroChannel& g = gyro_[a];
      g.constantRateDegPerS = degPerHourToDegPerS(c_.fog.biasDegPerH[a]);
      g.arwDegPerSqrtS = degPerSqrtHourToDegPerSqrtS(c_.fog.arwDegPerSqrtH);
      g.wanderSigmaDegPerS = degPerHourToDegPerS(c_.fog.biasInstabilityDegPerH);
      g.wanderCorrelationS = c_.fog.biasCorrelationS;
    }
    // Effects may keep the reference reset() hands them: the streams must
    // never move, so the vector is sized before any is handed out.
    effectRngs_.reserve(effects_.size());
    for (std::size_t i = 0; i < effects_.size(); ++i) {
      effectRngs_.emplace_back(Random::derive(config.seed, 100 + i));
      effects_[i]->reset(effectRngs_.back());
    }
    // Start of the first interval: the pulse count one frame before the first.
    const double u0 = imuSenseTime(-1);
    for (int a = 0; a < kAxisCount; ++a) gyro_[a].lastTimeS = std::min(u0, latchTime(u0));
    const auto sensed = gyroOutput(u0);
    for (int a = 0; a < kAxisCount; ++a)
      gyro_[a].lastCount = static_cast<std::int64_t>(std::floor(sensed[a] / c_.fog.pulseEquivalentDeg));
    statusEvents_.reserve(table_.schedule().size() * 3);
    for (const auto& s : table_.schedule())
      for (double t : {s.swingStartS, s.recordStartS, s.recordEndS}) statusEvents_.push_back(t);
    std::sort(statusEvents_.begin(), statusEvents_.end());
    prepareTable();
    prepareImu();
  }

  // Emits frames whose stamps are below untilS, in stamp order: encoded
  // (bytes) or as they are (frames).
  //
  // Termination: every pass of the loop either returns or moves one of the
  // three streams to its next index (status, table or IMU), and each stream
  // is over once its index passes a bound fixed by the configuration
  // (tableOver(), imuOver(), nextStatusTimeS()): an effect that stamps
  // frames backwards in time (a clock drift of -100 %, issue: diagnose on a
  // jittered pendulum) or with NaN cannot make the loop emit for ever.
  template <class Out>
  void advance(double untilS, Out& out) {
    for (;;) {
      const double tStatus = nextStatusTimeS();
      const double tTable = tableOver() ? kNever : tableStampS_;
      const double tImu = imuOver() ? kNever : imuStampS_;
      const double t = std::min({tStatus, tTable, tImu});
      if (!(t < untilS) || t == kNever) return;
      if (t == tStatus) {
        emit(statusFrame(t), out);
      } else if (t == tTable) {
        // A dropped frame still uses its sequence number, as on a lossy link.
        const auto frame = writer_.numbered(toCounter(tableStampS_, c_.samplingBoard), tablePayload_);
        if (!tableDropped_) emit(frame, out);
        ++tableIndex_;
        prepareTable();
      } else {
        const auto frame = writer_.numbered(toCounter(imuStampS_, c_.samplingBoard), imuPayload_);
        if (!imuDropped_) emit(frame, out);
        ++imuIndex_;
        prepareImu();
      }
    }
  }

 private:
  std::array<double, kAxisCount> motion(double t) const {
    auto angles = table_.anglesDeg(t);
    for (const auto& e : effects_) e->onTableMotion(t, angles);
    return angles;
  }

  double imuSampleTime(std::int64_t k) const {
    return c_.imuBoard.firstSampleS + static_cast<double>(k) * c_.imuBoard.actualFramePeriodS();
  }
  // The instant whose motion the pulse register holds when sample k is taken.
  double imuSenseTime(std::int64_t k) const {
    return imuSampleTime(k) - c_.fog.sampleAfterUpdateS - c_.fog.loopDelayS();
  }

  // What the gyros sensed up to u (u increasing between calls): the body's
  // rotation from the table's motion, exact for one axis moving at a time
  // (Attitude::rotationBetweenDeg), plus the Earth rate rotated into the
  // body frame at every instant (the trapezoid rule over each frame
  // interval: for a swing at f its relative error is (2 pi f h)^2 / 12,
  // 5e-7 of a 1.9 deg/h modulation at 0.2 Hz with h = 2 ms; Simpson's rule
  // cost a fifth of a replay for nothing measurable), plus bias and noise.
  std::array<double, kAxisCount> sensedAngles(double u) {
    if (play_ && tapeMatched_) {
      if (playIndex_ < play_->senses.size() && play_->senses[playIndex_].context.timeS == u) {
        const MotionTape::Sense& s = play_->senses[playIndex_++];
        GyroContext context = s.context;
        std::array<double, kAxisCount> sensed = s.sensed;
        for (const auto& e : effects_) e->onGyroAngle(context, sensed);
        return sensed;
      }
      tapeMatched_ = false;  // another chain's tape: the state below was never kept
    }
    GyroContext context{u, motion(u)};
    const Eigen::Matrix3d bodyToTable = attitude_.bodyToTable(context.tableAngleDeg, rotations_);
    const Eigen::Vector3d earth = attitude_.earthRateBodyDegPerH(bodyToTable);
    if (sensedBefore_ && u > lastSenseS_) {
      bodyAngleDeg_ += attitude_.rotationBetweenDeg(lastBodyToTable_, bodyToTable);
      earthAngleDeg_ += degPerHourToDegPerS((u - lastSenseS_) / 2.0) * (lastEarthDegPerH_ + earth);
    }
    sensedBefore_ = true;
    lastSenseS_ = u;
    lastBodyToTable_ = bodyToTable;
    lastEarthDegPerH_ = earth;
    const Eigen::Vector3d force = attitude_.specificForceBodyG(bodyToTable);
    const Eigen::Matrix3d bodyToLocal = attitude_.bodyToLocal(bodyToTable);
    std::array<double, kAxisCount> sensed{};
    for (int a = 0; a < kAxisCount; ++a) {
      context.bodyAngleDeg[a] = bodyAngleDeg_[a];
      context.specificForceG[a] = force[a];
      for (int k = 0; k < kAxisCount; ++k) context.bodyToLocal[a][k] = bodyToLocal(a, k);
      sensed[a] = bodyAngleDeg_[a] + earthAngleDeg_[a] + gyro_[a].noiseAngleDeg(u, noiseRng_);
    }
    if (record_) record_->senses.push_back({context, sensed});
    for (const auto& e : effects_) e->onGyroAngle(context, sensed);
    return sensed;
  }

  // The last pulse-register update at or before u (u itself with the
  // register off).
  double latchTime(double u) const {
    const double p = c_.fog.registerPeriodS;
    if (!(p > 0.0)) return u;
    const double o = c_.fog.registerOffsetS;
    return o + p * std::floor((u - o) / p);
  }

  // What the board reads when it would read the angle sensed at u: the
  // rate filters' output, held since the last register update.
  std::array<double, kAxisCount> gyroOutput(double u) {
    if (!(c_.fog.registerPeriodS > 0.0) && !filters_.active()) return sensedAngles(u);
    const double t = latchTime(u);
    if (haveLatch_ && t == latchS_) return latched_;
    auto x = sensedAngles(t);
    if (filters_.active()) filters_.apply(t, x);
    haveLatch_ = true, latchS_ = t, latched_ = x;
    return x;
  }

  void prepareTable() {
    const double stamp = static_cast<double>(tableIndex_) * c_.encoder.samplePeriodS;
    const double readS = stamp - c_.encoder.readDelayS;
    std::array<double, kAxisCount> reading;
    if (play_ && tapeMatched_ && readIndex_ < play_->readings.size() && play_->readings[readIndex_].timeS == readS) {
      reading = play_->readings[readIndex_++].deg;
    } else {
      if (play_) tapeMatched_ = false;
      reading = motion(readS);
      if (const double e = c_.encoder.eccentricityPeakDeg(); e > 0.0)
        for (double& r : reading) r += e * std::sin((r + c_.encoder.eccentricityPhaseDeg) * kRadPerDeg);
      if (record_) record_->readings.push_back({readS, reading});
    }
    for (const auto& e : effects_) e->onEncoderReading(stamp - c_.encoder.readDelayS, reading);
    for (int a = 0; a < kAxisCount; ++a) {
      const double q = c_.encoder.quantumDeg;
      const double v = q > 0.0 ? std::round(reading[a] / q) * q : reading[a];
      tablePayload_.angleMicroDeg[a] = toMicroDeg(v);
    }
    tableStampS_ = stamp;
    tableDropped_ = false;
    if (c_.encoder.lostPerMille > 0.0) tableDropped_ = lostRng_.uniform() < c_.encoder.lostPerMille * 1e-3;
    for (const auto& e : effects_) e->onTableStamp(tableStampS_, tableDropped_);
  }

  void prepareImu() {
    const auto sensed = gyroOutput(imuSenseTime(imuIndex_));
    for (int a = 0; a < kAxisCount; ++a) {
      const auto count = static_cast<std::int64_t>(std::floor(sensed[a] / c_.fog.pulseEquivalentDeg));
      imuPayload_.pulses[a] = static_cast<std::int32_t>(count - gyro_[a].lastCount);
      gyro_[a].lastCount = count;
    }
    imuPayload_.temperatureCentiC = static_cast<std::int16_t>(std::lround(c_.fog.temperatureC * 100.0));
    imuStampS_ = imuSampleTime(imuIndex_) + c_.imuBoard.boardDelayS();
    imuDropped_ = false;
    for (const auto& e : effects_) e->onImuStamp(imuStampS_, imuDropped_);
  }

  // A stream is over at a stamp past the end (or not finite: an effect's
  // NaN), or at an index whose nominal instant is past the end by more than
  // the slack any real stamp error (ppm of clock drift, ms of jitter) moves
  // a frame: that bound is what Simulator::frameBound() counts.
  bool tableOver() const {
    return !(tableStampS_ <= table_.endS()) ||
           static_cast<double>(tableIndex_) * c_.encoder.samplePeriodS > table_.endS() + slackS_;
  }
  bool imuOver() const { return !(imuStampS_ <= table_.endS()) || imuSampleTime(imuIndex_) > table_.endS() + slackS_; }

  double nextStatusTimeS() const {
    const double periodic = static_cast<double>(statusIndex_) * c_.samplingBoard.statusPeriodS;
    const double event = nextEvent_ < statusEvents_.size() ? statusEvents_[nextEvent_] : kNever;
    const double t = std::min(periodic, event);
    return t <= table_.endS() ? t : kNever;
  }

  static void emit(const protocol::Frame& frame, std::vector<std::uint8_t>& out) { protocol::appendFrame(frame, out); }
  static void emit(protocol::Frame frame, std::vector<protocol::Frame>& out) { out.push_back(std::move(frame)); }

  protocol::Frame statusFrame(double t) {
    while (nextEvent_ < statusEvents_.size() && statusEvents_[nextEvent_] <= t) ++nextEvent_;
    while (static_cast<double>(statusIndex_) * c_.samplingBoard.statusPeriodS <= t) ++statusIndex_;
    protocol::StatusPayload s;
    s.counterHz = static_cast<std::uint32_t>(std::lround(c_.samplingBoard.counterHz));
    s.counterBits = static_cast<std::uint8_t>(c_.samplingBoard.counterBits);
    s.pulseEquivalentDeg = c_.fog.pulseEquivalentDeg;
    s.phase = protocol::TestPhase::kIdle;
    for (const auto& p : table_.schedule()) {
      if (!c_.samplingBoard.markTestPoints) break;
      if (t < p.swingStartS || t >= p.recordEndS) continue;
      s.testPoint = static_cast<std::uint16_t>(p.index);
      s.axis = static_cast<std::uint8_t>(p.point.axis);
      s.phase = t < p.recordStartS ? protocol::TestPhase::kSettling : protocol::TestPhase::kRecording;
      s.nominalFrequencyMicroHz = static_cast<std::uint32_t>(std::lround(p.point.frequencyHz * 1e6));
      s.nominalAmplitudeMicroDeg = static_cast<std::uint32_t>(std::lround(p.point.amplitudeDeg * 1e6));
      s.flags = p.point.isStatic() ? protocol::kStatusFlagStatic : std::uint8_t{0};
    }
    if (c_.samplingBoard.markTestPoints && s.phase == protocol::TestPhase::kIdle && !table_.schedule().empty() &&
        t >= table_.schedule().back().recordEndS)
      s.phase = protocol::TestPhase::kDone;
    return writer_.numbered(toCounter(t, c_.samplingBoard), s);
  }

  const SimConfig& c_;
  const Turntable& table_;
  MotionTape* record_ = nullptr;
  const MotionTape* play_ = nullptr;
  std::size_t playIndex_ = 0, readIndex_ = 0;
  bool tapeMatched_ = true;

 public:
  bool tapeMatched() const { return tapeMatched_; }

 private:
  const double slackS_;  // Simulator::streamSlackS()
  std::vector<std::unique_ptr<Effect>>& effects_;
  Attitude attitude_;
  AxisRotations rotations_;
  Random noiseRng_;
  Random lostRng_;  // lost table frames (EncoderParams::lostPerMille)
  GyroFilters filters_;
  bool haveLatch_ = false;
  double latchS_ = 0.0;
  std::array<double, kAxisCount> latched_{};
  bool sensedBefore_ = false;
  double lastSenseS_ = 0.0;
  Eigen::Matrix3d lastBodyToTable_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d lastEarthDegPerH_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d bodyAngleDeg_ = Eigen::Vector3d::Zero(), earthAngleDeg_ = Eigen::Vector3d::Zero();
  std::vector<Random> effectRngs_;
  std::array<GyroChannel, kAxisCount> gyro_{};
  protocol::FrameWriter writer_;

  std::int64_t tableIndex_ = 0;
  double tableStampS_ = 0.0;
  bool tableDropped_ = false;
  protocol::TablePayload tablePayload_;

  std::int64_t imuIndex_ = 0;
  double imuStampS_ = 0.0;
  bool imuDropped_ = false;
  protocol::ImuPayload imuPayload_;

  std::int64_t statusIndex_ = 0;
  std::vector<double> statusEvents_;
  std::size_t nextEvent_ = 0;
};

Simulator::Simulator(const SimConfig& config, const TestPlan& plan)
    : config_(config), plan_(plan), turntable_(plan, config.turntable) {}

Simulator::~Simulator() = default;

Result<std::unique_ptr<Simulator>> Simulator::create(const SimConfig& config, const TestPlan& plan, double maxFrames) {
  if (Status s = config.validate(); !s.isOk()) return invalidArgument("simulator configuration: " + s.message());
  FOG_RETURN_IF_ERROR(plan.validate(config.turntable.limits));
  auto sim = std::make_unique<Simulator>(config, plan);
  const double frames = sim->frameBound();
  if (!(frames <= maxFrames))
    return outOfRange("the simulated stream would hold up to " + std::to_string(frames) + " frames (" +
                      std::to_string(sim->endS()) + " s at a table period of " +
                      std::to_string(config.encoder.samplePeriodS * 1e3) + " ms, an IMU period of " +
                      std::to_string(config.imuBoard.framePeriodS * 1e3) + " ms), over the budget of " +
                      std::to_string(maxFrames) + " frames");
  return sim;
}

Simulator::FrameCounts Simulator::frameCounts() const {
  // Indices 0..floor(limit / period) of the table and IMU streams, the
  // periodic status frames and three status events per point.
  const double limit = endS() + streamSlackS();
  const double imuPeriod = config_.imuBoard.actualFramePeriodS();
  FrameCounts n;
  n.table = std::floor(limit / config_.encoder.samplePeriodS) + 1.0;
  n.imu = std::floor(std::max(0.0, limit - config_.imuBoard.firstSampleS) / imuPeriod) + 1.0;
  n.status = std::floor(endS() / config_.samplingBoard.statusPeriodS) + 1.0 +
             3.0 * static_cast<double>(turntable_.schedule().size());
  return n;
}

void Simulator::addEffect(std::unique_ptr<Effect> effect) { effects_.push_back(std::move(effect)); }

void Simulator::start() {
  impl_ = std::make_unique<Impl>(config_, turntable_, streamSlackS(), effects_, recordTape_, playTape_);
}

bool Simulator::tapeMatched() const { return !impl_ || impl_->tapeMatched(); }

bool Simulator::advance(double untilS, std::vector<std::uint8_t>& out) { return advanceInto(untilS, out); }

bool Simulator::advance(double untilS, std::vector<protocol::Frame>& out) { return advanceInto(untilS, out); }

template <class Out>
bool Simulator::advanceInto(double untilS, Out& out) {
  if (!impl_) start();
  // Frames stamped at endS() itself belong to the plan: the stream ends just
  // after it, so only a step past endS() emits the last of them.
  const double last = endS() + 1e-9;
  const double until = std::min(untilS, last);
  if (until > nowS_) {
    impl_->advance(until, out);
    nowS_ = until;
  }
  return nowS_ < last;
}

void Simulator::runToEnd(std::vector<std::uint8_t>& out) { advance(endS() + 1.0, out); }

std::vector<TestPointTruth> Simulator::truth() const {
  std::vector<TestPointTruth> out;
  const Attitude attitude(config_.earth, config_.turntable);
  for (const auto& s : turntable_.schedule()) {
    TestPointTruth t;
    t.index = s.index;
    t.axis = s.point.axis;
    t.frequencyHz = s.angularFrequencyRadPerS / kTwoPi;
    t.amplitudeDeg = s.point.amplitudeDeg;
    t.lagS = config_.trueLagS();
    t.imuDelayS = config_.trueImuDelayS();
    t.gyroDelayS = config_.trueGyroDelayS();
    const int a = static_cast<int>(s.point.axis);
    // A swing turns the IMU about the swing axis, which keeps the Earth rate
    // along that axis constant: the trend is the one at the point's position.
    const Eigen::Vector3d earth = attitude.earthRateBodyDegPerH(attitude.bodyToTable(s.point.positionDeg));
    t.gyroTrendDegPerS = degPerHourToDegPerS(config_.fog.biasDegPerH[a] + earth[a]);
    out.push_back(t);
  }
  return out;
}

Result<SimulatedRun> simulate(const SimConfig& config, const TestPlan& plan,
                              std::vector<std::unique_ptr<Effect>> effects) {
  auto sim = Simulator::create(config, plan);
  if (!sim) return sim.status();
  for (auto& e : effects) (*sim)->addEffect(std::move(e));
  SimulatedRun run;
  // Frames are ~22 bytes; 1.5 kHz of them plus status.
  run.bytes.reserve(static_cast<std::size_t>((*sim)->endS() * 1510.0 * 26.0));
  (*sim)->runToEnd(run.bytes);
  run.truth = (*sim)->truth();
  return run;
}

}  // namespace fog::model
