#pragma once
// fogbench-cli with a real sampling board on a serial port (docs/serial.md):
// `run --source serial --port DEV ...` records the board's stream into a
// session and reports the delay; `ports` lists the serial ports. Both need
// the Qt build (QSerialPort); a build without Qt says so.

#include "cli_arguments.h"

namespace fog::app {

int runSerialCommand(CliArguments& args);  // run --source serial
int portsCommand(CliArguments& args);      // ports

}  // namespace fog::app
