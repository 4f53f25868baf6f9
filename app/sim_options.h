#pragma once
// The test-plan and simulator options shared by `fogbench-cli run` and the
// board emulator (fogbench-board-emu): one parser, so both programs accept
// the same plan and chain options.

#include <optional>

#include "app/cli_arguments.h"
#include "core/common/status.h"
#include "core/common/test_plan.h"
#include "core/model/sim_config.h"

namespace fog::app {

// --plan FILE.json | --preset paper|paper-slow|paper-fast|quick|noise|response|response-third-octave |
// --axis A --freq-hz F --amp-deg A [--duration-s T --settle-s S]; default
// preset paper; a response preset with --axis A is that axis' response.
// Marks the options used.
Result<TestPlan> readPlan(CliArguments& args);
// True when any plan option was given (so `run --source serial` knows
// whether the operator stated the board's plan). Does not mark them used.
bool planGiven(const CliArguments& args);
// --seed and the chain options (--gyro-delay-ms, --arw-deg-sqrt-h, ...,
// --counter-bits, --counter-start). Marks the options used.
Result<model::SimConfig> readSimConfig(CliArguments& args);

// The start every emulator's main() shares: --help, -h or help prints
// `help` and gives nullopt (exit 0); otherwise the parsed arguments and the
// simulator's chain (readSimConfig), or why not.
struct EmulatorStart {
  CliArguments args;
  model::SimConfig config;
};
Result<std::optional<EmulatorStart>> startEmulator(int argc, char** argv, const char* help);

}  // namespace fog::app
