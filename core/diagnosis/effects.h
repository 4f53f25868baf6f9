#pragma once
// The effect library of the sim-to-real diagnosis (docs/diagnosis.md): every
// candidate unmodelled effect as a parametric model::Effect that plugs into
// the simulator's hooks (core/model/effect.h) without touching its stages,
// plus what the diagnosis needs to fit it: named parameters with units, a
// reference magnitude, and whether the features respond linearly.
//
// Contracts:
//  - makeEffect(id, params, context) builds a fresh, unreset effect; the same
//    parameters, context and seed give the same stream (effects draw only from
//    the Random they are reset with).
//  - Parameters are in the units of EffectParameter::unit; zero parameters
//    leave the chain exactly unchanged.
//  - Qt-free; effects are not thread-safe (one simulator per thread).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/model/effect.h"
#include "core/model/sim_config.h"

namespace fog::diagnosis {

enum class EffectId {
  kBiasDrift,              // temperature-like ramp of every gyro's bias
  kScaleFactorError,       // gyro scale factor off by a constant
  kScaleFactorAsymmetry,   // different scale factor for positive and negative rates
  kScaleFactorNonlinearity,// cubic rate term
  kMisalignment,           // cross-axis coupling of the swing into the other gyros
  kGSensitivity,           // rate error proportional to the tilt of a horizontal axis
  kFirstOrderLag,          // first-order low-pass of the gyro output
  kTableHarmonicDistortion,// 2nd/3rd harmonic in the table motion itself
  kEncoderCyclicError,     // encoder reading error periodic in angle
  kTimestampJitter,        // white jitter on the IMU frame stamps
  kClockDrift,             // IMU stamps run off the table's time base
  kDroppedFrames,          // IMU frames lost at random
  kEarthRateProjection,    // wrong latitude / heading for the Earth-rate projection
};
inline constexpr int kEffectCount = 13;

struct EffectParameter {
  std::string name;  // "scale_factor_ppm"
  std::string unit;  // "ppm"
  double reference = 0.0;  // magnitude used for the linear signature
  // False for a parameter that cannot be negative (a time constant, a
  // variance, a loss rate): its signature is a one-sided difference.
  bool canBeNegative = true;
  // Largest magnitude the effect is modelled for, in `unit`. A fitted value
  // beyond it is not a finding: the linear signature, measured at the
  // reference, is extrapolated far past where it was measured, or the chain
  // stops being physical (a clock drift of -1e6 ppm stops the IMU's clock
  // and stamps its frames backwards). The diagnosis never replays such a
  // value (checkParameters()).
  double maxMagnitude = 0.0;
  // What the number is, in the words of the standard that defines it
  // (docs/diagnosis.md, "Parameters and their definitions"), and which
  // standard that is ("" where no standard defines the quantity; then the
  // definition is the project's own and says so).
  std::string definition;
  std::string standard;
  // The parameter's name before issue 44 where its meaning changed, and the
  // factor that turns a value in that old meaning into this one (new =
  // legacyScale * old); "" where it did not change. readEffects() accepts
  // `legacyName:value` for it, with a note.
  std::string legacyName;
  double legacyScale = 1.0;
};

struct EffectSpec {
  EffectId id;
  std::string name;         // stable key, "scale_factor_error" (JSON, CLI options)
  std::string title;        // in words for people, "scale-factor error"
  std::string description;  // one line for reports
  std::vector<EffectParameter> parameters;
  // Features respond linearly in the parameters (fitted by variable
  // projection); otherwise fitted with Ceres on the full forward model.
  bool linear = true;
  // False when swing data cannot tell it from a nominal parameter the replay
  // calibrates (then it is reported in an alias group, never fitted).
  bool identifiable = true;
};

// What some effects need to know about the nominal chain.
struct EffectContext {
  model::EarthParams earth;  // nominal Earth-rate projection (kEarthRateProjection)
  // kDroppedFrames loses exactly its expected share of frames, evenly spaced,
  // instead of a random set: the diagnosis' replay uses this so that the
  // lost-frame count per segment is a deterministic function of the loss rate
  // (a recording's random pattern cannot be reproduced; only its rate can).
  bool expectedDrops = false;
};

const std::vector<EffectSpec>& effectLibrary();
const EffectSpec& effectSpec(EffectId id);
Result<EffectId> effectIdFromName(const std::string& name);

// An effect's name or a diagnosis verdict ("none", "unexplained",
// "undetermined", "frame_contradicted") in words for people: what the text report and the GUI
// show; the name stays the key of the JSON. An unknown name is returned as is.
std::string effectTitle(const std::string& name);

// Ok when every parameter is finite and within its maxMagnitude (and not
// negative where it cannot be); otherwise what is out of range, in words.
Status checkParameters(EffectId id, const std::vector<double>& params);

// params.size() must equal the spec's parameter count.
std::unique_ptr<model::Effect> makeEffect(EffectId id, const std::vector<double>& params,
                                          const EffectContext& context = {});

}  // namespace fog::diagnosis
