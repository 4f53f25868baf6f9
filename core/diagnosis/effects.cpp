#include "core/diagnosis/effects.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

#include "core/common/units.h"
#include "core/model/gyro_filters.h"
#include "core/model/random.h"

namespace fog::diagnosis {

namespace {

std::string fmtValue(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

using Angles = std::array<double, kAxisCount>;

// Every effect here but the table harmonic distortion leaves the table's
// motion as planned (changesTableMotion() false): their replays at the
// signatures' seed play the first replay's motion tape instead of computing
// the gyro and encoder stages again (model::MotionTape).

// Integrates a rate error (deg/s, a function of the true table angles) along
// the instants the FOG is sampled, trapezoidal; the simulator calls the gyro
// hook every 2 ms in time order, far finer than any swing period.
class RateErrorEffect : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    const Angles rate = rateErrorDegPerS(c);
    if (started_) {
      const double dt = c.timeS - lastS_;
      for (int a = 0; a < kAxisCount; ++a) accumulated_[a] += 0.5 * (rate[a] + lastRate_[a]) * dt;
    }
    started_ = true;
    lastS_ = c.timeS;
    lastRate_ = rate;
    for (int a = 0; a < kAxisCount; ++a) sensed[a] += accumulated_[a];
  }

 protected:
  virtual Angles rateErrorDegPerS(const model::GyroContext& c) = 0;

 private:
  bool started_ = false;
  double lastS_ = 0.0;
  Angles lastRate_{}, accumulated_{};
};

// Bias ramp of every gyro, starting at the first sensed instant: a warming
// IMU. driftDegPerHPerMin: deg/h of bias gained per minute.
class BiasDrift final : public RateErrorEffect {
 public:
  explicit BiasDrift(double driftDegPerHPerMin) : d_(driftDegPerHPerMin) {}
  std::string name() const override { return "bias_drift"; }

 protected:
  Angles rateErrorDegPerS(const model::GyroContext& c) override {
    const double t = c.timeS;
    if (!haveStart_) t0_ = t, haveStart_ = true;
    const double r = degPerHourToDegPerS(d_ * (t - t0_) / 60.0);
    return {r, r, r};
  }

 private:
  double d_, t0_ = 0.0;
  bool haveStart_ = false;
};

// g-sensitive bias: each gyro's rate error is k times the specific force
// along its own axis (deg/h per g). Swinging a horizontal axis tilts gravity
// into the other horizontal gyro (k g sin(angle), in phase with the angle)
// and out of the vertical one (k g cos(angle): a second harmonic).
class GSensitivity final : public RateErrorEffect {
 public:
  explicit GSensitivity(double degPerHPerG) : k_(degPerHPerG) {}
  std::string name() const override { return "g_sensitivity"; }

 protected:
  Angles rateErrorDegPerS(const model::GyroContext& c) override {
    Angles r{};
    for (int a = 0; a < kAxisCount; ++a) r[a] = degPerHourToDegPerS(k_ * c.specificForceG[a]);
    return r;
  }

 private:
  double k_;
};

// Errors that depend on the increments of the body's rotation between two
// gyro samples: asymmetry (|dtheta|) and cubic nonlinearity (dtheta * rate^2).
class IncrementEffect : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    if (started_) {
      const double dt = c.timeS - lastS_;
      for (int a = 0; a < kAxisCount; ++a)
        if (dt > 0.0) accumulated_[a] += error(c.bodyAngleDeg[a] - last_[a], dt);
    }
    started_ = true;
    lastS_ = c.timeS;
    last_ = c.bodyAngleDeg;
    for (int a = 0; a < kAxisCount; ++a) sensed[a] += accumulated_[a];
  }

 protected:
  virtual double error(double dThetaDeg, double dtS) const = 0;

 private:
  bool started_ = false;
  double lastS_ = 0.0;
  Angles last_{}, accumulated_{};
};

// Scale-factor asymmetry a as IEEE Std 528 defines it, (K+ - K-) / Kbar
// with Kbar = (K+ + K-) / 2: the scale factor is Kbar (1 + a/2) for
// positive rates and Kbar (1 - a/2) for negative ones, so the sensed
// increment gains (a/2) |dtheta| (Kbar is the scale_factor_error's).
class ScaleFactorAsymmetry final : public IncrementEffect {
 public:
  explicit ScaleFactorAsymmetry(double ieeePpm) : halfA_(0.5 * ieeePpm * 1e-6) {}
  std::string name() const override { return "scale_factor_asymmetry"; }

