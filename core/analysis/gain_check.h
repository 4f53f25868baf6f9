#pragma once
// The "gain" validity check (docs/method.md, "Validity checks"): the gyro's
// amplitude against the table's, judged against the bench's stated scale
// tolerance (BenchConstants::gainToleranceFraction, default 1 %).
//
// A wrong pulse equivalent or a wrong frame period (imported rates times a
// frame period) scales every increment by one factor and leaves the phase,
// and so the delay, untouched: "gyro/table ratio 499.9995" passed as a valid
// result. The ratio a point measures is the gyro's scale times its dynamics
// at that frequency (a first-order lag, a resonance), and the dynamics are
// the measurand of a frequency response, not an error. The rule:
//
//   scale = |gyro/table ratio| / D(f),  valid when |scale - 1| <= tolerance,
//
// where D(f) = |H(f)| / K is the dynamics' own gain at the point's frequency,
// from the frequency-response model chosen for the axis' points
// (frequency_response.h: the pure delay, D = 1; a first-order lag; a
// second-order response) fitted to the points of that axis that passed
// every other check, when they span two or more frequencies. Dynamics come
// with phase (the models tie magnitude to phase), and K, the scale, is a
// parameter of its own: a scale error is never taken for dynamics. With one
// frequency on the axis nothing tells dynamics from scale, and D = 1: the
// tolerance applies to the ratio itself (a gyro whose bandwidth is that low
// is told to measure its response).

#include <string>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/validity.h"

namespace fog::analysis {

// The gyro's dynamics at one point as the axis' frequency response gives
// them: dynamicGain = |H(f)| / K of the chosen model (1 for none or the pure
// delay), model its name ("" when no response was fitted).
struct PointDynamics {
  double dynamicGain = 1.0;
  std::string model;
};

// The check of one point against `toleranceFraction`.
ValidityCheck gainCheck(const TestPointResult& point, const PointDynamics& dynamics, double toleranceFraction);

// Adds the gain check to every point of the report, after its axis_sign
// check, with each axis' dynamics fitted as above (analyzeRecording calls
// it before the frequency test, which pools only points that pass it).
void addGainChecks(DelayReport& report, double toleranceFraction);

}  // namespace fog::analysis
