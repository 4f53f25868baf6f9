#pragma once
// The stages of diagnose() and what they hand on to each other: internal to
// core/diagnosis (namespace fog::diagnosis::detail; not installed, included
// by no file outside core/diagnosis). The public interface is diagnosis.h.
//
//   replay.cpp            the replay, and the messages every stage uses
//   calibration.cpp       the session as analysed, the replay calibrated to it
//                         (Earth rate and biases included), the memory budget
//   gap_map.cpp           the replays' jobs, the gap map, its per-channel sums
//   scoring.cpp           the linear fits, the effects' scores, the exact
//                         refinement, the model and the verdict
//   diagnosis.cpp         diagnose(), which runs them in order, and the views
//   diagnosis_format.cpp  formatDiagnosisText() / formatDiagnosisJson()
//
// Each function below says what it takes, what it gives and what it refuses;
// the comments at the definitions say why it works the way it does.

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/diagnosis/diagnosis.h"
#include "core/model/simulator.h"

namespace fog::diagnosis::detail {

using EffectList = std::vector<std::pair<EffectId, std::vector<double>>>;

// Replays run by calibrateEarthRateAndBias().
inline constexpr std::size_t kCalibrationReplays = 5;

// The status of a diagnosis the caller cancelled (kCancelled, "nothing was
// concluded"): every stage returns it once Progress::cancelled() is true.
Status cancelledByCaller();

// Progress of a diagnosis, counted in replays (each is most of the cost of
// its step), and the caller's cancel request. Thread-safe: replays run on
// several threads; the caller's callback is called one call at a time.
class Progress {
 public:
  explicit Progress(const DiagnosisOptions& options) : callback_(options.progress) {}

  // Enters a stage; `expectedReplays` is the whole diagnosis' replay count
  // as now known (it grows as the stages learn what they will run).
  void stage(const char* name, std::size_t expectedReplays) {
    std::lock_guard lock(mutex_);
    stage_ = name;
    expected_ = std::max(expected_, expectedReplays);
    reportLocked();
  }
  void replayDone() {
    std::lock_guard lock(mutex_);
    ++done_;
    reportLocked();
  }
  void finished() {
    std::lock_guard lock(mutex_);
    fraction_ = 1.0;
    if (callback_ && !cancelled_) callback_(1.0, stage_);
  }
  bool cancelled() const { return cancelled_.load(); }

 private:
  void reportLocked() {
    if (!callback_ || cancelled_) return;
    // The last few percent are left to finished(): the estimate of the
    // replays still to come can be short.
    if (expected_ > 0)
      fraction_ = std::max(fraction_, std::min(0.99, static_cast<double>(done_) / static_cast<double>(expected_)));
    if (!callback_(fraction_, stage_)) cancelled_ = true;
  }

