#pragma once
// The built-in simulator as a byte source, paced like a live board: at
// speed 1 a 60 s plan takes 60 s of wall-clock time, at 20 three seconds, and
// with speed 0 it runs as fast as the machine allows. The bytes are exactly
// model::simulate()'s for the same configuration and plan (pacing only
// decides when they are handed out).

#include <memory>
#include <vector>

#include "core/acquisition/byte_source.h"
#include "core/acquisition/paced_clock.h"
#include "core/model/simulator.h"

namespace fog::acquisition {

class SimulatorSource : public ByteSource {
 public:
  // Errors: the configuration or plan is invalid (kInvalidArgument, saying
  // which value and why).
  static Result<std::unique_ptr<SimulatorSource>> create(const model::SimConfig& config, const TestPlan& plan,
                                                         double speed,
                                                         std::vector<std::unique_ptr<model::Effect>> effects = {});

  Result<ReadOutcome> read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) override;
  std::string description() const override;

  // Simulated seconds of the whole plan (settling and rests included).
  double totalS() const { return simulator_->endS(); }
  std::vector<model::TestPointTruth> truth() const { return simulator_->truth(); }

 private:
  SimulatorSource(std::unique_ptr<model::Simulator> simulator, double speed)
      : simulator_(std::move(simulator)), clock_(speed) {}

  std::unique_ptr<model::Simulator> simulator_;
  PacedClock clock_;
  bool ended_ = false;
};

}  // namespace fog::acquisition
