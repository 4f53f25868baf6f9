#pragma once
// The paper's theory: the delay budget of the chain (eigen period from the
// fibre length, loop delay, pulse update window, board cycles, serial frame
// time) and its resolution argument (smallest resolvable time difference from
// the gyro's stability, swing frequency and amplitude), next to the bench's
// own Cramer-Rao prediction for a planned swing test.

#include <string>
#include <vector>

namespace fog::analysis {

struct TheoryInputs {
  double fibreLengthM = 1000.0;
  double groupIndex = 1.0;  // the paper's eigen period is L/c
  double loopDelayEigenPeriods = 2.0;
  double pulseUpdatePeriodS = 0.5e-3;
  double boardClockHz = 10e6;
  double pulseSampleCycles = 1.0;
  double temperatureCompensationCycles = 10.0;
  int frameBytes = 31;
  double bitsPerByte = 8.0;
  double baud = 1e6;
};

struct BudgetLine {
  std::string stage;
  double minMs = 0.0, maxMs = 0.0;
  std::string basis;  // how the figure is obtained
};

struct DelayBudget {
  double eigenPeriodUs = 0.0;
  std::vector<BudgetLine> lines;
  double boardMaxMs = 0.0;  // processing board share (sampling, compensation, serial)
  double totalMinMs = 0.0, totalMaxMs = 0.0;
};

DelayBudget delayBudget(const TheoryInputs& in);

// The paper's resolution figure: the gyro's angle error over one swing period,
// stability * T, divided by the peak rate 2*pi*f*A. Seconds.
double paperResolutionS(double stabilityDegPerH, double frequencyHz, double amplitudeDeg);

// The bench's prediction of the lag's standard deviation (s) for a planned
// test: the Cramer-Rao bound for encoder quantisation, pulse quantisation and
// angle random walk.
struct PlannedTest {
  double frequencyHz = 1.0, amplitudeDeg = 3.0, durationS = 60.0;
  double encoderQuantumDeg = 1e-4, encoderIntervalS = 1e-3;
  double pulseEquivalentDeg = 5e-5, imuIntervalS = 2e-3;
  double arwDegPerSqrtH = 0.004;
};
double predictedLagStdS(const PlannedTest& test);

}  // namespace fog::analysis
