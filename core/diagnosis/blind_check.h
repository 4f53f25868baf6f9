#pragma once
// Self-consistency check of the diagnosis (docs/diagnosis.md; called the
// blind check before issue 44, and its identifiers still are): sessions are
// simulated with an effect the diagnosis is not told about — one from the
// library at 1x..10x its detection threshold, none, two at once, or one
// outside the library — diagnosed with the same library, and scored. Not
// blind to the library's own parameterisation: tests/independent's
// blind_reference.py is the check on sessions the library did not make.
//
// Deterministic for a given seed and trial count (threads change only the
// order of work). Qt-free; runs its own worker threads.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/test_plan.h"
#include "core/diagnosis/diagnosis.h"
#include "core/model/effect.h"

namespace fog::diagnosis {

// The plan of the self-consistency sessions: X 1 Hz / 3 deg 30 s, X 0.1 Hz / 10 deg 60 s,
// Y 1 Hz / 3 deg 30 s (two frequencies and two axes in two minutes).
TestPlan blindCheckPlan();

enum class TrialKind { kSingle, kNone, kPair, kOutside };
const char* trialKindName(TrialKind k);

// Effects outside the library, for the "unexplained" recall.
enum class OutsideEffect { kBiasStep, kScaleFactorRamp, kGyroVibration, kTableWobble };
inline constexpr int kOutsideEffectCount = 4;
const char* outsideEffectName(OutsideEffect e);
std::unique_ptr<model::Effect> makeOutsideEffect(OutsideEffect e, double magnitude);


struct TrialResult {
  int trial = 0;
  TrialKind kind = TrialKind::kNone;
  std::vector<std::string> truth;
  double magnitude = 0.0;      // multiple of the detection threshold (single / pair)
  std::string verdict;
  std::vector<std::string> ranked;  // effect names, best first
  double heldOutShrink = 0.0;  // of the verdict's model
  // The channel whose held-out remainder is largest, in sigma of its chi2
  // ((chi2 - n) / sqrt(2 n)).
  std::string worstChannel;
  double worstRemainderSigma = 0.0;
  double elapsedS = 0.0;
  std::string error;           // non-empty when the diagnosis failed
};

struct BlindCheckOptions {
  int trials = 40;
  std::uint64_t seed = 1;
  int threads = 2;
  TestPlan plan = blindCheckPlan();
  DiagnosisOptions diagnosis;  // its threads are set to 1: trials run in parallel
};

struct BlindCheckSummary {
  std::vector<TrialResult> trials;
  std::map<std::string, double> thresholds;  // effect -> detection threshold of its first parameter
  // truth label -> predicted verdict -> count
  std::map<std::string, std::map<std::string, int>> confusion;
  int singleTrials = 0, singleAt3x = 0;
  double top1 = 0.0, top3 = 0.0;             // single-effect sessions, all magnitudes
  double top1At3x = 0.0, top3At3x = 0.0;     // single-effect sessions at >= 3x threshold
  double pairAnyTop1 = 0.0;                  // two-effect sessions: verdict is one of the two
  double falseAlarm = 0.0;                   // no-effect sessions with a verdict other than "none"
  double unexplainedRecall = 0.0;            // outside-library sessions answered "unexplained"
  double medianShrinkWhenRight = 0.0;        // held-out shrink, single sessions named right
  double medianSecondsPerTrial = 0.0;
  double wallSeconds = 0.0;
};

Result<BlindCheckSummary> runBlindCheck(const BlindCheckOptions& options,
                                        const std::function<void(const TrialResult&)>& progress = {});
std::string formatBlindCheck(const BlindCheckSummary& s);

}  // namespace fog::diagnosis
