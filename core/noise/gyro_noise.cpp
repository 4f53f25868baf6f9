#include "core/noise/gyro_noise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/units.h"
#include "core/common/version.h"

namespace fog::noise {

namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

const char* upperAxis(Axis a) {
  switch (a) {
    case Axis::kX: return "X";
    case Axis::kY: return "Y";
    case Axis::kZ: return "Z";
  }
  return "?";
}

// Peak of the Markov Allan deviation relative to sigma and where it lies
// (tau / Tc), found once numerically: about 0.6174 at 1.89 Tc.
struct MarkovPeak {
  double relativeDeviation = 0.0, tauOverTc = 0.0;
};
MarkovPeak markovPeak() {
  MarkovPeak best;
  for (double x = 0.5; x < 5.0; x *= 1.0005) {
    const double d = std::sqrt(unitAllanVariance(NoiseTermKind::kMarkov, x, 1.0));
    if (d > best.relativeDeviation) best = {d, x};
  }
  return best;
}

}  // namespace

Result<GyroNoiseReport> analyzeStaticSegment(const TestPointData& data, const GyroNoiseOptions& options,
                                             double degPerPulse) {
  GyroNoiseReport r;
  r.testPointIndex = data.index;
  r.gyroAxis = options.gyroAxis.value_or(data.axis);
  const auto a = static_cast<std::size_t>(r.gyroAxis);
  if (data.imu.size() < 8)
    return insufficientData("static segment " + std::to_string(data.index + 1) + " holds " +
                            std::to_string(data.imu.size()) + " IMU samples; an Allan deviation needs at least 8");
  // Lost frames: their increments are missing. Each is filled with the mean
  // increment, which keeps the time base and costs only a little noise.
  std::vector<double> increments;
  increments.reserve(data.imu.size() + 16);
  double sum = 0.0;
  for (const auto& s : data.imu) sum += s.incrementDeg[a];
  const double meanIncrement = sum / static_cast<double>(data.imu.size());
  for (std::size_t k = 0; k < data.imu.size(); ++k) {
    const auto& s = data.imu[k];
    if (k > 0)
      for (std::uint32_t l = 0; l < s.lostBefore; ++l) increments.push_back(meanIncrement);
    if (k > 0) r.lostFrames += s.lostBefore;
    increments.push_back(s.incrementDeg[a]);
  }
  r.samples = data.imu.size();
  // The first sample's increment covers the frame before its stamp.
  const double span = data.imu.back().timeS - data.imu.front().timeS;
  r.intervalS = span / static_cast<double>(increments.size() - 1);
  r.durationS = r.intervalS * static_cast<double>(increments.size());
  if (!(r.intervalS > 0.0)) return corruptData("static segment " + std::to_string(data.index + 1) + ": IMU time stamps do not advance");
  if (r.lostFrames)
    r.warnings.push_back(std::to_string(r.lostFrames) + " lost IMU frames filled with the mean increment");

  // A gyro whose every increment is the same (a dead or disconnected axis, a
  // file of zeros) has no noise to analyse: its Allan deviation is 0 at every
  // tau, and a fit to it gave "rate ramp: 0 ± 0" with chi^2 2.5e10.
  if (std::all_of(increments.begin(), increments.end(), [&](double d) { return d == increments.front(); }))
    return insufficientData("static segment " + std::to_string(data.index + 1) + ": the " + std::string(axisLabel(r.gyroAxis)) +
                            " gyro's " + std::to_string(increments.size()) + " increments are all " +
                            fmt("%.6g", increments.front()) +
                            " deg: no noise to analyse (a dead or disconnected axis, or a file of constants)");
  if (!std::all_of(increments.begin(), increments.end(), [](double d) { return std::isfinite(d); }))
    return corruptData("static segment " + std::to_string(data.index + 1) + ": an increment is not finite");

  const double meanRateDegPerS = meanIncrement / r.intervalS;
  r.biasDegPerH = meanRateDegPerS * kSecondsPerHour;
  r.earthRateDegPerH = options.earth.projectionDegPerH(r.gyroAxis);
  r.earthCorrectedBiasDegPerH = r.biasDegPerH - r.earthRateDegPerH;

  const auto phase = cumulativeSum(increments, meanIncrement);
  FOG_ASSIGN_OR_RETURN(auto curve, overlappingAllanCurve(phase, r.intervalS, options.allan));
  r.curve = std::move(curve);
  // The increments are whole pulses: the quantisation term is that of the
  // pulse count of an angle moving meanIncrement per frame (docs/noise.md).
  bool wholePulses = options.pulseQuantisation && degPerPulse > 0.0;
  for (std::size_t k = 0; wholePulses && k < data.imu.size(); ++k) {
    const double c = data.imu[k].incrementDeg[a] / degPerPulse;
    wholePulses = std::abs(c - std::round(c)) < 1e-6 * std::max(1.0, std::abs(c));
  }
  if (wholePulses) r.curve.pulse = {degPerPulse, meanIncrement};
  FOG_ASSIGN_OR_RETURN(auto model, identifyNoise(r.curve, options.identify));
  r.model = std::move(model);
  r.biasStdDegPerH = std::sqrt(std::max(0.0, r.model.allanVariance(r.durationS))) * kSecondsPerHour;
  if (r.model.chiSquare > 3.0 * std::max(1, r.model.dof))
    r.warnings.push_back("the noise model fits the Allan curve poorly (chi^2 " + fmt("%.0f", r.model.chiSquare) + " for " +
                         std::to_string(r.model.dof) + " dof): a term outside IEEE 952, or non-white quantisation");
  return r;
}

