// diagnose(): the stages (diagnosis_stages.h) in order, and the views of
// the result (alias groups, per-point views, timing audits).
#include "core/diagnosis/diagnosis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <tuple>

#include "core/common/units.h"
#include "core/diagnosis/diagnosis_stages.h"

namespace fog::diagnosis {

namespace detail {
namespace {

std::vector<AliasGroup> aliasGroups(const Calibration& cal) {
  std::vector<AliasGroup> groups;
  groups.push_back(
      {"constant delay",
       {"pure gyro delay", "first-order lag with time constant <= 5 ms", "table read delay", "timestamp offset",
        "fixed serial / board latency"},
       "lag " + fmt("%.4f", cal.lagMs) + " ms (taken as the replay's nominal delay)",
       "swing data shift all of them by one constant at every frequency: measure the read delay and the board "
       "latency on the board (loop-back / sync pulse), and separate a lag from a delay with a step or a swing "
       "above 1/(2 pi tau) (~30 Hz for 5 ms)"});
  groups.push_back(
      {"constant rate", {"gyro bias", "earth_rate_projection (latitude / heading error)"},
       "bias " + fmt("%+.3f", cal.biasDegPerH[0]) + " / " + fmt("%+.3f", cal.biasDegPerH[1]) + " / " +
           fmt("%+.3f", cal.biasDegPerH[2]) + " deg/h (X/Y/Z, over the nominal Earth rate)",
       "a constant rate per axis looks the same either way: a multi-position static test (IMU turned to four "
       "headings) separates the Earth rate from the bias"});
  return groups;
}

// Per test point, what a GUI draws: spectra and per-segment delays of the
// session and of the replays.
std::vector<PointView> pointViews(const AnalysedSession& session, const Replay& replay, const FeatureSet& realFeatures,
                                  const std::vector<FeatureSet>& outputs, int K, const Stats& st) {
  const Recording& used = session.used;
  const Calibration& cal = replay.cal;
  const auto& keys = realFeatures.keys;
  const std::vector<double>& real = realFeatures.values;
  const std::size_t n = keys.size();
  std::vector<PointView> points;
  for (std::size_t p = 0; p < used.testPoints.size(); ++p) {
    PointView v;
    v.point = static_cast<int>(p);
    v.axis = used.testPoints[p].axis;
    v.frequencyHz = cal.plan.points[p].frequencyHz;
    v.amplitudeDeg = cal.plan.points[p].amplitudeDeg;
    v.real = realFeatures.spectra[p];
    v.simulated = outputs[0].spectra[p];
    for (std::size_t h = 0; h < v.simulated.gyroHarmonicPpm.size(); ++h) {
      double m = 0, s = 0;
      for (int k = 0; k < K; ++k) m += outputs[static_cast<std::size_t>(k)].spectra[p].gyroHarmonicPpm[h] / K;
      for (int k = 0; k < K; ++k) {
        const double dv = outputs[static_cast<std::size_t>(k)].spectra[p].gyroHarmonicPpm[h] - m;
        s += dv * dv / (K - 1);
      }
      v.simHarmonicStdPpm.push_back(std::sqrt(s));
    }
    const double span = cal.plan.points[p].durationS;
    const int segs = replay.ref.points[p].segments;
    for (std::size_t i = 0; i < n; ++i) {
      if (keys[i].point != static_cast<int>(p) || keys[i].quantity != Quantity::kDelay) continue;
      v.segmentMidS.push_back(-0.5 * span + (keys[i].segment + 0.5) * span / segs);
      v.realDelayUs.push_back(real[i]);
      v.simDelayUs.push_back(st.mean[i]);
      v.simDelayStdUs.push_back(st.sigma[i]);
    }
    points.push_back(std::move(v));
  }
  return points;
}

// A stated frame the data contradict: the verdict says so and names no
// effect (an effect fitted in the wrong frame absorbs the frame: a z axis
// stated down but up is an isotropic g-sensitivity of -2 Omega sin(lat) / g
// that "closes" every clean session). The gap map stays, replayed in the
// frame the data show; what the effects would say there is in the reason.
void reportContradictedFrame(const FrameCheck& frame, Diagnosis& d) {
  const std::string inFoundFrame = effectTitle(d.verdict);
  d.verdict = "frame_contradicted";
  d.verdictReason = std::string("the data show the IMU's z axis ") + (frame.zUp ? "up" : "down") +
                    "; the bench constants state " + (frame.zUp ? "down" : "up") + " (" +
                    describeImuFrame(frame.stated) + "). Correct the IMU frame in the bench constants (or the "
                    "IMU's mounting) and diagnose again; a latitude of the wrong sign (the other hemisphere) looks "
                    "the same: check it too; no effect is named. Replayed in the frame the data show, the verdict "
                    "would be: " + inFoundFrame;
  d.verdictEffects.clear();
  for (auto& c : d.gapMap) c.zAfter = c.z;
  d.gapAfter = d.gapBefore;
  for (auto& h : d.heldOut) {  // one per channel: nothing closed
    h.after = h.before;
    h.shrink = 0.0;
  }
  for (auto& e : d.effects) e.kept = false;
}

// A g-sensitivity named in the frame used has an alias in the other one:
// the specific force at rest and the vertical Earth rate both point up, so
// gyro i sees (Omega sin(lat) + k g) (up . e_i) and the frame turned over
// with k' = -k - 2 Omega sin(lat) / g gives the same data. The frame check
// keeps the frame whose k is smaller by a margin (alpha < -1/2); when the
// other frame's k' is within 3x of k the verdict says so: a z-up IMU stated
// z down with k = -1.13 Omega sin(lat) / g was named g-sensitivity -8.2
// deg/h/g (k' -11.2, its truth) with the stated frame "confirmed".
void noteFrameAlias(const Calibration& cal, Diagnosis& d) {
  const auto named = std::find(d.verdictEffects.begin(), d.verdictEffects.end(), "g_sensitivity");
  if (named == d.verdictEffects.end()) return;
  const auto fit = std::find_if(d.effects.begin(), d.effects.end(),
                                [](const EffectFit& e) { return e.name == "g_sensitivity"; });
  if (fit == d.effects.end() || fit->values.empty()) return;
  const double k = fit->values[0];
  const double other = -k - 2.0 * kEarthRateDegPerH * std::sin(cal.config.earth.latitudeDeg * kRadPerDeg);
  if (!(std::abs(other) <= 3.0 * std::abs(k))) return;
  const std::string text = std::string("with the IMU's z axis ") + (cal.frame.zUp ? "down" : "up") +
                           " instead, a g-sensitivity of " + fmt("%.2f", other) + " deg/h/g gives the same data as " +
                           fmt("%.2f", k) + " deg/h/g in the frame used: an isotropic g-sensitivity adds to the "
                           "vertical Earth rate and swing data cannot tell them apart; check the IMU's mounting "
                           "(a static test with the IMU turned over separates them)";
  d.verdictReason += "; " + text;
  d.notes.push_back(text);
}

// Table harmonic distortion is a motion: the gyros see it as the encoder
// does, and the gyro-table harmonic cells stay as simulated. An encoder
// reading error with the same harmonics is in the reading only, so those
// cells carry minus what the table's carry: an eccentric grating read by one
// head, e/r sin(theta + phi), gives a swing about zero a 2nd and a 3rd
// harmonic as a motion's x^2 and x^3 do. Over the harmonic-2 and -3 cells,
// alpha is the weighted least-squares slope of the gyro-table residuals on
// minus the table residuals: 0 for a motion, 1 for a reading error, with
// its standard error from the replays' spread. On the paper's plan an
// eccentricity of 20 urad reads alpha = 0.93 +- 0.41 (2.3 sigma from a
// motion): the table cells see the harmonic at 57 sigma, the gyros at 2.
struct ReadingShare {
  double alpha = 0.0, sigma = 0.0;
};
std::optional<ReadingShare> readingShare(const std::vector<GapCell>& map) {
  using CellKey = std::tuple<int, int, int, int>;  // point, segment, harmonic, quantity
  auto keyOf = [](const FeatureKey& k) {
    return CellKey{k.point, k.segment, k.harmonic, static_cast<int>(k.quantity)};
  };
  auto isHarmonic = [](const FeatureKey& k) {
    return (k.harmonic == 2 || k.harmonic == 3) &&
           (k.quantity == Quantity::kInPhase || k.quantity == Quantity::kQuadrature);
  };
  std::map<CellKey, const GapCell*> table;
  for (const auto& c : map)
    if (c.key.channel == Channel::kTable && isHarmonic(c.key)) table[keyOf(c.key)] = &c;
  double num = 0.0, den = 0.0;
  for (const auto& c : map) {
    if (c.key.channel != Channel::kGyroMinusTable || !isHarmonic(c.key)) continue;
    const auto t = table.find(keyOf(c.key));
    if (t == table.end()) continue;
    const double var = c.simStd * c.simStd + t->second->simStd * t->second->simStd;
    if (!(var > 0.0)) continue;
    const double minusTable = -(t->second->real - t->second->simMean);
    num += (c.real - c.simMean) * minusTable / var;
    den += minusTable * minusTable / var;
  }
  if (!(den > 0.0) || !std::isfinite(num)) return std::nullopt;
  return ReadingShare{num / den, 1.0 / std::sqrt(den)};
}

// A named table distortion the gyros do not see is an encoder reading
// error: the verdict is "unexplained" (the library has no reading error of
// those harmonics), the distortion kept as the table channel's partial
// explanation. Where the gyros cannot tell the two apart, the verdict
// keeps the distortion and says so.
void judgeMotionOrReading(const DiagnosisOptions& options, Diagnosis& d) {
  if (std::find(d.verdictEffects.begin(), d.verdictEffects.end(), "table_harmonic_distortion") ==
      d.verdictEffects.end())
    return;
  const auto share = readingShare(d.gapMap);
  if (!share) return;
  const double fromMotion = share->alpha / share->sigma, fromReading = (share->alpha - 1.0) / share->sigma;
  const std::string measured = "the share of the table's harmonics the gyros do not see is " +
                               fmt("%.2f", share->alpha) + " +- " + fmt("%.2f", share->sigma) +
                               " (0 for a motion of the table, 1 for an encoder reading error)";
  if (fromMotion >= options.gapSigma && std::abs(fromReading) <= 3.0) {
    d.verdict = "unexplained";
    d.verdictEffects.clear();
    d.verdictReason = "the table channel's harmonics are in the encoder's reading only: " + measured + ", " +
                      fmt("%.1f", fromMotion) + " sigma from a motion; an encoder reading error (an eccentric "
                      "grating, a read-head error) is not in the library, whose table harmonic distortion is a "
                      "motion and is kept as the table channel's partial explanation";
    for (auto& e : d.effects)
      if (e.name == "table_harmonic_distortion" && e.kept)
        e.note = "fits the table channel, but the gyros do not see its harmonics: a reading error, not a motion";
    return;
  }
  if (std::abs(fromReading) >= 3.0 && std::abs(fromMotion) < 3.0) return;  // a motion, as named
  const std::string text = "an encoder reading error with the same harmonics is not excluded: " + measured +
                           "; a second read head opposite the first, or an autocollimator on the table, "
                           "separates a reading error from a motion";
  d.verdictReason += "; " + text;
  d.notes.push_back(text);
}

}  // namespace
}  // namespace detail

Result<Diagnosis> diagnose(const Recording& input, const SessionInfo* info, const BenchConstants& constants,
                           const DiagnosisOptions& requested) {
  using namespace detail;
  const auto started = std::chrono::steady_clock::now();
  auto threads = threadsWithinMemory(input, requested.threads);
  if (!threads) return threads.status();
  DiagnosisOptions options = requested;
  options.threads = *threads;
  Progress progress(options);
  const std::vector<SignatureJob> jobs = signatureJobs(options);
  const std::size_t expectedReplays = kCalibrationReplays + jobs.size() + laterReplays(options);
  progress.stage("calibration", expectedReplays);
  if (progress.cancelled()) return cancelledByCaller();
  Diagnosis d;
  if (options.threads < requested.threads)
    d.notes.push_back("ran on " + std::to_string(options.threads) + " of the " + std::to_string(requested.threads) +
                      " threads asked for, to stay within the " + megabytes(kDiagnosisMemoryBudgetBytes) +
                      " memory limit");

  auto session = analyseSession(input, constants, d.notes);
  if (!session) return session.status();
  auto calibrated = calibrate(*session, info, options, progress, d.notes);
  if (!calibrated) return calibrated.status();
  FOG_RETURN_IF_ERROR(budgetReplays(input, calibrated->replay, options, d.notes));
  // The stated frame (its vertical, and its heading where it names one) until
  // the Earth-rate calibration finds them from the data; where the plan
  // cannot show them, the statement stays.
  model::applyImuFrame(constants.imuFrame, calibrated->replay.cal.config.earth);
  FOG_RETURN_IF_ERROR(calibrateEarthRateAndBias(calibrated->replay, calibrated->real.keys, calibrated->real.values,
                                                constants.imuFrame, options, d.notes));
  const Replay& replay = calibrated->replay;
  const FeatureSet& real = calibrated->real;

  progress.stage("replays", expectedReplays);
  // The nominal replay's timing audit comes from the first Monte Carlo
  // replay (seed options.seed, no effect), not from a replay of its own: the
  // start phase its seed draws moves the table, not a stamp, so the audit is
  // the one a separate replay at that seed gave (the same stamps, lost
  // frames and counter wraps), for one pass over its stamps instead of a
  // whole simulation (2 % of the diagnosis' CPU, its last serial step).
  std::shared_ptr<model::MotionTape> tape;
  std::shared_ptr<FeatureSums> sums;
  auto outputs = runReplays(replay, jobs, real.values.size(), options.threads, progress, &d.simTiming, &tape, &sums);
  if (!outputs) return outputs.status();
  // The refinement's and the pairs' replays run at the signatures' seed:
  // they play the first replay's tape and reuse its sums too.
  calibrated->replay.tape = std::move(tape);
  calibrated->replay.sums = std::move(sums);
  calibrated->replay.tapeSeed = jobs.front().seed;
  const double counterTickUs = 1e6 / replay.cal.config.samplingBoard.counterHz;
  auto gapMap = buildGapMap(real, jobs, *outputs, counterTickUs, options, d);
  if (!gapMap) return gapMap.status();
  const GapModel& gap = *gapMap;

  progress.stage("effects", expectedReplays);
  std::vector<Candidate> candidates = scoreEffects(real, gap, jobs, *outputs, d.gapMap);

  progress.stage("refinement", expectedReplays);
  FOG_RETURN_IF_ERROR(refineBest(candidates, replay, gap, real.values, d.gapMap, options, progress));
  if (progress.cancelled()) return cancelledByCaller();

  progress.stage("pairs", expectedReplays);
  const VerdictModel model = chooseModel(candidates, replay, gap, real.values, d.gapMap, options);
  if (progress.cancelled()) return cancelledByCaller();

  progress.stage("verdict", expectedReplays);
  decideVerdict(model, candidates, gap.z0, options, d);
  judgeMotionOrReading(options, d);
  if (replay.cal.frame.contradicted && d.verdict != "undetermined")
    reportContradictedFrame(replay.cal.frame, d);
  else
    noteFrameAlias(replay.cal, d);
  d.aliasGroups = aliasGroups(replay.cal);
  d.points = pointViews(*session, replay, real, *outputs, monteCarloReplays(options), gap.st);
  d.realTiming = auditTiming(session->used, replay.ref.tablePeriodS, replay.ref.imuPeriodS);
  if (progress.cancelled()) return cancelledByCaller();
  d.calibration = replay.cal;
  progress.finished();
  d.elapsedS = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return d;
}

}  // namespace fog::diagnosis
