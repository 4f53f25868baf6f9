#pragma once
// fogbench-cli catalog index|units|unit|lot|push|refused (docs/catalog.md).

#include <string>
#include <vector>

#include "app/cli_arguments.h"

namespace fog::app {

int catalogCommand(CliArguments& args);

}  // namespace fog::app
