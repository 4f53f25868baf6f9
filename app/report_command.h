#pragma once
// fogbench-cli report: the calibration report (PDF and/or page PNGs) of a
// session. Compiled only where the GUI stack (Qt + Qwt) is built
// (FOG_HAVE_REPORT); the headless build says so instead.
//
//   fogbench-cli report (FILE.bin | --preset NAME [--seed N]) [--pdf OUT.pdf]
//                       [--png-dir DIR [--dpi 100]] [--limit-ms 0.8] [--coverage-k 2]
//                       [--imu-model M --imu-serial S --operator NAME] [constants]
//
// Exit codes as the other commands: 0 the report was written (whatever its
// verdict; the verdict is printed), 1 the data gave no delay, 2 bad command
// line, unreadable input or unwritable output.

#include "app/cli_arguments.h"

namespace fog::app {

int reportCommand(CliArguments& args);

}  // namespace fog::app
