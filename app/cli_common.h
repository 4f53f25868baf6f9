#pragma once
// Pieces every fogbench-cli command shares: the one-line error convention,
// exit codes and the bench-constant options. (The named test plans are
// fog::presetPlan, core/common/test_plan.h.)
//
// Exit codes: 0 ok, 1 the data gave no result (too little data, no
// convergence), 2 bad command line or input (one line on stderr).

#include <array>
#include <string>
#include <vector>

#include "core/acquisition/acquisition.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/verdict.h"
#include "app/cli_arguments.h"
#include "core/common/session_info.h"
#include "core/common/imu_frame.h"
#include "core/common/status.h"
#include "core/common/test_plan.h"

namespace fog::app {

// The command line as the audit trail of a stored result states it
// ("fogbench-cli analyze s.fbs --board-delay-ms 0.2"; session::commandLineOf),
// set once by main().
void setAuditCommandLine(const std::string& line);
const std::string& auditCommandLine();

// Prints "fogbench-cli: <message>" on stderr and returns `code`.
int fail(const Status& s, int code);
// On stderr: why a run (simulator or serial) ended early, the bytes received
// and how many of them the session kept.
void printIncompleteRun(const acquisition::AcquisitionResult& run);
// 1 for kInsufficientData / kNotConverged, 2 for everything else.
int exitCodeFor(const Status& s);

// Prints rows as aligned columns (two spaces apart) on stdout, each line
// made safe for a terminal. rows[0] is the header.
void printColumns(const std::vector<std::vector<std::string>>& rows);

// An output file a command is about to write (--pdf, --save-raw,
// --results-json): a session is never overwritten, not even with
// --overwrite; any other existing file only with --overwrite; a folder never.
// `option` names the option in the message.
Status checkOutputFile(const std::string& path, bool overwrite, const std::string& option);

// The bench constants as the session (or the defaults) has them, each
// overridable on the command line: --read-delay-ms, --read-delay-std-ms,
// --board-delay-ms, --board-delay-std-ms, --pulse-equivalent-deg,
// --gain-tolerance (a fraction: the gain check's scale tolerance); and
// --gyro-sign x=-1[,y=-1...] for a gyro axis mounted the other way round;
// --imu-frame NED|ENU|FRD[:H]|RFU[:H] for where the IMU's axes point at zero.
// Every constant is then range-checked (checkBenchConstants,
// core/common/bench_constants.h): "--board-delay-ms: the processing-board
// delay (1e+308 ms) must be within 0 .. 1000 ms: ...".
Result<BenchConstants> readConstants(CliArguments& args, const BenchConstants& defaults = {});
// --imu-frame NED|ENU|FRD[:H]|RFU[:H]: the frame given, or `defaults` (the
// session's stored frame) without the option; "--imu-frame: ..." when it is
// not one.
Result<ImuFrame> readImuFrame(CliArguments& args, const ImuFrame& defaults);
// --gyro-sign's text ("x=-1,z=-1") into per-axis signs (the rest +1).
// The axes given ("x=-1,z=-1") set their signs; the others keep `signs`
// (the session's stored ones, +1 without a session).
Result<std::array<int, kAxisCount>> parseGyroSigns(const std::string& text,
                                                   std::array<int, kAxisCount> signs = {1, 1, 1});
// --limit-ms: the IMU delay limit of the verdict (default 0.8 ms).
Result<double> readDelayLimit(CliArguments& args);
// --coverage-k: the decision rule's coverage factor k (PASS when IMU delay +
// k sigma < limit; default 2; a finite number in (0, 10]).
Result<double> readCoverageK(CliArguments& args);
// Writes the constants back into the settings a session stores.
void storeConstants(const BenchConstants& constants, BenchConstants& bench);

// The delay report as `run` and `analyze` print it: text for the terminal
// or JSON; a plan with three or more passed frequencies on an axis (run
// --preset response) has its frequency response after it, as `response`
// prints it (JSON: the same entries under "responses").
std::string reportOutput(const analysis::DelayReport& report, const analysis::ReportContext& context, bool json);

}  // namespace fog::app
