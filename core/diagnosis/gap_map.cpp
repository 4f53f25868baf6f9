// The diagnosis' gap map (diagnosis_stages.h): the replays it runs, each
// cell's z against their spread, and the gap per channel.
#include "core/diagnosis/diagnosis_stages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <map>
#include <mutex>

#include "core/common/parallel.h"

namespace fog::diagnosis::detail {

GroupKey groupKey(const FeatureKey& k) { return {k.channel, k.quantity, k.harmonic, k.axis, k.point}; }

namespace {
// The smallest difference a cell resolves, whatever the replays' spread.
// An interval variance also allows the counter's own dither: a stream whose
// period is not a whole number of counter ticks alternates between two
// interval lengths, p(1-p) tick^2 <= tick^2 / 4 of variance that a recording
// stamped at another resolution (an imported CSV) does not show.
double floorFor(const FeatureKey& k, double mean, double counterTickUs) {
  if (k.unit == Unit::kFrames) return 0.5;
  if (k.unit == Unit::kMicrosecondsSquared) return 1e-3 + 1e-3 * std::abs(mean) + 0.25 * counterTickUs * counterTickUs;
  if (k.unit == Unit::kMicroDegSquared) return 1e-3 * std::abs(mean) + 1e-6;
  if (k.channel == Channel::kTiming) return 0.05;  // interval ppm
  return 1e-6;
}

}  // namespace

std::vector<HeldOutShrink> shrinkPerChannel(const std::vector<GapCell>& cells, const std::vector<double>& before,
                                            const std::vector<double>& after, HeldOutShrink* total) {
  std::vector<HeldOutShrink> out;
  HeldOutShrink all;
  for (int c = 0; c < kChannelCount; ++c) {
    HeldOutShrink s;
    s.channel = static_cast<Channel>(c);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (!cells[i].heldOut || !cells[i].informative || static_cast<int>(cells[i].key.channel) != c) continue;
      ++s.cells;
      s.before += before[i] * before[i];
      s.after += after[i] * after[i];
    }
    all.cells += s.cells;
    all.before += s.before;
    all.after += s.after;
    s.before -= s.cells, s.after -= s.cells;
    s.shrink = s.before > 0.0 ? 1.0 - std::max(0.0, s.after) / s.before : 0.0;
    out.push_back(s);
  }
  all.before -= all.cells, all.after -= all.cells;
  all.shrink = all.before > 0.0 ? 1.0 - std::max(0.0, all.after) / all.before : 0.0;
  if (total) *total = all;
  return out;
}

// Largest increase of a channel's held-out chi2 from `before` to `after`.
double worstChannelWorsening(const std::vector<GapCell>& cells, const std::vector<double>& before,
                             const std::vector<double>& after) {
  std::array<double, kChannelCount> delta{};
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].heldOut)
      delta[static_cast<std::size_t>(cells[i].key.channel)] += after[i] * after[i] - before[i] * before[i];
  return *std::max_element(delta.begin(), delta.end());
}

bool gapIsSignificant(double chiSquare, int cells, const std::vector<ChannelGap>& channels, double sigma) {
  auto beyond = [sigma](double chi2, int n) {
    return n > 0 && chi2 - n > sigma * std::sqrt(2.0 * static_cast<double>(n));
  };
  if (beyond(chiSquare, cells)) return true;
  return std::any_of(channels.begin(), channels.end(),
                     [&](const ChannelGap& c) { return beyond(c.chiSquare, c.cells); });
}

// The headline gap of the informative cells of `channel` that `include` takes.
template <typename Include>
ChannelGap gapOver(const std::vector<GapCell>& cells, Channel channel, Include include, bool after) {
  ChannelGap g;
  g.channel = channel;
  for (const auto& cell : cells) {
    if (cell.key.channel != channel || !cell.informative || !include(cell.key)) continue;
    const double z = after ? cell.zAfter : cell.z;
    ++g.cells;
    g.chiSquare += z * z;
    g.maxAbsZ = std::max(g.maxAbsZ, std::abs(z));
  }
  g.rmsZ = g.cells ? std::sqrt(g.chiSquare / g.cells) : 0.0;
  return g;
}

