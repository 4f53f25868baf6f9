#include "core/diagnosis/blind_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>

#include "core/common/parallel.h"
#include "core/common/units.h"
#include "core/model/random.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis {

namespace {

using Angles = std::array<double, kAxisCount>;

// Bias of every gyro steps by `step` deg/h half-way through the run.
class BiasStep final : public model::Effect {
 public:
  BiasStep(double stepDegPerH, double atS) : rate_(degPerHourToDegPerS(stepDegPerH)), at_(atS) {}
  std::string name() const override { return "bias_step"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    if (c.timeS > at_)
      for (double& s : sensed) s += rate_ * (c.timeS - at_);
  }

 private:
  double rate_, at_;
};

// Scale factor drifting linearly in time: k(t) = ppmPerMin * t / 60 s.
class ScaleFactorRamp final : public model::Effect {
 public:
  explicit ScaleFactorRamp(double ppmPerMin) : k_(ppmPerMin * 1e-6 / 60.0) {}
  std::string name() const override { return "scale_factor_ramp"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    if (started_)
      for (int a = 0; a < kAxisCount; ++a)
        acc_[a] += k_ * c.timeS * (c.tableAngleDeg[a] - last_[a]);
    started_ = true;
    last_ = c.tableAngleDeg;
    for (int a = 0; a < kAxisCount; ++a) sensed[a] += acc_[a];
  }

 private:
  double k_;
  bool started_ = false;
  Angles last_{}, acc_{};
};

// A vibration the gyros sense but the table does not: 7.3 Hz, not a harmonic
// of any swing in the plan.
class GyroVibration final : public model::Effect {
 public:
  explicit GyroVibration(double amplitudeDeg) : a_(amplitudeDeg) {}
  std::string name() const override { return "gyro_vibration"; }
  void onGyroAngle(const model::GyroContext& c, Angles& sensed) override {
    for (double& s : sensed) s += a_ * std::sin(kTwoPi * 7.3 * c.timeS);
  }

 private:
  double a_;
};

// The table wobbles at 2.37 Hz on every axis (both encoder and gyro see it).
class TableWobble final : public model::Effect {
 public:
  explicit TableWobble(double amplitudeDeg) : a_(amplitudeDeg) {}
  std::string name() const override { return "table_wobble"; }
  void onTableMotion(double t, Angles& angle) const override {
    for (double& v : angle) v += a_ * std::sin(kTwoPi * 2.37 * t);
  }

