// The replay of a session on the simulator, and the messages every stage of
// the diagnosis uses (diagnosis_stages.h).
#include "core/diagnosis/diagnosis_stages.h"
#include "core/diagnosis/replay_passes.h"

#include <cmath>
#include <cstdio>
#include <span>

#include "core/model/random.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis::detail {

Status cancelledByCaller() { return cancelled("diagnosis cancelled: nothing was concluded"); }

// Runs the simulated chain and builds its recording as it is made, two
// simulated seconds at a time: a long session's stream is never held whole
// (140 MB of bytes for an hour). The frames go to the decoder as they are,
// not encoded: the recording is the one the bytes would give
// (SimulatorFrames.GiveTheRecordingTheirBytesGive), without the checksums
// and parsing that were a fifth of a diagnosis' time.
//
// maxFrames: the stream's budget (Simulator::frameBound()); a configuration
// that could emit more is refused before anything runs.
Result<Recording> simulateRecording(const model::SimConfig& config, const TestPlan& plan, double maxFrames,
                                    std::vector<std::unique_ptr<model::Effect>> effects, model::MotionTape* recordTape,
                                    const model::MotionTape* playTape, bool* tapeMatched) {
  constexpr double kChunkS = 2.0;
  auto sim = model::Simulator::create(config, plan, maxFrames);
  if (!sim) return sim.status();
  countReplay();
  for (auto& e : effects) (*sim)->addEffect(std::move(e));
  (*sim)->recordMotionTape(recordTape);
  (*sim)->playMotionTape(playTape);
  protocol::StreamDecoder decoder;
  std::vector<protocol::Frame> frames;
  for (double until = kChunkS; (*sim)->advance(until, frames); until += kChunkS) {
    decoder.push(std::span<const protocol::Frame>(frames));
    frames.clear();
  }
  decoder.push(std::span<const protocol::Frame>(frames));
  if (tapeMatched) *tapeMatched = (*sim)->tapeMatched();
  return decoder.finish();
}

Result<FeatureSet> Replay::run(std::uint64_t seed, const EffectList& effects, ReplayExtras extras) const {
  if (progress && progress->cancelled()) return cancelledByCaller();
  auto features = runUncounted(seed, effects, extras);
  if (progress) progress->replayDone();
  return features;
}

Result<FeatureSet> Replay::runUncounted(std::uint64_t seed, const EffectList& effects, ReplayExtras extras) const {
  model::SimConfig config = cal.config;
  config.seed = seed;
  // A fitted value outside the effect's modelled range is never replayed.
  for (const auto& [id, p] : effects) FOG_RETURN_IF_ERROR(checkParameters(id, p));
  auto effectList = [&] {
    std::vector<std::unique_ptr<model::Effect>> list;
    for (const auto& [id, p] : effects) list.push_back(makeEffect(id, p, context));
    return list;
  };
  // The encoder quantises exact motion, so without a change of phase every
  // replay would read the table alike and the table cells would have no
  // spread; a start phase drawn per seed (well under a sample period's
  // worth of motion) re-draws the quantisation pattern, as a different
  // session would.
  TestPlan plan = cal.plan;
  model::Random phase(model::Random::derive(seed, 0x7ab1e));
  for (auto& p : plan.points) p.startPhaseDeg += 0.1 * (phase.uniform() - 0.5);
  const model::MotionTape* play = extras.playTape;
  const FeatureSums* reuse = extras.reuseSums;
  if (!play && tape && seed == tapeSeed) play = tape.get();
  if (!reuse && sums && seed == tapeSeed) reuse = sums.get();
  bool matched = true;
  auto rec = simulateRecording(config, plan, maxFrames, effectList(), extras.recordTape, play, &matched);
  // A tape that was not this chain's cannot happen within one diagnosis (one
  // calibrated chain); were it to, the replay is run again without it.
  if (rec && !matched) rec = simulateRecording(config, plan, maxFrames, effectList());
  if (!rec) return rec.status();
  if (extras.timing) *extras.timing = auditTiming(*rec, ref.tablePeriodS, ref.imuPeriodS);
  return extractFeatures(*rec, ref, extras.residual, extras.recordSums, reuse);
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// "gyro h3_in_phase of test point 2, segment 3", for messages.
std::string describeCell(const FeatureKey& k) {
  std::string s = std::string(channelName(k.channel)) + " " + quantityName(k);
  if (k.axis >= 0) s += std::string(" (gyro ") + "xyz"[k.axis] + ")";
  return s + " of test point " + std::to_string(k.point + 1) + ", segment " + std::to_string(k.segment + 1);
}

// Ok when the recording's feature i and its formal error are finite;
// otherwise a refusal naming the cell (kCorruptData).
Status checkFinite(const FeatureSet& real, std::size_t i) {
  const bool value = std::isfinite(real.values[i]);
  if (value && std::isfinite(real.formalStd[i])) return Status::ok();
  return corruptData("the diagnosis cannot compare this session with its replay: the recording's " +
                     describeCell(real.keys[i]) + (value ? " has a standard error of " + fmt("%g", real.formalStd[i])
                                                         : " is " + fmt("%g", real.values[i])) +
                     ", not a finite number (a sample in that segment is not a finite number or far beyond its "
                     "range); nothing was concluded");
}

}  // namespace fog::diagnosis::detail