  std::function<bool(double, const std::string&)> callback_;
  std::mutex mutex_;
  std::string stage_ = "calibration";
  std::size_t done_ = 0, expected_ = 0;
  double fraction_ = 0.0;
  std::atomic<bool> cancelled_{false};
};

// ---- The replay (replay.cpp) ------------------------------------------------

// The recording the simulated chain `config` makes of `plan`, with `effects`
// added, built as it is simulated. Refuses (kOutOfRange, from
// model::Simulator::create) a configuration whose stream could pass
// maxFrames, before anything runs; a chain the simulator refuses otherwise
// is refused with its status.
//
// recordTape / playTape (Simulator::recordMotionTape / playMotionTape): the run
// records its gyro and encoder stages, or plays one recorded by a run of the same
// configuration and plan. *tapeMatched (when given) is false when the tape
// played was not this chain's: the recording is then not to be used.
Result<Recording> simulateRecording(const model::SimConfig& config, const TestPlan& plan, double maxFrames,
                                    std::vector<std::unique_ptr<model::Effect>> effects = {},
                                    model::MotionTape* recordTape = nullptr, const model::MotionTape* playTape = nullptr,
                                    bool* tapeMatched = nullptr);

// What a replay gives besides its features, taken from the same recording
// (simulating the chain again for them would cost a whole replay).
struct ReplayExtras {
  // The features' cumulative gyro residual, a pass over the IMU samples that
  // only the views of the first replay draw.
  ResidualView residual = ResidualView::kSkip;
  // When set, receives the replay's timing audit (auditTiming() against
  // ref's periods).
  TimingAudit* timing = nullptr;
  // When set, receives the replay's motion tape (model::MotionTape).
  model::MotionTape* recordTape = nullptr;
  // When set, a tape of the replay at this seed without effects: the replay
  // plays it (unless an effect changes the table's motion) instead of
  // computing its gyro and encoder stages, with the same result.
  const model::MotionTape* playTape = nullptr;
  // The same for the features' sums (FeatureSums): recorded, or reused where
  // the replay's stamps and readings are the recorded ones.
  FeatureSums* recordSums = nullptr;
  const FeatureSums* reuseSums = nullptr;
};

// The simulated chain calibrated to a session (cal), the reference its
// features are taken against (ref) and the effects' context: run() replays
// it with a seed and effects and gives the replay's features.
struct Replay {
  Calibration cal;
  FeatureReference ref;
  EffectContext context;
  Progress* progress = nullptr;  // counts the replays; a cancel makes run() fail at once
  // Frames one replay's stream may hold (set by budgetReplays()); a replay over
  // it fails with kOutOfRange instead of growing.
  double maxFrames = model::kMaxSimulatedFrames;
  // Sensed instants and encoder readings a motion tape of one replay holds
  // (set by budgetReplays());
  // 0 when no tape fits the memory budget, and none is recorded.
  std::size_t tapeSenses = 0, tapeReadings = 0;
  // The gap map's first replay's tape (seed tapeSeed, no effect), set once
  // it has run: every later replay at that seed plays it (the refinement's
  // and the pairs' replays run at the signatures' seed).
  std::shared_ptr<const model::MotionTape> tape;
  std::shared_ptr<const FeatureSums> sums;  // that replay's features' sums
  std::uint64_t tapeSeed = 0;

  // The features of the replay at `seed` with `effects` added, against ref.
  // Counts one replay in `progress` once it starts. Refuses kCancelled at
  // once (nothing run) after a cancel, an effect whose parameters are
  // outside its modelled range (checkParameters(); never replayed), a
  // stream over maxFrames (kOutOfRange), and the features' own refusals.
  // One replay (simulateRecording()), and extractFeatures()' passes over it
  // (with extras.residual's), plus auditTiming()'s when extras.timing is set.
  Result<FeatureSet> run(std::uint64_t seed, const EffectList& effects, ReplayExtras extras = {}) const;