 private:
  double a_;
};

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

TestPlan blindCheckPlan() {
  TestPlan p;
  p.restBetweenS = 1.0;
  p.points.push_back({Axis::kX, 1.0, 3.0, 30.0, 2.0, 0.0});
  p.points.push_back({Axis::kX, 0.1, 10.0, 60.0, 2.0, 0.0});
  p.points.push_back({Axis::kY, 1.0, 3.0, 30.0, 2.0, 0.0});
  return p;
}

const char* trialKindName(TrialKind k) {
  switch (k) {
    case TrialKind::kSingle: return "single";
    case TrialKind::kNone: return "none";
    case TrialKind::kPair: return "pair";
    case TrialKind::kOutside: return "outside";
  }
  return "?";
}

const char* outsideEffectName(OutsideEffect e) {
  switch (e) {
    case OutsideEffect::kBiasStep: return "bias_step";
    case OutsideEffect::kScaleFactorRamp: return "scale_factor_ramp";
    case OutsideEffect::kGyroVibration: return "gyro_vibration";
    case OutsideEffect::kTableWobble: return "table_wobble";
  }
  return "?";
}

std::unique_ptr<model::Effect> makeOutsideEffect(OutsideEffect e, double m) {
  switch (e) {
    case OutsideEffect::kBiasStep: return std::make_unique<BiasStep>(m, 60.0);
    case OutsideEffect::kScaleFactorRamp: return std::make_unique<ScaleFactorRamp>(m);
    case OutsideEffect::kGyroVibration: return std::make_unique<GyroVibration>(m);
    case OutsideEffect::kTableWobble: return std::make_unique<TableWobble>(m);
  }
  return nullptr;
}

namespace {

// The scores of the trials run: top-1 / top-3 (all and at >= 3x the
// threshold), false alarms, "unexplained" recall, pairs, the confusion
// matrix, the median held-out shrink of right answers and time per trial.
void scoreTrials(BlindCheckSummary& out) {
  int top1 = 0, top3 = 0, top1x3 = 0, top3x3 = 0, none = 0, falseAlarms = 0, outside = 0, unexplained = 0, pairs = 0,
      pairHits = 0;
  std::vector<double> shrinks, seconds;
  for (const auto& r : out.trials) {
    seconds.push_back(r.elapsedS);
    const std::string label = r.kind == TrialKind::kSingle ? r.truth[0]
                              : r.kind == TrialKind::kNone  ? "none"
                              : r.kind == TrialKind::kPair  ? "pair"
                                                            : "outside: " + r.truth[0];
    out.confusion[label][r.verdict]++;
    if (r.kind == TrialKind::kSingle) {
      ++out.singleTrials;
      const bool hit1 = r.verdict == r.truth[0];
      bool hit3 = false;
      for (std::size_t i = 0; i < std::min<std::size_t>(3, r.ranked.size()); ++i) hit3 |= r.ranked[i] == r.truth[0];
      hit3 = hit3 && r.verdict != "none";
      top1 += hit1, top3 += hit3;
      if (r.magnitude >= 3.0) ++out.singleAt3x, top1x3 += hit1, top3x3 += hit3;
      if (hit1) shrinks.push_back(r.heldOutShrink);
    } else if (r.kind == TrialKind::kNone) {
      ++none;
      falseAlarms += r.verdict != "none";
    } else if (r.kind == TrialKind::kOutside) {
      ++outside;
      unexplained += r.verdict == "unexplained";
    } else {
      ++pairs;
      pairHits += std::find(r.truth.begin(), r.truth.end(), r.verdict) != r.truth.end();
    }
  }
  auto frac = [](int a, int b) { return b > 0 ? static_cast<double>(a) / b : 0.0; };
  out.top1 = frac(top1, out.singleTrials);
  out.top3 = frac(top3, out.singleTrials);
  out.top1At3x = frac(top1x3, out.singleAt3x);
  out.top3At3x = frac(top3x3, out.singleAt3x);
  out.falseAlarm = frac(falseAlarms, none);
  out.unexplainedRecall = frac(unexplained, outside);
  out.pairAnyTop1 = frac(pairHits, pairs);
  out.medianShrinkWhenRight = medianOf(shrinks);
  out.medianSecondsPerTrial = medianOf(seconds);
}

}  // namespace

Result<BlindCheckSummary> runBlindCheck(const BlindCheckOptions& options,
                                        const std::function<void(const TrialResult&)>& progress) {
  const auto wallStart = std::chrono::steady_clock::now();
  BlindCheckSummary out;
  DiagnosisOptions dopt = options.diagnosis;
  dopt.threads = 1;
  SessionInfo info;
  info.plan = options.plan;

  auto simulateSession = [&](std::uint64_t seed, double gyroDelayMs,
                             std::vector<std::unique_ptr<model::Effect>> effects) -> Result<Recording> {
    model::SimConfig config;
    config.seed = seed;
    config.fog.setOwnDelayS(gyroDelayMs * 1e-3);
    auto run = model::simulate(config, options.plan, std::move(effects));
    if (!run) return run.status();
    return protocol::decodeRecording(run->bytes);
  };

  // Detection thresholds: from the signatures in a clean session of the plan.
  auto clean = simulateSession(options.seed * 7919 + 13, 0.2358, {});
  if (!clean) return clean.status();
  DiagnosisOptions topt = options.diagnosis;
  topt.threads = options.threads;
  auto cleanDiag = diagnose(*clean, &info, {}, topt);
  if (!cleanDiag) return cleanDiag.status();
  std::map<std::string, std::vector<double>> thresholds;
  for (const auto& e : cleanDiag->effects) {
    thresholds[e.name] = e.detectionThresholds;
    if (!e.detectionThresholds.empty()) out.thresholds[e.name] = e.detectionThresholds[0];
  }

  std::vector<EffectId> identifiable;
  for (const auto& s : effectLibrary())
    if (s.identifiable) identifiable.push_back(s.id);

  const int n = std::max(1, options.trials);
  out.trials.resize(static_cast<std::size_t>(n));
  std::mutex mutex;
  parallelFor(static_cast<std::size_t>(n), options.threads, [&](std::size_t slotIndex) {
    {
      const int t = static_cast<int>(slotIndex);
      model::Random rng(model::Random::derive(options.seed, static_cast<std::uint64_t>(t)));
      TrialResult r;
      r.trial = t;
      // 60 % single, 15 % none, 10 % pairs, 15 % outside, interleaved.
      const int slot = t % 20;
      r.kind = slot < 12 ? TrialKind::kSingle : slot < 15 ? TrialKind::kNone : slot < 17 ? TrialKind::kPair : TrialKind::kOutside;
      std::vector<std::unique_ptr<model::Effect>> effects;
      auto drawLibrary = [&](EffectId id) {
        const EffectSpec& spec = effectSpec(id);
        const auto& th = thresholds[spec.name];
        const double m = std::exp(rng.uniform() * std::log(10.0));
        std::vector<double> p(spec.parameters.size(), 0.0);
        const double phi = rng.uniform() * kTwoPi;
        for (std::size_t j = 0; j < p.size(); ++j) {
          const double thj = j < th.size() ? th[j] : spec.parameters[j].reference;
          const double dir = p.size() == 1 ? (!spec.parameters[0].canBeNegative || rng.uniform() < 0.5 ? 1.0 : -1.0)
                                           : (j == 0 ? std::cos(phi) : std::sin(phi));
          p[j] = m * thj * dir;
        }
        effects.push_back(makeEffect(id, p));
        r.truth.push_back(spec.name);
        r.magnitude = r.magnitude == 0.0 ? m : std::min(r.magnitude, m);
      };
      if (r.kind == TrialKind::kSingle) {
        drawLibrary(identifiable[static_cast<std::size_t>((t / 20 * 12 + slot) % identifiable.size())]);
      } else if (r.kind == TrialKind::kPair) {
        const auto count = static_cast<double>(identifiable.size());
        const std::size_t a = static_cast<std::size_t>(rng.uniform() * count);
        std::size_t b = static_cast<std::size_t>(rng.uniform() * (count - 1.0));
        if (b >= a) ++b;
        drawLibrary(identifiable[a]);
        drawLibrary(identifiable[b]);
      } else if (r.kind == TrialKind::kOutside) {
        const auto which = static_cast<OutsideEffect>((t / 20 * 3 + slot) % kOutsideEffectCount);
        // Magnitudes that make a clear gap in the blind plan (checked in the
        // tests: the gap is significant).
        const double magnitude[] = {3.0, 300.0, 2e-4, 2e-4};
        effects.push_back(makeOutsideEffect(which, magnitude[static_cast<int>(which)] * (1.0 + rng.uniform())));
        r.truth.push_back(outsideEffectName(which));
      }
      const double gyroDelayMs = 0.2 + 0.15 * rng.uniform();
      auto rec = simulateSession(options.seed * 1000003 + static_cast<std::uint64_t>(t), gyroDelayMs, std::move(effects));
      const auto t0 = std::chrono::steady_clock::now();
      auto diag = rec ? diagnose(*rec, &info, {}, dopt) : Result<Diagnosis>(rec.status());
      r.elapsedS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!diag) {
        r.error = diag.status().toString();
        r.verdict = "error";
      } else {
        r.verdict = diag->verdict;
        for (const auto& e : diag->effects) r.ranked.push_back(e.name);
        r.heldOutShrink = 0.0;
        double before = 0, after = 0;
        for (const auto& h : diag->heldOut) before += h.before, after += h.after;
        r.heldOutShrink = before > 0 ? 1.0 - std::max(0.0, after) / before : 0.0;
        for (const auto& h : diag->heldOut) {
          const double sigma = h.cells > 0 ? h.after / std::sqrt(2.0 * h.cells) : 0.0;
          if (r.worstChannel.empty() || sigma > r.worstRemainderSigma)
            r.worstChannel = channelName(h.channel), r.worstRemainderSigma = sigma;
        }
      }
      std::lock_guard<std::mutex> lock(mutex);
      out.trials[static_cast<std::size_t>(t)] = r;
      if (progress) progress(r);
    }
  });