Result<std::vector<GyroNoiseReport>> analyzeGyroNoise(const Recording& recording, const GyroNoiseOptions& options) {
  // Increments are in degrees (protocol::RecordingBuilder); the pulse
  // equivalent is the quantum for the quantisation term.
  std::vector<GyroNoiseReport> out;
  for (const auto& tp : recording.testPoints) {
    if (tp.kind != TestPointKind::kStatic) continue;
    FOG_ASSIGN_OR_RETURN(auto r, analyzeStaticSegment(tp, options, recording.pulseEquivalentDeg));
    out.push_back(std::move(r));
  }
  if (out.empty())
    return insufficientData("the recording has no static segment (table at rest); record one, e.g. "
                            "fogbench-cli run --preset noise, or add {\"kind\": \"static\"} to the plan");
  return out;
}

TermInUnits termInGyroUnits(const NoiseTerm& t) {
  double f = 1.0;
  const char* unit = "";
  switch (t.kind) {
    case NoiseTermKind::kQuantisation: f = kArcsecPerDeg, unit = "arcsec"; break;
    case NoiseTermKind::kAngleRandomWalk: f = 60.0, unit = "deg/sqrt(h)"; break;
    case NoiseTermKind::kBiasInstability: f = kSecondsPerHour, unit = "deg/h"; break;
    case NoiseTermKind::kRateRandomWalk: f = kSecondsPerHour * 60.0, unit = "deg/h/sqrt(h)"; break;
    case NoiseTermKind::kRateRamp: f = kSecondsPerHour * kSecondsPerHour, unit = "deg/h^2"; break;
    case NoiseTermKind::kMarkov: f = kSecondsPerHour, unit = "deg/h"; break;
  }
  return {t.value * f, t.stdError * f, unit};
}

TermInUnits termInSiUnits(const NoiseTerm& t) {
  // Native units are deg and deg/s times a power of s (noise_terms.h); only
  // the angle changes: deg -> rad. N in deg/sqrt(s) is rad/s/sqrt(Hz) once
  // in radians, since sqrt(s) = 1/sqrt(Hz); likewise K in deg/s/sqrt(s).
  constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
  const char* unit = "";
  switch (t.kind) {
    case NoiseTermKind::kQuantisation: unit = "rad"; break;
    case NoiseTermKind::kAngleRandomWalk: unit = "rad/s/sqrt(Hz)"; break;
    case NoiseTermKind::kBiasInstability: unit = "rad/s"; break;
    case NoiseTermKind::kRateRandomWalk: unit = "rad/s^2/sqrt(Hz)"; break;
    case NoiseTermKind::kRateRamp: unit = "rad/s^2"; break;
    case NoiseTermKind::kMarkov: unit = "rad/s"; break;
  }
  return {t.value * kRadPerDeg, t.stdError * kRadPerDeg, unit};
}

