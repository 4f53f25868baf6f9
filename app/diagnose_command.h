#pragma once
// fogbench-cli diagnose and bench-diagnosis (docs/diagnosis.md).

#include "app/cli_arguments.h"

namespace fog::app {

// diagnose SESSION.fbs | FILE.bin [--json] [--seeds K] [--threads T] [constants]
int diagnoseCommand(CliArguments& args);
// bench-diagnosis [--trials N] [--seed S] [--threads T]
int benchDiagnosisCommand(CliArguments& args);

}  // namespace fog::app