std::vector<ChannelGap> significanceGroups(const std::vector<GapCell>& cells, const std::vector<ChannelGap>& channels) {
  std::vector<ChannelGap> groups = channels;
  groups.push_back(gapOver(
      cells, Channel::kGyro, [](const FeatureKey& k) { return k.quantity == Quantity::kTrend; }, false));
  return groups;
}

std::vector<ChannelGap> channelGaps(const std::vector<GapCell>& cells, bool after) {
  std::vector<ChannelGap> out;
  for (int c = 0; c < kChannelCount; ++c)
    out.push_back(gapOver(cells, static_cast<Channel>(c), [](const FeatureKey&) { return true; }, after));
  return out;
}

int monteCarloReplays(const DiagnosisOptions& options) { return std::max(2, options.monteCarloSeeds); }

// Signatures are central differences (+reference and -reference) where the
// parameter can be negative: cells that respond to the square of an
// amplitude (the residual variance takes up an encoder cyclic error's
// harmonics above the fifth) then have no linear part, instead of a chord
// through the reference that overstates them hundreds of times at the
// small magnitudes actually fitted. The exact re-evaluation below keeps
// the quadratic part. Other parameters take a one-sided difference.
std::vector<SignatureJob> signatureJobs(const DiagnosisOptions& options) {
  std::vector<SignatureJob> jobs;
  const int K = monteCarloReplays(options);
  for (int k = 0; k < K; ++k) jobs.push_back({options.seed + static_cast<std::uint64_t>(k), {}});
  const auto& library = effectLibrary();
  for (std::size_t e = 0; e < library.size(); ++e) {
    if (!library[e].identifiable) continue;
    for (std::size_t j = 0; j < library[e].parameters.size(); ++j) {
      for (double sign : {1.0, -1.0}) {
        if (sign < 0.0 && !library[e].parameters[j].canBeNegative) continue;
        std::vector<double> p(library[e].parameters.size(), 0.0);
        p[j] = sign * library[e].parameters[j].reference;
        jobs.push_back({options.seed, {{library[e].id, p}}, static_cast<int>(e), static_cast<int>(j), sign});
      }
    }
  }
  return jobs;
}

// Replays beyond the calibration's and the signature jobs: the exact
// re-evaluations, a Ceres fit or two (a few rounds of a replay per
// parameter), a pair (the timing audit has no replay of its own: it is the
// first job's). An estimate, for the progress bar.
std::size_t laterReplays(const DiagnosisOptions& options) {
  return 4 * static_cast<std::size_t>(std::max(0, options.refineTop)) + 1;
}

Result<std::vector<FeatureSet>> runReplays(const Replay& replay, const std::vector<SignatureJob>& jobs,
                                           std::size_t cells, int threads, const Progress& progress,
                                           TimingAudit* firstTiming, std::shared_ptr<model::MotionTape>* tapeOut,
                                           std::shared_ptr<FeatureSums>* sumsOut) {
  std::vector<Result<FeatureSet>> outputs(jobs.size(), Status(StatusCode::kInternal, "not run"));
  // The first job records its motion tape; the others at its seed wait for it
  // (jobs are taken in order, so it is already running) and play it. Its
  // Monte Carlo siblings at other seeds run meanwhile.
  auto tape = std::make_shared<model::MotionTape>();
  auto sums = std::make_shared<FeatureSums>();
  const bool useTape = replay.tapeSenses > 0 && !jobs.empty() && jobs[0].effects.empty();
  if (useTape) {
    tape->senses.reserve(replay.tapeSenses);
    tape->readings.reserve(replay.tapeReadings);
  }
  std::mutex mutex;
  std::condition_variable recorded;
  bool tapeDone = false, tapeOk = false;
  parallelFor(jobs.size(), threads, [&](std::size_t i) {
    ReplayExtras extras;
    if (i == 0) {
      extras = {ResidualView::kCompute, firstTiming, useTape ? tape.get() : nullptr, nullptr,
                useTape ? sums.get() : nullptr, nullptr};
      outputs[i] = replay.run(jobs[i].seed, jobs[i].effects, extras);
      {
        std::lock_guard lock(mutex);
        tapeDone = true;
        tapeOk = useTape && outputs[i].isOk();
      }
      recorded.notify_all();
      return;
    }
    if (useTape && jobs[i].seed == jobs[0].seed) {
      std::unique_lock lock(mutex);
      recorded.wait(lock, [&] { return tapeDone; });
      if (tapeOk) extras.playTape = tape.get(), extras.reuseSums = sums.get();
    }
    outputs[i] = replay.run(jobs[i].seed, jobs[i].effects, extras);
  });
  if (tapeOut && useTape && outputs[0]) *tapeOut = tape;
  if (sumsOut && useTape && outputs[0]) *sumsOut = sums;
  if (progress.cancelled()) return cancelledByCaller();
  std::vector<FeatureSet> features;
  features.reserve(outputs.size());
  for (auto& o : outputs) {
    if (!o) return Status(o.status().code(), "replay: " + o.status().message());
    if (o->values.size() != cells)
      return Status(StatusCode::kInternal, "the replay's features do not line up with the session's");
    features.push_back(std::move(*o));
  }
  return features;
}

