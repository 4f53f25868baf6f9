#pragma once
// Simulator: runs a test plan through the modelled chain and emits the
// sampling board's byte stream (docs/protocol.md), exactly what a real board
// sends, so every consumer goes through the same decoder.
//
// Deterministic: the same configuration, plan, effects and seed give
// bit-identical bytes. Motion is analytic; noise processes are sampled exactly
// at the instants the chain observes them, so there is no integration step.
// Not thread-safe; one simulator per thread.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/common/status.h"
#include "core/common/test_plan.h"
#include "core/model/effect.h"
#include "core/model/sim_config.h"
#include "core/model/turntable.h"
#include "core/protocol/frame.h"

namespace fog::model {

// What the simulation built in, per test point, to compare estimates against.
struct TestPointTruth {
  int index = 0;
  Axis axis = Axis::kX;
  double frequencyHz = 0.0;  // true swing frequency (with the table's rate error)
  double amplitudeDeg = 0.0;
  double lagS = 0.0;          // gyro output behind the stamped table angle
  double imuDelayS = 0.0;     // lag + table read delay
  double gyroDelayS = 0.0;    // IMU delay - board delay
  double gyroTrendDegPerS = 0.0;  // bias + Earth-rate projection on the swing axis
};

// Frames a simulator may emit unless its caller states a smaller budget:
// a day at 11 kHz of frames, far beyond any real chain (1.5 kHz). A
// configuration needing more (a sample period of 1e-300 s) is refused by
// create() instead of running for ever.
inline constexpr double kMaxSimulatedFrames = 1e9;

// What the physical stages computed at each instant of one run, before any
// effect's hook: what the gyros sensed (the context effects read and the
// sensed angles: motion, body rotation, Earth rate, bias and noise; before
// onGyroAngle) and what the encoder read (the motion at the reading instant,
// with the grating's eccentricity; before onEncoderReading). The instants,
// the motion and the noise draws depend on the configuration, the plan and
// the seed alone when no effect changes the table's motion, so a run of the
// same chain at the same seed with other such effects can play the tape
// instead of computing them: bit for bit what it would compute (a replay's
// physics, about half of its time). 22 doubles per sensed instant (once per
// IMU frame, or per register update) and 4 per table frame.
struct MotionTape {
  struct Sense {
    GyroContext context;
    std::array<double, kAxisCount> sensed{};
  };
  struct Reading {
    double timeS = 0.0;
    std::array<double, kAxisCount> deg{};
  };
  std::vector<Sense> senses;
  std::vector<Reading> readings;
};

class Simulator {
 public:
  // The configuration and plan must be valid (see create()).
  Simulator(const SimConfig& config, const TestPlan& plan);
  ~Simulator();

  // Checks configuration and plan, then builds a simulator. Refuses
  // (kOutOfRange, saying how many frames) a run whose frameBound() exceeds
  // maxFrames: a caller that holds the stream states its memory as frames.
  static Result<std::unique_ptr<Simulator>> create(const SimConfig& config, const TestPlan& plan,
                                                   double maxFrames = kMaxSimulatedFrames);

  // Most frames the whole run can emit, whatever the effects do: every
  // stream ends at a sample index fixed by the configuration (a table or IMU
  // frame whose nominal instant is more than streamSlackS() past endS()
  // ends its stream even if an effect stamped it earlier; a stamp past
  // endS(), or not finite, ends it too). Each step of advance() emits or
  // drops one of these frames, so advance() always returns. Counted in
  // double: a period of 1e-300 s gives a huge count, not an overflow.
  struct FrameCounts {
    double table = 0.0, imu = 0.0, status = 0.0;
    double total() const { return table + imu + status; }
  };
  FrameCounts frameCounts() const;
  double frameBound() const { return frameCounts().total(); }
  double streamSlackS() const { return 1.0 + 0.01 * endS(); }

  // Effects must be added before the first advance().
  void addEffect(std::unique_ptr<Effect> effect);

  // Before the first advance(): the run appends its gyro and encoder stages to *tape
  // (which must outlive the run), or plays *tape, recorded by a run of the
  // same configuration (seed included) and plan, instead of computing the
  // stages. A tape is played only when no effect changesTableMotion(); else it
  // is ignored and the stages computed. A run that asks for an instant the
  // tape does not hold (another configuration's tape) computes the rest
  // with its gyro stage's state lost: tapeMatched() is then false, and the
  // caller must run again without the tape.
  void recordMotionTape(MotionTape* tape) { recordTape_ = tape; }
  void playMotionTape(const MotionTape* tape) { playTape_ = tape; }
  bool tapeMatched() const;

  // Appends every frame stamped before untilS (true seconds since the start)
  // to out. Returns false once the whole plan has been emitted. At most
  // frameBound() frames over the whole run.
  bool advance(double untilS, std::vector<std::uint8_t>& out);
  // The same frames, not encoded (protocol::StreamDecoder::push takes them):
  // for a replay that would decode its own bytes at once. One simulator
  // emits either bytes or frames, not both.
  bool advance(double untilS, std::vector<protocol::Frame>& out);
  // Runs to the end of the plan.
  void runToEnd(std::vector<std::uint8_t>& out);

  double timeS() const { return nowS_; }
  double endS() const { return turntable_.endS(); }
  std::vector<TestPointTruth> truth() const;
  const SimConfig& config() const { return config_; }

 private:
  class Impl;
  void start();
  template <class Out>
  bool advanceInto(double untilS, Out& out);

  SimConfig config_;
  TestPlan plan_;
  Turntable turntable_;
  std::vector<std::unique_ptr<Effect>> effects_;
  MotionTape* recordTape_ = nullptr;
  const MotionTape* playTape_ = nullptr;
  std::unique_ptr<Impl> impl_;
  double nowS_ = 0.0;
};

// Convenience: the whole run's bytes and its truth.
struct SimulatedRun {
  std::vector<std::uint8_t> bytes;
  std::vector<TestPointTruth> truth;
};
Result<SimulatedRun> simulate(const SimConfig& config, const TestPlan& plan,
                              std::vector<std::unique_ptr<Effect>> effects = {});

}  // namespace fog::model