std::string formatKalibrYaml(const GyroNoiseReport& report, const std::string& source) {
  auto value = [&](NoiseTermKind kind, const char* why) {
    const NoiseTerm* t = report.model.find(kind);
    if (!t) return std::string(".nan  # ") + why;
    const auto si = termInSiUnits(*t);
    const auto native = termInGyroUnits(*t);
    return fmt("%.9g", si.value) + "  # " + si.unit + " (" + fmt("%.6g", native.value) + " " + native.unit + " ± " +
           fmt("%.2g", native.stdError) + ", IEEE Std 952 " + noiseTermName(kind) + ")";
  };
  std::string oneLine = source;  // a comment ends at a line break: the name stays in it
  std::replace_if(oneLine.begin(), oneLine.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  std::ostringstream o;
  o << "# IMU noise model for kalibr / OpenVINS (imu.yaml), written by fogbench " << FOG_VERSION << "\n"
    << "# from the static segment of test point " << report.testPointIndex + 1 << " (" << upperAxis(report.gyroAxis)
    << " gyro, " << fmt("%.1f", report.durationS) << " s at rest) of " << oneLine << "\n"
    << "# Continuous-time densities, SI units, angles in radians: the angle random walk N in deg/sqrt(h)\n"
    << "# is N / 60 deg/sqrt(s) = N / 60 * pi / 180 rad/s/sqrt(Hz); the rate random walk K in\n"
    << "# deg/h/sqrt(h) is K / 3600 / 60 * pi / 180 rad/s^2/sqrt(Hz). Only this gyro axis was measured;\n"
    << "# kalibr takes one value for all three gyros.\n"
    << "rostopic: /imu0\n"
    << "update_rate: " << fmt("%.6g", report.intervalS > 0.0 ? 1.0 / report.intervalS : 0.0)
    << "  # Hz, 1 / the IMU's mean frame interval (" << fmt("%.6g", report.intervalS * 1e3) << " ms)\n"
    << "gyroscope_noise_density: "
    << value(NoiseTermKind::kAngleRandomWalk, "not identified in this record (no white rate above the other terms)")
    << "\n"
    << "gyroscope_random_walk: "
    << value(NoiseTermKind::kRateRandomWalk,
             "not identified in this record (too short to see a rate random walk; a longer rest shows it)")
    << "\n"
    << "accelerometer_noise_density: .nan  # not measured: fogbench measures the gyro, not the accelerometer\n"
    << "accelerometer_random_walk: .nan  # not measured: fogbench measures the gyro, not the accelerometer\n";
  return o.str();
}

SimulatorFeed simulatorFeed(const GyroNoiseReport& report, const model::SimConfig& base) {
  SimulatorFeed feed;
  feed.config = base;
  model::FogParams& fog = feed.config.fog;
  fog.biasDegPerH[static_cast<std::size_t>(report.gyroAxis)] = report.earthCorrectedBiasDegPerH;
  const NoiseTerm* n = report.model.find(NoiseTermKind::kAngleRandomWalk);
  fog.arwDegPerSqrtH = n ? n->value * 60.0 : 0.0;
  if (const NoiseTerm* m = report.model.find(NoiseTermKind::kMarkov)) {
    fog.biasInstabilityDegPerH = m->value * kSecondsPerHour;
    fog.biasCorrelationS = m->correlationTimeS;
  } else if (const NoiseTerm* b = report.model.find(NoiseTermKind::kBiasInstability)) {
    const MarkovPeak peak = markovPeak();
    const double plateau = b->value * std::sqrt(unitAllanVariance(NoiseTermKind::kBiasInstability, 1.0));
    fog.biasInstabilityDegPerH = plateau / peak.relativeDeviation * kSecondsPerHour;
    fog.biasCorrelationS = std::sqrt(b->tauLowS * b->tauHighS) / peak.tauOverTc;
    feed.notes.push_back("flicker bias instability approximated by a Gauss-Markov rate of " +
                         fmt("%.3g", fog.biasInstabilityDegPerH) + " deg/h, " + fmt("%.3g", fog.biasCorrelationS) +
                         " s (same peak Allan deviation)");
  } else {
    fog.biasInstabilityDegPerH = 0.0;
  }
  if (const NoiseTerm* q = report.model.find(NoiseTermKind::kQuantisation))
    feed.notes.push_back("quantisation " + fmt("%.3g", q->value * kArcsecPerDeg) +
                         " arcsec: the simulator quantises by its pulse equivalent (" +
                         fmt("%.3g", fog.pulseEquivalentDeg * kArcsecPerDeg) + " arcsec per pulse) only");
  if (report.model.find(NoiseTermKind::kRateRandomWalk))
    feed.notes.push_back("rate random walk is not simulated");
  if (report.model.find(NoiseTermKind::kRateRamp)) feed.notes.push_back("rate ramp is not simulated");
  return feed;
}

SwingPrediction predictSwing(const GyroNoiseReport& report, analysis::PlannedTest planned) {
  const NoiseTerm* n = report.model.find(NoiseTermKind::kAngleRandomWalk);
  planned.arwDegPerSqrtH = n ? n->value * 60.0 : 0.0;
  if (const NoiseTerm* q = report.model.find(NoiseTermKind::kQuantisation)) planned.pulseEquivalentDeg = q->value * std::sqrt(12.0);
  planned.imuIntervalS = report.intervalS;
  return {planned, analysis::predictedLagStdS(planned)};
}

std::string formatNoiseText(const std::vector<GyroNoiseReport>& reports, const std::vector<SwingPrediction>& predictions) {
  std::ostringstream o;
  for (const auto& r : reports) {
    o << "Static segment " << r.testPointIndex + 1 << ": " << upperAxis(r.gyroAxis) << " gyro, " << fmt("%.1f", r.durationS)
      << " s at rest, " << r.samples << " samples every " << fmt("%.3f", r.intervalS * 1e3) << " ms\n";
    o << "  bias " << fmt("%.4f", r.biasDegPerH) << " ± " << fmt("%.4f", r.biasStdDegPerH) << " deg/h; Earth rate "
      << fmt("%.4f", r.earthRateDegPerH) << " deg/h; Earth-corrected bias " << fmt("%.4f", r.earthCorrectedBiasDegPerH)
      << " deg/h\n";
    o << "  overlapping Allan deviation (" << fmt("%.1f", r.curve.confidence * 100.0) << " % interval, EDF):\n";
    o << "        tau s      adev deg/h      low deg/h     high deg/h        EDF  noise\n";
    for (const auto& p : r.curve.points)
      o << fmt("%13.4g", p.tauS) << fmt("%16.5g", p.deviation * kSecondsPerHour)
        << fmt("%15.5g", p.interval.low * kSecondsPerHour) << fmt("%15.5g", p.interval.high * kSecondsPerHour)
        << fmt("%11.4g", p.edf) << "  " << powerLawNoiseName(p.noise) << "\n";
    o << "  noise terms (IEEE Std 952; significant only; chi^2 " << fmt("%.1f", r.model.chiSquare) << " for "
      << r.model.dof << " dof):\n";
    for (const auto& t : r.model.terms) {
      const auto u = termInGyroUnits(t);
      const auto si = termInSiUnits(t);
      o << "    " << noiseTermName(t.kind) << ": " << fmt("%.4g", u.value) << " ± " << fmt("%.2g", u.stdError) << " "
        << u.unit << " = " << fmt("%.4g", si.value) << " ± " << fmt("%.2g", si.stdError) << " " << si.unit << "  (tau "
        << fmt("%.3g", t.tauLowS) << " .. " << fmt("%.3g", t.tauHighS) << " s";
      if (t.kind == NoiseTermKind::kMarkov)
        o << "; correlation time " << fmt("%.3g", t.correlationTimeS) << " s, " << fmt("%.3g", t.correlationTimeLowS)
          << " .. " << fmt("%.3g", t.correlationTimeHighS);
      o << ")\n";
    }
    for (const auto& w : r.warnings) o << "  warning: " << w << "\n";
  }
  for (const auto& p : predictions)
    o << "Swing test with this gyro: " << fmt("%g", p.test.frequencyHz) << " Hz / " << fmt("%g", p.test.amplitudeDeg)
      << " deg for " << fmt("%g", p.test.durationS) << " s gives a lag sigma of " << fmt("%.3g", p.lagStdS * 1e6)
      << " us (Cramer-Rao bound)\n";
  return o.str();
}

std::string formatNoiseJson(const std::vector<GyroNoiseReport>& reports, const std::vector<SwingPrediction>& predictions) {
  using nlohmann::json;
  json doc;
  doc["segments"] = json::array();
  for (const auto& r : reports) {
    json s;
    s["test_point"] = r.testPointIndex + 1;
    s["axis"] = axisName(r.gyroAxis);
    s["duration_s"] = r.durationS;
    s["interval_s"] = r.intervalS;
    s["samples"] = r.samples;
    s["lost_frames"] = r.lostFrames;
    s["bias_deg_h"] = r.biasDegPerH;
    s["bias_std_deg_h"] = r.biasStdDegPerH;
    s["earth_rate_deg_h"] = r.earthRateDegPerH;
    s["earth_corrected_bias_deg_h"] = r.earthCorrectedBiasDegPerH;
    s["confidence"] = r.curve.confidence;
    s["allan"] = json::array();
    for (const auto& p : r.curve.points)
      s["allan"].push_back({{"tau_s", p.tauS},
                            {"adev_deg_h", p.deviation * kSecondsPerHour},
                            {"low_deg_h", p.interval.low * kSecondsPerHour},
                            {"high_deg_h", p.interval.high * kSecondsPerHour},
                            {"edf", p.edf},
                            {"noise", powerLawNoiseName(p.noise)}});
    s["terms"] = json::array();
    for (const auto& t : r.model.terms) {
      const auto u = termInGyroUnits(t);
      const auto si = termInSiUnits(t);
      json e = {{"term", noiseTermKey(t.kind)}, {"value", u.value},         {"std", u.stdError},
                {"unit", u.unit},               {"value_si", si.value},     {"std_si", si.stdError},
                {"unit_si", si.unit},           {"tau_low_s", t.tauLowS},   {"tau_high_s", t.tauHighS},
                {"significance", t.significance}};
      if (t.kind == NoiseTermKind::kMarkov) {
        e["correlation_time_s"] = t.correlationTimeS;
        e["correlation_time_low_s"] = t.correlationTimeLowS;
        e["correlation_time_high_s"] = t.correlationTimeHighS;
      }
      s["terms"].push_back(e);
    }
    s["chi2"] = r.model.chiSquare;
    s["dof"] = r.model.dof;
    s["warnings"] = r.warnings;
    doc["segments"].push_back(s);
  }
  doc["swing_predictions"] = json::array();
  for (const auto& p : predictions)
    doc["swing_predictions"].push_back({{"frequency_hz", p.test.frequencyHz},
                                        {"amplitude_deg", p.test.amplitudeDeg},
                                        {"duration_s", p.test.durationS},
                                        {"arw_deg_sqrt_h", p.test.arwDegPerSqrtH},
                                        {"pulse_equivalent_deg", p.test.pulseEquivalentDeg},
                                        {"lag_std_us", p.lagStdS * 1e6}});
  return doc.dump(2);
}

}  // namespace fog::noise
