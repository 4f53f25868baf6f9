#pragma once
// fogbench-cli with a real sampling board on a serial port (docs/serial.md):
// `run --source serial --port DEV ...` records the board's stream into a
// session and reports the delay; `ports` lists the serial ports. In every
// build (core/serial is POSIX, Qt-free).

#include "app/cli_arguments.h"
#include "core/common/status.h"
#include "core/serial/serial_source.h"

namespace fog::app {

int runSerialCommand(CliArguments& args);  // run --source serial
int portsCommand(CliArguments& args);      // ports
// --port, --baud, --parity, --data-bits, --stop-bits.
Result<serial::SerialSettings> readSerialSettings(CliArguments& args);
// run --table remote:ADDR|manual --source serial --port DEV (docs/table-control.md).
int runTableCommand(CliArguments& args, const std::string& table);

}  // namespace fog::app
