#pragma once
// fogbench-cli response: the gyro's frequency response from the swing test
// points of a session or raw stream (core/analysis/frequency_response.h,
// docs/method.md "Frequency response", JSON in docs/report.md).

#include "app/cli_arguments.h"

namespace fog::app {

// response SESSION.fbs | FILE.bin [constants] [--json] [--at-hz F]
// Analyses the recording (nothing is stored), then per axis with at least two
// passed points: the table of points and the three models, the chosen one by
// AIC; the group delay at F Hz (default 5). Exit 1 when no axis has two
// passed points (the message says how many each has), 2 for bad arguments.
int responseCommand(CliArguments& args);

}  // namespace fog::app
