#pragma once
// The fogbench-cli commands. Each returns the process exit code and prints
// its own output; errors are one line on stderr saying what is wrong.

#include "app/cli_arguments.h"

namespace fog::app {

int runCommand(CliArguments& args);       // simulate a plan and report its delay
int theoryCommand(CliArguments& args);    // delay budget and resolution
int accuracyCommand(CliArguments& args);  // Monte Carlo accuracy study

}  // namespace fog::app
