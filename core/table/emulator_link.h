#pragma once
// An emulated table controller in this process (EmulatedTable + TableServer,
// the emulator's own code) driven through the remote driver over an
// in-process link: the whole protocol of docs/table-control.md without a
// port. For tests of whatever drives a TableController, and a table to try
// the bench's controls on. Table time runs with the wall clock
// (steady_clock) from creation, `speed` times faster.
//
// Not thread-safe (TableController contract): one thread uses the returned
// controller; the emulator runs inside its calls.

#include <memory>

#include "core/table/emulated_table.h"
#include "core/table/table_controller.h"

namespace fog::table {

struct EmulatorLinkOptions {
  EmulatedTableParams table;
  double speed = 1.0;             // table seconds per wall second
  double heartbeatTimeoutS = 0.0; // the controller's watchdog (0: off)
};

// The remote driver connected to a fresh emulated controller (description
// "remote emulated (fogbench,table-emu,0,0.1.0)").
Result<std::unique_ptr<TableController>> connectEmulatedTable(EmulatorLinkOptions options = {});

}  // namespace fog::table