// Fills d's gap map and its headline numbers.
// Refuses (kCorruptData / kInternal) when a cell's inputs or statistics are
// not finite numbers: a NaN z would make chi2 NaN, and "chi2 - n > 5 sigma"
// is false for NaN, which once read as "real and simulated data agree".
Result<GapModel> buildGapMap(const FeatureSet& realFeatures, const std::vector<SignatureJob>& jobs,
                             const std::vector<FeatureSet>& outputs, double counterTickUs,
                             const DiagnosisOptions& options, Diagnosis& d) {
  const auto& keys = realFeatures.keys;
  const std::vector<double>& real = realFeatures.values;
  const auto& library = effectLibrary();
  const std::size_t n = real.size();
  const int K = monteCarloReplays(options);
  GapModel g;
  Stats& st = g.st;
  for (std::size_t i = 0; i < n; ++i) {
    FOG_RETURN_IF_ERROR(checkFinite(realFeatures, i));
    for (const auto& o : outputs)
      if (!std::isfinite(o.values[i]))
        return Status(StatusCode::kInternal, "the diagnosis cannot compare this session with its replay: the replay's " +
                                                 describeCell(keys[i]) + " is " + fmt("%g", o.values[i]) +
                                                 ", not a finite number; nothing was concluded");
  }
  st.mean.assign(n, 0.0);
  st.sigma.assign(n, 0.0);
  st.z.assign(n, 0.0);
  st.held.assign(n, false);
  st.variance.assign(n, false);
  for (std::size_t i = 0; i < n; ++i) st.variance[i] = keys[i].unit == Unit::kMicrosecondsSquared;
  for (int k = 0; k < K; ++k)
    for (std::size_t i = 0; i < n; ++i) st.mean[i] += outputs[static_cast<std::size_t>(k)].values[i] / K;
  std::map<GroupKey, std::pair<double, double>> pooled;  // sum of squares, dof
  for (std::size_t i = 0; i < n; ++i) {
    auto& pool = pooled[groupKey(keys[i])];
    for (int k = 0; k < K; ++k) {
      const double dv = outputs[static_cast<std::size_t>(k)].values[i] - st.mean[i];
      pool.first += dv * dv;
    }
    pool.second += K - 1;
  }
  // Lost frames: the replay loses the expected share of frames evenly (the
  // random pattern of a recording cannot be replayed, only its rate), so a
  // correct loss rate still leaves the recording's Poisson spread. Its
  // expected count per cell is the session's own total spread over the cells
  // in proportion to their frames (the dropped-frames signature).
  std::vector<double> lostExpected(n, 0.0), lostPerUnit(n, 0.0);
  {
    std::size_t dropJob = jobs.size();
    for (std::size_t j = 0; j < jobs.size(); ++j)
      if (jobs[j].effectIndex >= 0 && library[static_cast<std::size_t>(jobs[j].effectIndex)].id == EffectId::kDroppedFrames)
        dropJob = j;
    double total = 0.0, shares = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (keys[i].quantity == Quantity::kImuLost) {
        total += std::max(0.0, real[i]);
        if (dropJob < jobs.size()) {
          const double perUnit = (outputs[dropJob].values[i] - outputs[0].values[i]) /
                                 library[static_cast<std::size_t>(jobs[dropJob].effectIndex)].parameters[0].reference;
          lostPerUnit[i] = std::max(0.0, perUnit);
          shares += lostPerUnit[i];
        }
      }
    for (std::size_t i = 0; i < n; ++i)
      if (keys[i].quantity == Quantity::kImuLost && shares > 0.0) lostExpected[i] = total * lostPerUnit[i] / shares;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto& pool = pooled[groupKey(keys[i])];
    // Pooled over few replays: (1 + 1/K) for the uncertain mean, and
    // dof / (dof - 2) so that z^2 averages 1 (a z against an estimated spread
    // is t-distributed).
    const double dof = pool.second;
    const double var = pool.first / std::max(1.0, dof) * (1.0 + 1.0 / K) * (dof > 4.0 ? dof / (dof - 2.0) : 2.0);
    const double fl = floorFor(keys[i], st.mean[i], counterTickUs);
    const double formal = realFeatures.formalStd[i];
    st.sigma[i] = std::sqrt(std::max(var, formal * formal) + fl * fl + lostExpected[i]);
    st.z[i] = (real[i] - st.mean[i]) / st.sigma[i];
    if (!(std::isfinite(st.sigma[i]) && st.sigma[i] > 0.0 && std::isfinite(st.z[i])))
      return Status(StatusCode::kInternal, "the diagnosis cannot score the " + describeCell(keys[i]) + ": real " +
                                               fmt("%g", real[i]) + ", replays " + fmt("%g", st.mean[i]) + " +- " +
                                               fmt("%g", st.sigma[i]) + " give no finite z; nothing was concluded");
    st.held[i] = keys[i].segment % 2 == 1;
    // A cell whose replays spread by less than a tenth of its floor (the
    // timing cells of a simulator whose clocks have no jitter, the lost-frame
    // cells of a session that lost nothing) is no statistical quantity: it
    // counts as a degree of freedom only when the recording departs from the
    // replays by more than its floor.
    const bool informative = std::sqrt(pool.first / std::max(1.0, dof)) > 0.1 * fl ||
                             std::abs(real[i] - st.mean[i]) > fl;
    d.gapMap.push_back({keys[i], real[i], st.mean[i], st.sigma[i], st.z[i], st.z[i], st.held[i], informative});
    if (informative) ++d.cells;
  }
  d.chiSquare = chi2(st.z, st.held, false) + chi2(st.z, st.held, true);
  d.gapBefore = channelGaps(d.gapMap, false);
  d.gapSignificant = gapIsSignificant(d.chiSquare, d.cells, significanceGroups(d.gapMap, d.gapBefore), options.gapSigma);
  g.base = outputs[0].values;
  // Nuisance directions the calibration already owns: one delay for the whole
  // session (the alias group) and one constant trend per gyro axis (bias).
  // Every fit includes them, so an effect is credited only with what they
  // cannot absorb.
  // The sample periods are calibrated from the recording too (an IMU whose
  // crystal is off by ppm): one mean interval per stream is the replay's,
  // and an effect is credited only with what varies beyond it.
  auto& nuisance = g.nuisance;
  nuisance.assign(3 + kAxisCount, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    if (keys[i].quantity == Quantity::kDelay) nuisance[0][i] = 1.0 / st.sigma[i];
    if (keys[i].quantity == Quantity::kTableInterval) nuisance[1][i] = 1.0 / st.sigma[i];
    if (keys[i].quantity == Quantity::kImuInterval) nuisance[2][i] = 1.0 / st.sigma[i];
    if (keys[i].quantity == Quantity::kTrend) nuisance[3 + static_cast<std::size_t>(keys[i].axis)][i] = 1.0 / st.sigma[i];
  }
  for (auto it = nuisance.begin(); it != nuisance.end();)
    it = std::all_of(it->begin(), it->end(), [](double v) { return v == 0.0; }) ? nuisance.erase(it) : it + 1;
  g.z0 = st.z;
  projectOut(nuisance, g.z0, st.held, true);
  g.chiTrain = chi2(g.z0, st.held, false);
  g.chiHeld = chi2(g.z0, st.held, true);
  if (!std::isfinite(d.chiSquare) || !std::isfinite(g.chiTrain) || !std::isfinite(g.chiHeld))
    return Status(StatusCode::kInternal, "the gap map's chi2 is not a finite number (" + fmt("%g", d.chiSquare) +
                                             "); nothing was concluded");
  return g;
}

}  // namespace fog::diagnosis::detail
