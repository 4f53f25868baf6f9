#pragma once
// fogbench-cli noise: gyro noise characterisation from the static segments of
// a session or raw stream (docs/noise.md).

#include "app/cli_arguments.h"

namespace fog::app {

// noise SESSION.fbs | FILE.bin [--json] [--axis x|y|z] [--taus-per-octave N]
//       [--freq-hz F --amp-deg A --duration-s T] [--latitude-deg L] [--pulse-equivalent-deg P]
// Exit 1 when the recording has no static segment.
int noiseCommand(CliArguments& args);

}  // namespace fog::app
