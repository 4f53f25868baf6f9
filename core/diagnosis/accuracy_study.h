#pragma once
// The Monte Carlo accuracy study of the delay estimate on the bench's own
// simulator (docs/accuracy.md, "The simulator study"), beside the
// diagnosis's blind check: per condition, sessions simulated with seeds
// 1..N go through the full chain (simulator -> board bytes -> decoder ->
// analyzeRecording), and the lags are compared with the truth.
//
// Targets: |bias| < 0.2 us + 0.1 x scatter; mean reported std within 15 % of
// the scatter; scatter <= 1.2 x the mean Cramer-Rao bound. (The independent
// check, on data the simulator did not make, is tests/independent.)

#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/test_plan.h"

namespace fog::diagnosis {

struct AccuracyCondition {
  std::string name;  // "0.1 Hz / 10 deg, 294 s"
  TestPlan plan;     // one test point
  double gyroDelayMs = 0.0;
};

// The paper's two conditions with its gyro delays.
std::vector<AccuracyCondition> paperAccuracyConditions();

struct AccuracyResult {
  std::string name;
  int seeds = 0;
  double trueLagMs = 0.0;
  double biasUs = 0.0, biasStdUs = 0.0;  // mean lag - truth, and its standard error
  double scatterUs = 0.0;                // standard deviation of the lags
  double meanReportedStdUs = 0.0, meanCrlbUs = 0.0;
  bool biasOk = false, stdOk = false, boundOk = false;
  bool ok() const { return biasOk && stdOk && boundOk; }
};

// seeds >= 3, threads >= 1. Fails with the first trial's reason when a trial
// gives no delay.
Result<AccuracyResult> runAccuracyStudy(const AccuracyCondition& condition, int seeds, int threads);

}  // namespace fog::diagnosis
