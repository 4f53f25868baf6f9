#include "core/acquisition/simulator_source.h"

#include <algorithm>
#include <cstdio>

namespace fog::acquisition {

namespace {
// As fast as possible, the simulator still hands out its stream in pieces so
// that a consumer can show progress and stop it.
constexpr double kUnpacedStepS = 0.25;
// When paced, bytes are released in steps no finer than this (a serial read).
constexpr double kPacedStepS = 0.005;
}  // namespace

Result<std::unique_ptr<SimulatorSource>> SimulatorSource::create(
    const model::SimConfig& config, const TestPlan& plan, double speed,
    std::vector<std::unique_ptr<model::Effect>> effects) {
  FOG_ASSIGN_OR_RETURN(auto sim, model::Simulator::create(config, plan));
  // The memory budget (test_plan.h): refused here, before anything is
  // simulated, when the plan at these sampling rates would hold more samples
  // than a run may (the plan's own 1-h limit assumes the standard rates).
  const double samples = sim->endS() * (1.0 / config.encoder.samplePeriodS + 1.0 / config.imuBoard.framePeriodS);
  // (0.1 % to spare: the run's own guard counts the frames as they come.)
  if (!(samples * 1.001 <= static_cast<double>(kMaxRunSamples))) {
    char why[320];
    std::snprintf(why, sizeof why,
                  "the run would hold %.3g table and IMU samples (%.0f s at %g Hz table + %g Hz IMU); at most %.3g "
                  "(every sample is held in memory, within 1 GB): shorten the plan or lower the sampling rates",
                  samples, sim->endS(), 1.0 / config.encoder.samplePeriodS, 1.0 / config.imuBoard.framePeriodS,
                  static_cast<double>(kMaxRunSamples));
    return invalidArgument(why);
  }
  for (auto& e : effects) sim->addEffect(std::move(e));
  return std::unique_ptr<SimulatorSource>(new SimulatorSource(std::move(sim), speed));
}

Result<ReadOutcome> SimulatorSource::read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) {
  if (ended_) return ReadOutcome{0, true};
  const std::size_t before = out.size();
  double untilS = 0.0;
  if (clock_.asFastAsPossible()) {
    untilS = simulator_->timeS() + kUnpacedStepS;
  } else {
    if (!clock_.waitFor(simulator_->timeS() + kPacedStepS, timeout)) return ReadOutcome{0, false};
    untilS = clock_.streamTimeNowS();
  }
  const bool more = simulator_->advance(untilS, out);
  ended_ = !more;
  return ReadOutcome{out.size() - before, ended_};
}

std::string SimulatorSource::description() const {
  char speed[48];
  if (clock_.asFastAsPossible()) std::snprintf(speed, sizeof speed, "as fast as possible");
  else if (clock_.speed() == 1.0) std::snprintf(speed, sizeof speed, "real time");
  else std::snprintf(speed, sizeof speed, "%gx real time", clock_.speed());
  return "simulator, seed " + std::to_string(simulator_->config().seed) + ", " + speed;
}

}  // namespace fog::acquisition