 protected:
  double error(double d, double) const override { return halfA_ * std::abs(d); }

 private:
  double halfA_;
};

// Scale-factor nonlinearity N as IEEE Std 528 states it over an input range
// of +-100 deg/s: the largest deviation of the output from its least-squares
// straight line over the range, as a fraction of the full-scale output. As a
// cubic rate error k * rate * (rate / 100 deg/s)^2 the least-squares line
// over +-R has slope 1 + 0.6 k and the deviation k R (x^3 - 0.6 x),
// x = rate / R, whose largest magnitude (at x = +-1) is 0.4 k R: k = 2.5 N.
class ScaleFactorNonlinearity final : public IncrementEffect {
 public:
  explicit ScaleFactorNonlinearity(double ieeePpm) : k_(2.5 * ieeePpm * 1e-6) {}
  std::string name() const override { return "scale_factor_nonlinearity"; }

 protected:
  double error(double d, double dt) const override {
    const double r = d / dt / 100.0;
    return k_ * d * r * r;
  }

 private:
  double k_;
};

class ScaleFactorError final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  explicit ScaleFactorError(double ppm) : k_(ppm * 1e-6) {}
  std::string name() const override { return "scale_factor_error"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    for (int a = 0; a < kAxisCount; ++a) sensed[a] += k_ * c.bodyAngleDeg[a];
  }

 private:
  double k_;
};

// Misalignment and non-orthogonality of the gyro triad: gyro i senses
// m_ij times the rotation about body axis j (i != j; six small angles, rad).
// The rates are constant linear maps, so the sensed angles are too.
class Misalignment final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  explicit Misalignment(const std::array<double, 6>& microRad) {
    // m_xy, m_xz, m_yx, m_yz, m_zx, m_zy
    int k = 0;
    for (int i = 0; i < kAxisCount; ++i)
      for (int j = 0; j < kAxisCount; ++j)
        if (i != j) m_[i][j] = microRad[static_cast<std::size_t>(k++)] * 1e-6;
  }
  std::string name() const override { return "misalignment"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    for (int i = 0; i < kAxisCount; ++i)
      for (int j = 0; j < kAxisCount; ++j) sensed[i] += m_[i][j] * c.bodyAngleDeg[j];
  }

 private:
  std::array<std::array<double, kAxisCount>, kAxisCount> m_{};
};

// The gyro's output through a first-order low-pass of the sensed rate, a
// continuous-time filter: y' = (x - y) / tau on the sensed angle (filtering
// the angle and the rate are the same LTI operation), the chain's own
// first-order filter (model::FirstOrderFilter: solved exactly for the
// polynomial through the last six 2-ms samples, whose error is of order
// (w h)^6 of the swing). The delay at low frequency is tau.
class FirstOrderLag final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  explicit FirstOrderLag(double tauMs) : filter_(tauMs * 1e-3) {}
  std::string name() const override { return "first_order_lag"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override { filter_.apply(c.timeS, sensed); }

 private:
  model::FirstOrderFilter filter_;
};

// The table's motion itself is distorted, as a pure function of the angle
// (so the encoder and the gyro both see it). The parameters are the 2nd and
// 3rd harmonic amplitudes relative to the fundamental of a swing of 10 deg
// amplitude about zero, each with phase zero at the fundamental's positive
// peak: a commanded 10 cos(chi) becomes 10 [cos(chi) + h2 cos(2 chi) +
// h3 cos(3 chi)] + 10 h2 + 30 h3 cos(chi) (an offset and a change of the
// fundamental by 3 h3 of it). As a function of the angle that is
// theta + 10 (2 h2 x^2 + 4 h3 x^3), x = theta / 10 deg
// (cos^2 = (1 + cos 2chi) / 2, cos^3 = (3 cos chi + cos 3chi) / 4); at an
// amplitude A the harmonics are h2 (A / 10) and h3 (A / 10)^2 of the
// fundamental. A negative h_n is the same harmonic at phase 180 deg.
class TableHarmonicDistortion final : public model::Effect {
 public:
  TableHarmonicDistortion(double h2Ppm, double h3Ppm) : c2_(2.0 * h2Ppm * 1e-6), c3_(4.0 * h3Ppm * 1e-6) {}
  std::string name() const override { return "table_harmonic_distortion"; }
  void onTableMotion(double, Angles& angle) const override {
    for (double& th : angle) {
      const double x = th / 10.0;
      th += 10.0 * (c2_ * x * x + c3_ * x * x * x);
    }
  }

