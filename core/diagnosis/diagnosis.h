#pragma once
// Sim-to-real gap diagnosis (docs/diagnosis.md).
//
//   auto d = diagnosis::diagnose(recording, &info, constants, {});
//   d->verdict  // "scale_factor_error", "none", "unexplained", "undetermined"
//               // or "frame_contradicted"
//
// 1. Replay: the session's test points are rebuilt as a plan and run on the
//    simulator with the nominal model, calibrated to the session (table
//    frequency error, encoder noise, ARW, pulse equivalent, gyro bias per
//    axis, the measured lag as the nominal delay, counter settings).
// 2. Timing audit of the real stream and the replay.
// 3. Gap map: residual features (features.h) of the real recording as
//    z-scores against the replay's Monte Carlo spread (a few seeds; spread
//    pooled over the segments of a test point).
// 4. Effects (effects.h): each one's signature is the change of the features
//    when it is added to the replay (common random numbers); linear effects are
//    fitted by weighted least squares on the training blocks (even segments),
//    the others with Ceres on the full forward model. An effect is kept only
//    when the held-out blocks (odd segments) improve beyond chance and BIC on
//    all blocks agrees; two effects at once are tried.
// 5. Verdict: the best kept effect; "none" when real and replay agree;
//    "unexplained" when the gap is significant and nothing in the library
//    closes it on held-out blocks; "undetermined" (with the reason) when a
//    chi2 the verdict rests on is not a finite number. Every verdict needs a
//    finite chi2 in every channel: a cell whose recording or replay value,
//    spread or z is not finite makes diagnose() refuse (kCorruptData for the
//    recording's, kInternal for the replay's) before any verdict; fits and
//    scores that are not finite are not ranked, never kept.
//
// Memory (kDiagnosisMemoryBudgetBytes): the session is checked before
// anything runs; the calibrated replay's stream (model::Simulator::
// frameBound(), which holds whatever the effects do to the stamps) before
// any replay runs. Over budget: kOutOfRange, never an abort. A fitted effect
// value outside its modelled range (EffectParameter::maxMagnitude) is never
// replayed.
//
// Contracts: Qt-free; thread-safe (no shared state; it starts its own worker
// threads); errors are Status values, never exceptions. Deterministic for a
// given recording and options.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/common/imu_frame.h"
#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"
#include "core/diagnosis/effects.h"
#include "core/diagnosis/features.h"
#include "core/model/sim_config.h"

