#include "core/diagnosis/accuracy_study.h"

#include <cmath>
#include <mutex>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/statistics.h"
#include "core/common/parallel.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"

namespace fog::diagnosis {

std::vector<AccuracyCondition> paperAccuracyConditions() {
  return {{"0.1 Hz / 10 deg, 294 s", TestPlan::paperSlow(), 0.2358},
          {"1 Hz / 3 deg, 60 s", TestPlan::paperFast(), 0.2967}};
}

Result<AccuracyResult> runAccuracyStudy(const AccuracyCondition& condition, int seeds, int threads) {
  if (seeds < 3 || threads < 1) return invalidArgument("the accuracy study needs 3 or more seeds and 1 or more threads");
  const auto n = static_cast<std::size_t>(seeds);
  std::vector<double> lag(n), sd(n), bound(n);
  std::mutex errorMutex;
  std::string error;
  model::SimConfig truthConfig;
  truthConfig.fog.setOwnDelayS(condition.gyroDelayMs * 1e-3);
  parallelFor(n, threads, [&](std::size_t i) {
    model::SimConfig config = truthConfig;
    config.seed = static_cast<std::uint64_t>(i + 1);
    auto run = model::simulate(config, condition.plan);
    auto rec = run ? protocol::decodeRecording(run->bytes) : Result<Recording>(run.status());
    auto rep = rec ? analysis::analyzeRecording(*rec, BenchConstants{})
                   : Result<analysis::DelayReport>(rec.status());
    if (!rep) {
      std::lock_guard<std::mutex> lock(errorMutex);
      error = rep.status().message();
      return;
    }
    lag[i] = rep->points[0].lagMs;
    sd[i] = rep->points[0].lagStdMs;
    bound[i] = rep->points[0].crlbMs;
  });
  if (!error.empty()) return Status(StatusCode::kInternal, "a trial gave no delay: " + error);
  const auto l = analysis::meanAndSpread(lag);
  const auto s = analysis::meanAndSpread(sd);
  const auto b = analysis::meanAndSpread(bound);
  AccuracyResult r;
  r.name = condition.name;
  r.seeds = seeds;
  r.trueLagMs = truthConfig.trueLagS() * 1e3;
  r.biasUs = (l.mean - r.trueLagMs) * 1e3;
  r.biasStdUs = l.stdOfMean * 1e3;
  r.scatterUs = l.stdDev * 1e3;
  r.meanReportedStdUs = s.mean * 1e3;
  r.meanCrlbUs = b.mean * 1e3;
  r.biasOk = std::abs(r.biasUs) < 0.2 + 0.1 * r.scatterUs;
  r.stdOk = std::abs(s.mean / l.stdDev - 1.0) <= 0.15;
  r.boundOk = l.stdDev <= 1.2 * b.mean;
  return r;
}

}  // namespace fog::diagnosis