 private:
  double c2_, c3_;
};

// Encoder reading error periodic in the angle (grating / interpolation error),
// period kPeriodDeg: es * sin(2 pi theta / P) + ec * cos(2 pi theta / P).
class EncoderCyclicError final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  static constexpr double kPeriodDeg = 10.0;
  EncoderCyclicError(double sinArcsec, double cosArcsec) : s_(sinArcsec / kArcsecPerDeg), c_(cosArcsec / kArcsecPerDeg) {}
  std::string name() const override { return "encoder_cyclic_error"; }
  void onEncoderReading(double, Angles& reading) override {
    for (double& r : reading) {
      const double ph = kTwoPi * r / kPeriodDeg;
      r += s_ * std::sin(ph) + c_ * std::cos(ph);
    }
  }

 private:
  double s_, c_;
};

class TimestampJitter final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  explicit TimestampJitter(double varianceUs2) : sigmaS_(std::sqrt(std::max(varianceUs2, 0.0)) * 1e-6) {}
  std::string name() const override { return "timestamp_jitter"; }
  // The simulator keeps the Random it hands out in a growing vector, so the
  // effect keeps its own copy of the stream.
  void reset(model::Random& rng) override { rng_ = rng; }
  void onImuStamp(double& stampS, bool&) override { stampS += sigmaS_ * rng_.normal(); }

 private:
  double sigmaS_;
  model::Random rng_{0};
};

// The IMU frames' stamps run eps off the table's: stamp * (1 + eps).
class ClockDrift final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  explicit ClockDrift(double ppm) : eps_(ppm * 1e-6) {}
  std::string name() const override { return "clock_drift"; }
  void onImuStamp(double& stampS, bool&) override { stampS += eps_ * stampS; }

 private:
  double eps_;
};

// Random loss at rate p; or, with `expected`, every frame at which the
// running sum of p crosses an integer (the expected count, evenly spaced).
class DroppedFrames final : public model::Effect {
 public:
  bool changesTableMotion() const override { return false; }
  DroppedFrames(double perMille, bool expected) : p_(perMille * 1e-3), expected_(expected) {}
  std::string name() const override { return "dropped_frames"; }
  void reset(model::Random& rng) override {
    rng_ = rng;
    acc_ = 0.5;
  }
  void onImuStamp(double&, bool& drop) override {
    if (p_ <= 0.0) return;
    if (!expected_) {
      if (rng_.uniform() < p_) drop = true;
      return;
    }
    acc_ += p_;
    if (acc_ >= 1.0) {
      drop = true;
      acc_ -= 1.0;
    }
  }

 private:
  double p_;
  bool expected_;
  double acc_ = 0.5;
  model::Random rng_{0};
};

// The Earth rate the IMU really senses, for a latitude and heading off the
// nominal ones by dLat and dHeading (the table turned further about down):
// the difference to the nominal Earth rate, rotated into the body frame at
// every sample.
class EarthRateProjection final : public RateErrorEffect {
 public:
  EarthRateProjection(double dLatDeg, double dHeadingDeg, const model::EarthParams& nominal) {
    model::EarthParams actual = nominal;
    actual.latitudeDeg = std::clamp(nominal.latitudeDeg + dLatDeg, -90.0, 90.0);
    const auto n = nominal.rateLocalDegPerH(), w = actual.rateLocalDegPerH();
    // In the local frame as the nominal attitude has it: R_z(dh)^T w - n.
    const double h = dHeadingDeg * kRadPerDeg;
    diff_ = {std::cos(h) * w[0] + std::sin(h) * w[1] - n[0], -std::sin(h) * w[0] + std::cos(h) * w[1] - n[1],
             w[2] - n[2]};
  }
  std::string name() const override { return "earth_rate_projection"; }