  scoreTrials(out);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return out;
}

std::string formatBlindCheck(const BlindCheckSummary& s) {
  std::string o;
  char b[2048];
  o += "Confusion matrix (rows: withheld truth; columns: verdict)\n";
  std::vector<std::string> cols;
  for (const auto& [truth, row] : s.confusion)
    for (const auto& [pred, count] : row)
      if (std::find(cols.begin(), cols.end(), pred) == cols.end()) cols.push_back(pred);
  std::sort(cols.begin(), cols.end());
  for (const auto& [truth, row] : s.confusion) {
    std::snprintf(b, sizeof b, "  %-34s", truth.c_str());
    o += b;
    for (const auto& [pred, count] : row) {
      std::snprintf(b, sizeof b, " %s:%d", pred.c_str(), count);
      o += b;
    }
    o += "\n";
  }
  o += "\nDetection thresholds (5 sigma in this plan, first parameter)\n";
  for (const auto& [name, th] : s.thresholds) {
    std::snprintf(b, sizeof b, "  %-28s %.4g %s\n", name.c_str(), th,
                  effectLibrary()[static_cast<std::size_t>(*effectIdFromName(name))].parameters[0].unit.c_str());
    o += b;
  }
  std::snprintf(b, sizeof b,
                "\n| metric | measured | target |\n|---|---|---|\n"
                "| top-1, single effect, >= 3x threshold (%d sessions) | %.1f %% | >= 85 %% |\n"
                "| top-3, single effect, >= 3x threshold | %.1f %% | >= 95 %% |\n"
                "| top-1 / top-3, single effect, 1x..10x (%d sessions) | %.1f %% / %.1f %% | - |\n"
                "| two effects: verdict is one of them | %.1f %% | - |\n"
                "| false alarms, no effect | %.1f %% | <= 10 %% |\n"
                "| \"unexplained\" on out-of-library effects | %.1f %% | >= 70 %% |\n"
                "| median held-out shrink, named effect right | %.1f %% | >= 80 %% |\n"
                "| median diagnosis time per session (%.0f s of data) | %.2f s | - |\n",
                s.singleAt3x, 100 * s.top1At3x, 100 * s.top3At3x, s.singleTrials, 100 * s.top1, 100 * s.top3,
                100 * s.pairAnyTop1, 100 * s.falseAlarm, 100 * s.unexplainedRecall, 100 * s.medianShrinkWhenRight,
                blindCheckPlan().totalDurationS(), s.medianSecondsPerTrial);
  o += b;
  std::snprintf(b, sizeof b, "%zu trials in %.1f s wall time\n", s.trials.size(), s.wallSeconds);
  o += b;
  return o;
}

}  // namespace fog::diagnosis
