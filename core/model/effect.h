#pragma once
// Effect: the one interface through which an unmodelled effect (harmonic
// distortion, scale-factor error, jitter, clock drift, lag, dropped frames,
// ...) plugs into the simulated chain without touching its stages.
//
// Each hook is called by one stage and may change the value it is given; the
// defaults leave everything unchanged. Hooks are called in time order within a
// run. onTableMotion is called by two stages (encoder and gyro) for different
// instants, so it must be a pure function of time. Effects run in the order
// they were added.

#include <array>
#include <string>

#include "core/common/test_plan.h"

namespace fog::model {

class Random;

struct GyroContext {
  double timeS = 0.0;                              // instant the FOG sensed
  std::array<double, kAxisCount> tableAngleDeg{};  // true table angles then
  // The body's rotation sensed by each gyro since the start of the run: the
  // integral of the body rate from the table's motion alone (no Earth rate,
  // bias or noise), deg. Equal to the table angle of the same axis (minus
  // its start) when the IMU is mounted square and only that axis moves.
  std::array<double, kAxisCount> bodyAngleDeg{};
  // Specific force of gravity in the body frame at rest, in g (|f| = 1).
  std::array<double, kAxisCount> specificForceG{};
  // Attitude: body to local north-east-down, row-major (model/attitude.h).
  std::array<std::array<double, kAxisCount>, kAxisCount> bodyToLocal{};
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;

  // Called once before a run; rng is the effect's own reproducible stream.
  virtual void reset(Random& rng) { (void)rng; }

  // Turntable stage: true table angle per axis at timeS.
  virtual void onTableMotion(double timeS, std::array<double, kAxisCount>& angleDeg) const {
    (void)timeS, (void)angleDeg;
  }
  // Whether onTableMotion may change the motion. A run whose effects all
  // say false senses what the same chain and seed sense without them, so it
  // may replay their MotionTape (Simulator::playMotionTape). True unless an
  // effect states otherwise: a motion taken as unchanged would be wrong.
  virtual bool changesTableMotion() const { return true; }
  // Encoder stage: the reading about to be quantised.
  virtual void onEncoderReading(double timeS, std::array<double, kAxisCount>& readingDeg) {
    (void)timeS, (void)readingDeg;
  }
  // FOG stage: cumulative sensed angle per axis, before pulse quantisation.
  virtual void onGyroAngle(const GyroContext& context, std::array<double, kAxisCount>& sensedDeg) {
    (void)context, (void)sensedDeg;
  }
  // Sampling-board stage: the true time a frame is stamped; set drop to lose
  // the frame (the sequence number still advances, as on a lossy link).
  virtual void onTableStamp(double& stampS, bool& drop) { (void)stampS, (void)drop; }
  virtual void onImuStamp(double& stampS, bool& drop) { (void)stampS, (void)drop; }
};

}  // namespace fog::model