 protected:
  Angles rateErrorDegPerS(const model::GyroContext& c) override {
    Angles r{};
    for (int i = 0; i < kAxisCount; ++i)
      for (int k = 0; k < kAxisCount; ++k) r[i] += c.bodyToLocal[k][i] * degPerHourToDegPerS(diff_[k]);
    return r;
  }

 private:
  Angles diff_{};
};

// Reference magnitudes: the linear signature is (replay at +reference -
// replay at -reference) / (2 reference) on one seed, or (replay with the
// effect - replay without) / reference for a parameter that cannot be
// negative. Any change of the sensed angle, however small, re-draws the
// pulse quantisation of the gyro (a chaotic, zero-mean change of ~10-20 chi2
// units spread over the residual and harmonic cells), so a reference must
// put the signature far above that, or the fitted values are biased towards
// zero and the detection thresholds come out too low (bias drift at 0.1
// deg/h per min and g-sensitivity at 5 deg/h/g were dominated by it). Every
// effect here responds linearly far beyond its reference, except in the
// residual-variance cells, which grow with the square of an amplitude: the
// central difference leaves that part to the exact evaluation.
std::vector<EffectSpec> buildLibrary() {
  using E = EffectId;
  // {name, unit, reference, can be negative, largest magnitude modelled,
  //  definition, standard, name and factor before issue 44 (new = factor * old)}
  const std::string s528 = "IEEE Std 528-2001 (inertial sensor terminology)";
  const std::string s952 = "IEEE Std 952-1997 (single-axis interferometric FOG)";
  return {
      {E::kBiasDrift, "bias_drift", "bias drift", "gyro bias ramp (temperature-like), all axes",
       {{"drift", "deg/h per min", 2.0, true, 1000.0,
         "deterministic bias ramp: every gyro's bias grows by this much per minute from the first sample (a linear "
         "drift rate; the random bias instability is the replay's stated Gauss-Markov wander, not this). "
         "IEEE Std 952's rate ramp coefficient R = 60 x this value in deg/h^2",
         s952 + ", rate ramp R (deg/h^2)"}}},
      {E::kScaleFactorError, "scale_factor_error", "scale-factor error", "gyro scale factor error",
       {{"scale_factor", "ppm", 1000.0, true, 1e6,
         "scale-factor error (K - K0) / K0: the output is (1 + s) times the input rate, both signs, every gyro",
         s528 + ", scale factor error"}}},
      {E::kScaleFactorAsymmetry, "scale_factor_asymmetry", "scale-factor asymmetry", "scale factor differs for positive / negative rate",
       {{"asymmetry", "ppm", 2000.0, true, 2e6,
         "scale-factor asymmetry (K+ - K-) / Kbar, Kbar = (K+ + K-) / 2: the scale factor is Kbar (1 + a/2) for "
         "positive input rates and Kbar (1 - a/2) for negative ones",
         s528 + ", scale factor asymmetry; " + s952, "asymmetry_k", 2.0}}},
      {E::kScaleFactorNonlinearity, "scale_factor_nonlinearity", "scale-factor nonlinearity", "cubic scale-factor nonlinearity (error at 100 deg/s)",
       {{"nonlinearity", "ppm of full scale over +-100 deg/s", 8000.0, true, 4e5,
         "scale-factor nonlinearity over the input range +-100 deg/s: the largest deviation of the output from its "
         "least-squares straight line over the range, as a fraction of the full-scale output (100 deg/s), for a "
         "cubic deviation (odd in the rate: the output is w + 2.5 N w^3 / (100 deg/s)^2); over +-R it is "
         "N (R / 100 deg/s)^2",
         s528 + ", scale factor nonlinearity (least-squares line)", "nonlinearity_at_100", 0.4}}},
      {E::kMisalignment, "misalignment", "misalignment", "gyro triad misalignment / non-orthogonality (gyro i senses m_ij of axis j)",
       {{"m_xy", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro x toward body axis y (small angle): gyro x senses +m_xy times the rate about y", s528 + ", input axis misalignment; " + s952},
        {"m_xz", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro x toward body axis z: gyro x senses +m_xz times the rate about z", s528 + ", input axis misalignment; " + s952},
        {"m_yx", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro y toward body axis x: gyro y senses +m_yx times the rate about x", s528 + ", input axis misalignment; " + s952},
        {"m_yz", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro y toward body axis z: gyro y senses +m_yz times the rate about z", s528 + ", input axis misalignment; " + s952},
        {"m_zx", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro z toward body axis x: gyro z senses +m_zx times the rate about x", s528 + ", input axis misalignment; " + s952},
        {"m_zy", "urad", 200.0, true, 1e5, "input-axis misalignment of gyro z toward body axis y: gyro z senses +m_zy times the rate about y", s528 + ", input axis misalignment; " + s952}}},
      {E::kGSensitivity, "g_sensitivity", "g-sensitivity", "g-sensitive bias: each gyro's rate error k times the specific force along it",
       {{"g_sensitivity", "deg/h/g", 50.0, true, 1e4,
         "g-sensitive bias along the input axis: each gyro's rate error is k times the specific force along its own "
         "input axis (the same k for the three gyros)",
         s528 + ", g-sensitive drift (acceleration-sensitive drift coefficient along the input axis)"}}},
      {E::kFirstOrderLag, "first_order_lag", "first-order lag", "first-order low-pass of the gyro output",
       {{"time_constant", "ms", 2.0, false, 1000.0,
         "time constant tau of a first-order low-pass 1 / (1 + s tau) of the gyro output; its -3 dB bandwidth is "
         "1 / (2 pi tau)",
         s528 + ", bandwidth (= 1 / (2 pi tau) for a first-order response)"}}, false},
      {E::kTableHarmonicDistortion, "table_harmonic_distortion", "table harmonic distortion", "2nd/3rd harmonic in the table motion",
       {{"h2", "ppm", 100.0, true, 5e5,
         "2nd-harmonic amplitude of the table's angle relative to its fundamental, for a swing of 10 deg amplitude "
         "about zero, phase 0 at the fundamental's positive peak: 10 cos(chi) becomes 10 [cos(chi) + h2 cos(2 chi)] "
         "(negative: phase 180 deg); a static distortion of the angle, so h2 (A / 10 deg) at amplitude A",
         "amplitude ratio of the harmonic to the fundamental (harmonic distortion as IEEE Std 1057 states it); "
         "phase convention this project's", "h2_at_10deg", 0.5},
        {"h3", "ppm", 100.0, true, 2.5e5,
         "3rd-harmonic amplitude of the table's angle relative to its fundamental, for a swing of 10 deg amplitude "
         "about zero, phase 0 at the fundamental's positive peak: + 10 h3 cos(3 chi) (negative: phase 180 deg); "
         "h3 (A / 10 deg)^2 at amplitude A",
         "amplitude ratio of the harmonic to the fundamental (harmonic distortion as IEEE Std 1057 states it); "
         "phase convention this project's", "h3_at_10deg", -0.25}}},
      {E::kEncoderCyclicError, "encoder_cyclic_error", "encoder cyclic error", "encoder error periodic in angle (10 deg period)",
       {{"sin_amplitude", "arcsec", 1.0, true, 3600.0,
         "encoder reading error s sin(2 pi theta / 10 deg) + c cos(2 pi theta / 10 deg): s", "own"},
        {"cos_amplitude", "arcsec", 1.0, true, 3600.0,
         "encoder reading error s sin(2 pi theta / 10 deg) + c cos(2 pi theta / 10 deg): c", "own"}}},
      // Up to 10 ms rms: beyond, frames of a 2-ms stream swap order.
      {E::kTimestampJitter, "timestamp_jitter", "time-stamp jitter", "white jitter on the IMU frame stamps",
       {{"jitter_variance", "us^2", 100.0, false, 1e8,
         "variance of a white, Gaussian error added to every IMU frame's stamp", "own"}}},
      // The IMU board's own clock error is modelled up to 1000 ppm
      // (SimConfig::validate); at -1e6 ppm its stamps would run backwards.
      {E::kClockDrift, "clock_drift", "IMU clock drift", "IMU stamps drift against the table's time base",
       {{"drift", "ppm", 1.0, true, 1000.0,
         "fractional frequency offset y of the IMU's time base against the table's: a stamp t reads t (1 + y)",
         "fractional frequency deviation y (IEEE Std 1139-2008)"}}},
      {E::kDroppedFrames, "dropped_frames", "dropped frames", "IMU frames lost at random",
       {{"loss_rate", "per mille", 5.0, false, 1000.0,
         "probability that an IMU frame is lost, each frame independently (Bernoulli)", "own"}}},
      {E::kEarthRateProjection, "earth_rate_projection", "Earth-rate projection", "wrong latitude / heading for the Earth-rate projection",
       {{"latitude_error", "deg", 5.0, true, 180.0, "true latitude minus the nominal one", "own"},
        {"heading_error", "deg", 5.0, true, 360.0,
         "true heading minus the nominal one, the table turned further about down", "own"}}, false, false},
  };
}

}  // namespace

std::string effectTitle(const std::string& name) {
  if (name == "none") return "none (the recording agrees with the simulation)";
  if (name == "unexplained") return "unexplained (no effect of the library closes the gap)";
  if (name == "undetermined") return "undetermined";
  if (name == "frame_contradicted") return "the IMU's frame contradicts the data (no effect named)";
  for (const auto& spec : effectLibrary())
    if (spec.name == name) return spec.title;
  return name;
}

const std::vector<EffectSpec>& effectLibrary() {
  static const std::vector<EffectSpec> library = buildLibrary();
  return library;
}

const EffectSpec& effectSpec(EffectId id) { return effectLibrary().at(static_cast<std::size_t>(id)); }

Result<EffectId> effectIdFromName(const std::string& name) {
  for (const auto& s : effectLibrary())
    if (s.name == name) return s.id;
  return invalidArgument("unknown effect '" + name + "'");
}

Status checkParameters(EffectId id, const std::vector<double>& p) {
  const EffectSpec& spec = effectSpec(id);
  if (p.size() != spec.parameters.size())
    return invalidArgument(spec.name + " takes " + std::to_string(spec.parameters.size()) + " parameters");
  for (std::size_t j = 0; j < p.size(); ++j) {
    const EffectParameter& q = spec.parameters[j];
    if (!std::isfinite(p[j])) return invalidArgument(spec.name + ": " + q.name + " is not a finite number");
    if (std::abs(p[j]) > q.maxMagnitude || (!q.canBeNegative && p[j] < 0.0))
      return outOfRange(spec.name + ": " + q.name + " = " + fmtValue(p[j]) + " " + q.unit +
                        " is outside the range the effect is modelled for (" + (q.canBeNegative ? "+-" : "0 .. ") +
                        fmtValue(q.maxMagnitude) + " " + q.unit + ")");
  }
  return Status::ok();
}

std::unique_ptr<model::Effect> makeEffect(EffectId id, const std::vector<double>& p, const EffectContext& context) {
  assert(p.size() == effectSpec(id).parameters.size());
  switch (id) {
    case EffectId::kBiasDrift: return std::make_unique<BiasDrift>(p[0]);
    case EffectId::kScaleFactorError: return std::make_unique<ScaleFactorError>(p[0]);
    case EffectId::kScaleFactorAsymmetry: return std::make_unique<ScaleFactorAsymmetry>(p[0]);
    case EffectId::kScaleFactorNonlinearity: return std::make_unique<ScaleFactorNonlinearity>(p[0]);
    case EffectId::kMisalignment: return std::make_unique<Misalignment>(std::array<double, 6>{p[0], p[1], p[2], p[3], p[4], p[5]});
    case EffectId::kGSensitivity: return std::make_unique<GSensitivity>(p[0]);
    case EffectId::kFirstOrderLag: return std::make_unique<FirstOrderLag>(p[0]);
    case EffectId::kTableHarmonicDistortion: return std::make_unique<TableHarmonicDistortion>(p[0], p[1]);
    case EffectId::kEncoderCyclicError: return std::make_unique<EncoderCyclicError>(p[0], p[1]);
    case EffectId::kTimestampJitter: return std::make_unique<TimestampJitter>(p[0]);
    case EffectId::kClockDrift: return std::make_unique<ClockDrift>(p[0]);
    case EffectId::kDroppedFrames: return std::make_unique<DroppedFrames>(p[0], context.expectedDrops);
    case EffectId::kEarthRateProjection: return std::make_unique<EarthRateProjection>(p[0], p[1], context.earth);
  }
  return nullptr;
}

}  // namespace fog::diagnosis