namespace fog::diagnosis {

struct DiagnosisOptions {
  int monteCarloSeeds = 4;   // replays used for the simulator's own spread
  int threads = 2;           // worker threads for the replays (fewer when memory needs it)
  std::uint64_t seed = 9001; // seeds of the replays: seed, seed + 1, ...
  // Held-out improvement (delta chi-square on odd segments) an effect must reach.
  double heldOutDeltaChi2 = 16.0;
  // The whole gap is "significant" when chi2 - n exceeds this many sigma of
  // chi2(n). The same test on the held-out remainder of a kept model, over
  // all held-out cells and within each channel: a significant remainder
  // makes the verdict "unexplained" (the kept effect is then a partial
  // explanation).
  double gapSigma = 5.0;
  // A kept model that leaves a significant remainder is reported as a
  // partial explanation only when it closes at least this share of the
  // held-out gap; below it the verdict names no effect. A decaying swing's
  // gap took up table distortion, encoder error or a lag closing 1-19 %
  // (and a telegraph latency's a g-sensitivity closing 0 %): each had its
  // delta chi2 of 16 on a gap of thousands, none explains it.
  double partialExplanationShare = 0.5;
  // An effect is not kept when it raises the held-out chi2 of any one
  // channel by more than this (it closes the gap in one place by opening it
  // in another).
  double channelWorsening = 25.0;
  int refineTop = 3;         // effects re-evaluated on the exact forward model
  bool allowPairs = true;
  // The IMU's bias instability, a first-order Gauss-Markov rate (1 sigma,
  // deg/h, and its correlation time, s), as its static noise test measured
  // it (the Noise view). The replays carry it, so it sets how far the gyro
  // trend cells may wander by chance. One recording cannot tell such a
  // wander from a bias drift or step, so it is not calibrated from the
  // session; unset, the replays assume the simulator's default (0.5 deg/h
  // over 300 s) and the diagnosis says so in its notes.
  std::optional<double> biasInstabilityDegPerH;
  std::optional<double> biasCorrelationS;
  // Progress and cancellation, for a GUI. Called from diagnose()'s own
  // threads, one call at a time (never concurrently), at least once per
  // replay (~0.1-0.5 s apart): `fraction` of the work done, in [0, 1] and
  // never decreasing, and the stage: "calibration", "replays", "effects",
  // "refinement", "pairs", "verdict". Returning false cancels: diagnose()
  // stops within about one replay's time and returns StatusCode::kCancelled.
  // The callback must not block (post to the GUI thread).
  std::function<bool(double fraction, const std::string& stage)> progress;
};

// Where the IMU's z axis points, as the bench constants state it and as the
// data show it (docs/diagnosis.md, "The IMU's frame"). A swing about a
// horizontal axis turns the vertical Earth rate into the other horizontal
// gyro, in quadrature with the angle, with opposite signs for z up and z
// down; each vertical is fitted (with its own best heading) to those cells.
// A vertical Earth rate and an isotropic g-sensitivity k look alike (k g
// adds to the vertical rate): the frame is turned over only when the stated
// one would need |k| > 1.5 Omega sin(lat) / g (14.5 deg/h/g at 40 deg), far
// beyond a fibre-optic gyro's.
struct FrameCheck {
  ImuFrame stated;                   // as the bench constants state it
  // The plan's swings turn enough of the vertical Earth rate into the cells
  // (sigma of verticalRatio <= 0.3); else nothing below is set.
  bool checked = false;
  // The vertical Earth rate the data show, as a multiple of the vertical the
  // replays were first configured in (the stated one, else z down): +1 as
  // configured, -1 turned over; with its standard error.
  double verticalRatio = 0.0, verticalRatioStd = 0.0;
  double chiSquareDown = 0.0;        // the cells, z down at its best heading
  double chiSquareUp = 0.0;          // ... z up
  // verticalRatio is 5 sigma clear of -1/2, the boundary between the two.
  bool decisive = false;
  bool zUp = false;                  // the vertical the replays use
  // Stated, and the data show the other vertical decisively: the verdict is
  // "frame_contradicted" and names no effect.
  bool contradicted = false;
};

struct Calibration {
  model::SimConfig config;   // the replay's nominal configuration
  TestPlan plan;             // the replay's plan (one point per analysed test point)
  double lagMs = 0.0;        // weighted mean measured lag, the replay's nominal delay
  double tableFrequencyErrorPpm = 0.0;
  double encoderNoiseDeg = 0.0;
  double arwDegPerSqrtH = 0.0;
  std::array<double, kAxisCount> biasDegPerH{};  // at the calibrated heading
  // Whether the user stated the replays' bias instability
  // (config.fog.biasInstabilityDegPerH, biasCorrelationS; DiagnosisOptions),
  // false: the simulator's default was assumed.
  bool biasInstabilityStated = false;
  // The table's heading as the Earth rate in the gyros shows it (sessions do
  // not state it), with its standard error.
  double headingDeg = 0.0;
  double headingStdDeg = 0.0;
  FrameCheck frame;
};

// One cell of the gap map: a feature of the real session against the replay.
struct GapCell {
  FeatureKey key;
  double real = 0.0, simMean = 0.0, simStd = 0.0;
  double z = 0.0;             // (real - simMean) / simStd
  double zAfter = 0.0;        // the same with the verdict's effects added (= z when none)
  bool heldOut = false;       // odd segment: not used to fit effects
  // False when the replays do not spread in this cell (by less than a tenth
  // of its floor) and the recording matches them within that floor (a timing
  // cell of a clean session: no frame lost anywhere). Such a cell carries no
  // information, so it is no degree of freedom: it is left out of every cell
  // count the significance tests use.
  bool informative = true;
};

// Headline gap of one channel: chi2 of its informative cells and
// sqrt(chi2 / n) (1 = no gap).
struct ChannelGap {
  Channel channel = Channel::kTable;
  int cells = 0;
  double chiSquare = 0.0;
  double rmsZ = 0.0;
  double maxAbsZ = 0.0;
};

// Held-out gap before / after an effect, as the excess chi2 over its cells
// (chi2 - n, 0 = noise only); shrink = 1 - after / before.
struct HeldOutShrink {
  Channel channel = Channel::kTable;
  int cells = 0;
  double before = 0.0, after = 0.0, shrink = 0.0;
};

struct EffectFit {
  std::string name, description;
  std::vector<EffectParameter> parameters;
  std::vector<double> values, standardErrors;  // fitted on all blocks, in the parameters' units
  // Training delta chi2 - k ln n (BIC-penalised); ranks the effects. None:
  // the effect has no signature in this session's features (not scored).
  std::optional<double> score;
  double trainDeltaChi2 = 0.0, heldOutDeltaChi2 = 0.0;
  double heldOutShrink = 0.0;    // all held-out cells together
  std::vector<HeldOutShrink> perChannel;
  // Per parameter: the magnitude whose signature alone gives delta chi2 = 25
  // over all cells of this session (5 sigma), from the linear signature.
  std::vector<double> detectionThresholds;
  bool exact = false;            // evaluated on the full forward model (not the linear signature)
  bool kept = false;
  std::string note;
};

struct AliasGroup {
  std::string name;
  std::vector<std::string> members;
  std::string value;           // what the data does fix, "lag 0.4658 ms"
  std::string separatingTest;  // what would tell the members apart
};

// Per test point, what a GUI draws.
struct PointView {
  int point = 0;
  Axis axis = Axis::kX;
  double frequencyHz = 0.0, amplitudeDeg = 0.0;
  PointSpectrum real, simulated;          // simulated: the first replay
  std::vector<double> simHarmonicStdPpm;  // gyro harmonic spread over the replays
  std::vector<double> segmentMidS;        // relative to the record middle
  std::vector<double> realDelayUs, simDelayUs, simDelayStdUs;  // per segment
};

struct Diagnosis {
  Calibration calibration;
  TimingAudit realTiming, simTiming;
  std::vector<GapCell> gapMap;
  std::vector<ChannelGap> gapBefore, gapAfter;  // informative cells, per channel
  double chiSquare = 0.0;                        // all cells, before
  int cells = 0;                                 // informative cells (the degrees of freedom)
  bool gapSignificant = false;
  std::vector<PointView> points;
  std::vector<EffectFit> effects;                // ranked, best first
  std::vector<HeldOutShrink> heldOut;            // held-out shrink of the verdict's model per channel
  std::vector<std::string> verdictEffects;       // the kept effects
  // Effect name, "none", "unexplained", "undetermined" or
  // "frame_contradicted" (FrameCheck; no effect is named).
  std::string verdict;
  std::string verdictReason;
  std::vector<AliasGroup> aliasGroups;
  std::vector<std::string> notes;
  double elapsedS = 0.0;
};

// Peak memory a diagnosis may use, counted as `ulimit -v` counts it (address
// space, docs/reliability.md): 1 GB. Its samples (the session's, its
// analysis copy, one replay per thread with the builder's growth) may take
// kDiagnosisSampleBudgetBytes of it; the rest is the program's own (code and
// libraries, thread stacks, malloc's per-thread arenas). Measured: an hour's
// session at 1 kHz / 500 Hz (200 MB of samples) peaked at 907 MB resident on
// 2 threads and did not fit in 1 GiB of address space; on 1 thread it does.
// A session whose diagnosis would need more even on one thread is refused
// with kOutOfRange before anything runs; one that fits on fewer threads than
// asked gets fewer.
inline constexpr double kDiagnosisMemoryBudgetBytes = 1e9;
inline constexpr double kDiagnosisSampleBudgetBytes = 0.75e9;

// info may be null (a raw stream): the plan is then rebuilt from the
// recording alone. Fails when the analysis gives no delay for any test point.
Result<Diagnosis> diagnose(const Recording& recording, const SessionInfo* info,
                           const BenchConstants& constants, const DiagnosisOptions& options = {});

std::string formatDiagnosisText(const Diagnosis& d);
std::string formatDiagnosisJson(const Diagnosis& d);

}  // namespace fog::diagnosis