 private:
  Result<FeatureSet> runUncounted(std::uint64_t seed, const EffectList& effects, ReplayExtras extras) const;
};

// printf of one number, for messages.
std::string fmt(const char* f, double v);

// "gyro h3_in_phase of test point 2, segment 3": the cell `k`, for messages.
std::string describeCell(const FeatureKey& k);

// Ok when the recording's feature i and its formal error are finite;
// otherwise kCorruptData naming the cell and the value.
Status checkFinite(const FeatureSet& real, std::size_t i);

// ---- Statistics shared by the gap map and the scoring -----------------------

// The cells whose Monte Carlo variance is pooled: one feature of one test
// point over its segments.
using GroupKey = std::tuple<Channel, Quantity, int, int, int>;  // channel, quantity, harmonic, axis, point
GroupKey groupKey(const FeatureKey& k);

// Each cell's replay mean and spread (sigma), its z against them, and
// whether it is held out (odd segments) or a training cell.
struct Stats {
  std::vector<double> mean, sigma, z;
  std::vector<bool> held;
  // The cell is a stamp-interval variance: a sample variance spreads in
  // proportion to the variance, so an effect that raises it (stamp jitter)
  // raises its spread with it (spreadWith()).
  std::vector<bool> variance;
};

// Cell i's spread with an effect that changes its replay value by `change`:
// sigma, scaled for a variance cell by (mean + change) / mean when the
// effect raises it. (Held to the clean replay's spread, a jitter of 2 us rms
// fitted at 3.99 +- 0.01 us^2 left "1276 sigma" in the timing cells.)
inline double spreadWith(const Stats& st, std::size_t i, double change) {
  if (i < st.variance.size() && st.variance[i] && st.mean[i] > 0.0 && change > 0.0)
    return st.sigma[i] * (st.mean[i] + change) / st.mean[i];
  return st.sigma[i];
}

// The sum of r[i]^2 over the cells whose mask[i] == which (with st.held:
// false for the training cells, true for the held-out ones).
double chi2(const std::vector<double>& r, const std::vector<bool>& mask, bool which);

// Subtracts from z its weighted least-squares fit on the columns (in z
// units), fitted on the training rows (held == false) or on all rows and
// applied to every row; gives the coefficients. When the fit is not
// possible (no column with a signature, too few rows, a singular or
// non-finite solution) z is left as it is and the coefficients are 0.
Eigen::VectorXd projectOut(const std::vector<std::vector<double>>& cols, std::vector<double>& z,
                           const std::vector<bool>& held, bool trainingOnly);

// The gap of each channel over its informative cells: count, chi2, rms and
// largest |z|, of z (after == false) or of zAfter. One entry per channel.
std::vector<ChannelGap> channelGaps(const std::vector<GapCell>& cells, bool after);

// Whether the gap is significant: chi2 - n > sigma * sqrt(2 n) over all
// informative cells, or within any one channel. A gap in one channel (a
// flicker bias in the gyro trends: excess 110 over 80 cells, 8.7 sigma) is
// diluted below the line by the other channels' cells (91 over 270, 3.9
// sigma, with the table under-dispersed), as the held-out remainder test
// already knows.
bool gapIsSignificant(double chiSquare, int cells, const std::vector<ChannelGap>& channels, double sigma);

// The groups gapIsSignificant() tests besides all cells: each channel, and
// the gyro trend cells on their own. A wander of the bias lives in the
// trends only, which the gyro channel's harmonic and cross-axis cells
// dilute: a flicker bias on the paper's plan left 5.2 sigma in its 24 trend
// cells and 2.9 in the gyro channel's 64.
std::vector<ChannelGap> significanceGroups(const std::vector<GapCell>& cells, const std::vector<ChannelGap>& channels);

// Per channel, the excess chi2 (chi2 - cells) of the held-out informative
// cells in `before` and in `after` (z per cell, in the order of cells), and
// the share of it that `after` closes (0 when there was none); the same
// over all channels in *total when it is given.
std::vector<HeldOutShrink> shrinkPerChannel(const std::vector<GapCell>& cells, const std::vector<double>& before,
                                            const std::vector<double>& after, HeldOutShrink* total);

// The largest increase of one channel's held-out chi2 from `before` to
// `after` (0 or less when no channel gets worse).
double worstChannelWorsening(const std::vector<GapCell>& cells, const std::vector<double>& before,
                             const std::vector<double>& after);

// ---- The stages of diagnose(), in order -------------------------------------
// Each takes what the ones before it established and hands on a typed result:
// the session as analysed, the calibrated replay, the replays, the gap map,
// the ranked candidates, the verdict's model.

// ---- Calibration (calibration.cpp) ------------------------------------------

// The session's test points that gave a delay, in recording order, with
// their analysis.
struct AnalysedSession {
  Recording used;
  std::vector<analysis::TestPointResult> results;  // one per used test point
};

// Takes the recording (in degrees, protocol::RecordingBuilder) and the
// bench constants; runs the delay analysis and gives the test points that
// gave a delay, in recording order, with their results (the others are
// noted as left out). Refuses with the analysis' own refusals, and
// kInsufficientData when no test point gave a delay.
Result<AnalysedSession> analyseSession(const Recording& recording, const BenchConstants& constants,
                                       std::vector<std::string>& notes);

// The replay calibrated to the session, and the session's own features
// against the replay's reference.
struct CalibratedReplay {
  Replay replay;
  FeatureSet real;
};

// Takes the analysed session (and its session info: latitude, settle times,
// start phases); gives the replay calibrated to it (sample periods, table
// frequency error, ARW, lag, encoder noise, the plan as recorded, the bias
// instability as stated or assumed, with a note), counting its replays in
// `progress`, and the session's features against the replay's reference.
// Runs no replay: the heading and the biases are
// calibrateEarthRateAndBias()'s, the frame budget budgetReplays()'. Refuses
// kCorruptData when a number the replay is built from, or any of the
// session's features, is not finite; the features' own refusals;
// kInvalidArgument when the calibrated chain is not a valid one.
Result<CalibratedReplay> calibrate(const AnalysedSession& session, const SessionInfo* info,
                                   const DiagnosisOptions& options, Progress& progress,
                                   std::vector<std::string>& notes);

// Takes the calibrated replay (in the stated frame's vertical), the
// session's features (keys and values, in line with the replay's) and the
// stated frame; runs kCalibrationReplays replays and sets the replay's
// frame check and vertical (FrameCheck), its heading (and its spread) and
// each gyro's bias, with notes. Leaves them as they were (ok, with a note)
// when the plan has too few trend or cross-axis cells for it (6), or fewer
// than 2 that the heading moves. Refuses kCancelled, a replay's failure,
// kInternal for replay features that do not line up with the session's or a
// heading or bias that is not finite, and the calibrated chain's own
// validation.
Status calibrateEarthRateAndBias(Replay& replay, const std::vector<FeatureKey>& keys, const std::vector<double>& real,
                                 const ImuFrame& stated, const DiagnosisOptions& options,
                                 std::vector<std::string>& notes);

// `bytes` as "123 MB", for messages.
std::string megabytes(double bytes);

// Takes the session and the threads asked for; gives the most threads, 1 to
// `requested`, whose estimated peak ((1.5 + 1.5 threads) times the
// session's samples) stays within kDiagnosisSampleBudgetBytes. Refuses
// kOutOfRange (with the sizes and what fits) when even one thread would
// pass it.
Result<int> threadsWithinMemory(const Recording& recording, int requested);

// Takes the session, the calibrated replay and the options; lowers
// options.threads (with a note) until the session and one replay's stream
// per thread fit the budget, and sets replay.maxFrames to the calibrated
// replay's frame bound. Refuses kOutOfRange when the calibrated replay
// cannot run or even one replay would pass the budget.
Status budgetReplays(const Recording& input, Replay& replay, DiagnosisOptions& options,
                     std::vector<std::string>& notes);

// ---- The gap map (gap_map.cpp) ----------------------------------------------

// The replays diagnose() runs side by side: K Monte Carlo replays of the
// nominal model (the first K jobs, seeds seed .. seed + K - 1), then one per
// signature (an effect's parameter at +-reference, seed `seed`: common
// random numbers with the first replay).
struct SignatureJob {
  std::uint64_t seed;
  EffectList effects;
  int effectIndex = -1, parameter = -1;  // in effectLibrary(); -1 for a Monte Carlo replay
  double sign = 1.0;
};

// K, the Monte Carlo replays: options.monteCarloSeeds, at least 2.
int monteCarloReplays(const DiagnosisOptions& options);

// The jobs, in order: K Monte Carlo replays (seeds seed .. seed + K - 1),
// then for every identifiable effect's parameter a +reference job, followed
// by a -reference job when the parameter can be negative (seed `seed`).
// Refuses nothing.
std::vector<SignatureJob> signatureJobs(const DiagnosisOptions& options);

// The replays expected after the calibration's and the signature jobs (an
// estimate, for the progress bar).
std::size_t laterReplays(const DiagnosisOptions& options);

// Runs the jobs on `threads` threads, one replay each; gives their features
// in job order, the first job's with its cumulative gyro residual (the
// views draw it) and its timing audit in *firstTiming when that is given
// (the first job is the nominal replay at options.seed: its stamps are the
// nominal chain's, which the start phase a seed draws does not move). When
// replay.tapeSenses > 0 the first job records its motion tape into *tape
// and its features' sums into *sums (when given) and the later jobs at its
// seed wait for them and play and reuse them (the signature jobs: common
// random numbers with the first).
// Refuses kCancelled after a cancel, the first failed replay's status
// ("replay: ..."), and kInternal when a replay's features are not `cells`
// long.
Result<std::vector<FeatureSet>> runReplays(const Replay& replay, const std::vector<SignatureJob>& jobs,
                                           std::size_t cells, int threads, const Progress& progress,
                                           TimingAudit* firstTiming = nullptr,
                                           std::shared_ptr<model::MotionTape>* tape = nullptr,
                                           std::shared_ptr<FeatureSums>* sums = nullptr);

// The gap map's statistics: each cell's replay mean and spread, its z, the
// nuisance directions every fit includes, and z with them taken out.
struct GapModel {
  Stats st;
  std::vector<std::vector<double>> nuisance;  // columns, in z units
  std::vector<double> z0;                     // st.z without the nuisance directions
  std::vector<double> base;                   // the first replay's features (signatures are against it)
  double chiTrain = 0.0, chiHeld = 0.0;       // chi2 of z0 on training / held-out cells
};

// Takes the session's features, the jobs with their features (the K Monte
// Carlo replays first) and the counter's tick; gives the gap statistics, the
// nuisance directions and z without them, and fills d.gapMap, d.cells,
// d.chiSquare, d.gapSignificant and d.gapBefore. Refuses kCorruptData when a
// feature of the session (or its formal error) is not finite, kInternal
// when a replay's feature, a cell's spread or z, or the chi2 is not.
Result<GapModel> buildGapMap(const FeatureSet& realFeatures, const std::vector<SignatureJob>& jobs,
                             const std::vector<FeatureSet>& outputs, double counterTickUs,
                             const DiagnosisOptions& options, Diagnosis& d);

// ---- Scoring (scoring.cpp) --------------------------------------------------

// An effect of the library with its signature and linear fit.
struct Candidate {
  std::size_t lib;                        // index in effectLibrary()
  std::vector<std::vector<double>> cols;  // signature per parameter, in z units per parameter unit
  EffectFit fit;
  std::vector<double> zAfter;             // z with the effect's fit taken out
};

// Takes the session's features, the gap model, the jobs with their
// features and the gap map; gives every identifiable effect with its
// signature, linear fit (with the nuisance directions, on the training
// cells), detection thresholds, score and held-out shrink, best score
// first. Refuses nothing: an effect without a signature, or whose fit is
// not finite, is not scored (it goes last, with a note).
std::vector<Candidate> scoreEffects(const FeatureSet& realFeatures, const GapModel& g,
                                    const std::vector<SignatureJob>& jobs, const std::vector<FeatureSet>& outputs,
                                    const std::vector<GapCell>& gapMap);

// Takes the ranked candidates; fits the top options.refineTop nonlinear ones
// whose linear fit already gains what the held-out test asks with Ceres on
// the replay, then replays each scored one of the top within its modelled
// range and decides whether it is kept (score, held-out gain, BIC, no
// channel made worse by more than options.channelWorsening), with a note
// when not. Refuses kCancelled after a cancel; a failed Ceres fit keeps the
// linear values (noted), a failed replay leaves the effect not kept.
Status refineBest(std::vector<Candidate>& cands, const Replay& replay, const GapModel& g,
                  const std::vector<double>& real, const std::vector<GapCell>& gapMap,
                  const DiagnosisOptions& options, const Progress& progress);

// The verdict's model: the kept effects (best first) and the z they leave.
struct VerdictModel {
  std::vector<std::size_t> members;  // indices in the candidates
  std::vector<double> z;
};

// Takes the refined candidates; gives the kept one with the largest
// held-out gain and, when options.allowPairs, the best partner among the top
// five when the pair, replayed, gains on the held-out cells, passes BIC and
// makes no channel worse (the partner is then marked kept and noted). No
// member and z0 when nothing was kept. Refuses nothing (a pair that cannot be
// replayed is not taken).
VerdictModel chooseModel(std::vector<Candidate>& cands, const Replay& replay, const GapModel& g,
                         const std::vector<double>& real, const std::vector<GapCell>& gapMap,
                         const DiagnosisOptions& options);

// Takes the model, the candidates and z0; fills d's zAfter per cell,
// gapAfter, heldOut, verdict, verdict effects and reason, and effects.
// "undetermined" when a chi2 or fitted value the verdict rests on is not
// finite; otherwise "none", "unexplained" (also when the model leaves a
// significant held-out remainder) or the first effect's name. Refuses
// nothing.
void decideVerdict(const VerdictModel& chosen, const std::vector<Candidate>& cands, const std::vector<double>& z0,
                   const DiagnosisOptions& options, Diagnosis& d);

}  // namespace fog::diagnosis::detail
