#include "core/analysis/theory.h"

#include <cmath>

#include "core/analysis/delay_analysis.h"
#include "core/common/units.h"

namespace fog::analysis {

DelayBudget delayBudget(const TheoryInputs& in) {
  DelayBudget b;
  const double eigenS = in.fibreLengthM * in.groupIndex / kSpeedOfLightMPerS;
  b.eigenPeriodUs = eigenS * 1e6;
  const double cycleMs = 1e3 / in.boardClockHz;
  const double serialMs = in.frameBytes * in.bitsPerByte / in.baud * 1e3;
  b.lines = {
      {"Sagnac sensing", 0.0, 0.0, "instantaneous in principle"},
      {"closed-loop delay", 0.0, in.loopDelayEigenPeriods * eigenS * 1e3,
       "<= " + std::to_string(static_cast<int>(in.loopDelayEigenPeriods)) + " eigen periods"},
      {"pulse output update", 0.0, in.pulseUpdatePeriodS * 1e3, "0 .. one update period"},
      {"board: pulse sampling", in.pulseSampleCycles * cycleMs, in.pulseSampleCycles * cycleMs,
       "board clock cycles"},
      {"board: temperature compensation", in.temperatureCompensationCycles * cycleMs,
       in.temperatureCompensationCycles * cycleMs, "board clock cycles"},
      {"board: serial frame", serialMs, serialMs,
       std::to_string(in.frameBytes) + " bytes at " + std::to_string(static_cast<long>(in.baud)) + " baud"},
  };
  for (const auto& l : b.lines) {
    b.totalMinMs += l.minMs;
    b.totalMaxMs += l.maxMs;
    if (l.stage.rfind("board:", 0) == 0) b.boardMaxMs += l.maxMs;
  }
  return b;
}

double paperResolutionS(double stabilityDegPerH, double frequencyHz, double amplitudeDeg) {
  const double angleErrorDeg = stabilityDegPerH / kSecondsPerHour / frequencyHz;  // over one period
  return angleErrorDeg / (kTwoPi * frequencyHz * amplitudeDeg);
}

double predictedLagStdS(const PlannedTest& t) {
  const double w = kTwoPi * t.frequencyHz;
  const double encoderSigma = t.encoderQuantumDeg / std::sqrt(12.0);
  const double pulseVar = t.pulseEquivalentDeg * t.pulseEquivalentDeg / 12.0;
  const double arw = degPerSqrtHourToDegPerSqrtS(t.arwDegPerSqrtH);
  return lagCramerRaoBoundS(w, t.durationS, t.amplitudeDeg, t.encoderIntervalS, encoderSigma, t.amplitudeDeg,
                            t.imuIntervalS, pulseVar, arw * arw);
}

}  // namespace fog::analysis
