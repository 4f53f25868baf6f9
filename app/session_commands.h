#pragma once
// fogbench-cli commands around session files (.fbs, docs/sessions.md):
// recording a simulated run into a session, analysing a session (storing the
// result), listing a folder of sessions, replaying a session's raw stream,
// importing the CSV layout of docs/formats.md into a session and exporting a
// session's samples, fits and residuals as CSV and its results as JSON.
// Exit codes as everywhere in fogbench-cli: 0 ok, 1 the data gave no result,
// 2 bad command line or input (one line on stderr saying what is wrong).

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "app/cli_arguments.h"
#include "core/common/session_info.h"
#include "core/common/test_plan.h"
#include "core/model/sim_config.h"

namespace fog::app {

// `run ... --out SESSION.fbs [--operator NAME --imu-model M --imu-serial S --notes TEXT]`.
struct SessionOutput {
  std::string path;
  SessionInfo info;  // operator, IMU and notes from the command line; the rest is filled when recording
};
// Reads --out and the metadata options (marks them used). Empty without
// --out; an error when metadata options come without --out or the file exists.
Result<std::optional<SessionOutput>> readSessionOutput(CliArguments& args);
// A run's --db (the catalog its stored result goes to; "" when not given:
// the session folder's, when it has one). An error without --out.
Result<std::string> readCatalogDb(CliArguments& args);

// The metadata of a session recorded from the simulator: what the command
// line gave, plus the plan, the bench constants and the simulated chain's
// latitude, pulse equivalent and counter.
SessionInfo simulatedSessionInfo(const SessionInfo& given, const TestPlan& plan, const model::SimConfig& config,
                                 const BenchConstants& constants);

int analyzeCommand(CliArguments& args);                                   // analyze SESSION.fbs|FILE
int sessionsCommand(CliArguments& args);                                  // sessions DIR
int replayCommand(CliArguments& args);                                    // replay SESSION.fbs
int importCommand(CliArguments& args);                                    // import DIR|FILES --out SESSION.fbs
int exportCommand(CliArguments& args);                                    // export SESSION.fbs --csv DIR / --results-json F

}  // namespace fog::app
