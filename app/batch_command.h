#pragma once
// fogbench-cli batch: re-analyse many sessions with one set of constants
// (issue 42; docs/sessions.md, "Batch re-analysis"). Each session gets a new
// stored result (never an overwrite, the raw data untouched) and one JSON line
// in OUT.jsonl, written and fsynced as the file finishes, so that a batch
// killed at any moment resumes with the same OUT: files listed are skipped, a
// partial last line is discarded, and a file whose result was stored but
// whose line was not written is found by its newest result (this batch's id
// in `analysed_by`, the same settings) and listed "already_stored", never
// stored twice.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli_arguments.h"
#include "core/analysis/decision_rule.h"
#include "core/session/shown_verdict.h"

namespace fog::app {

// What a batch analyses every file with.
struct BatchSettings {
  // The constant options given on the command line (name without "--", the
  // text as given), applied over each session's own constants as `analyze`
  // applies them; the options not given are each session's own.
  std::vector<std::pair<std::string, std::string>> constantOptions;
  double imuDelayLimitMs = 0.0;
  double coverageK = analysis::kDefaultCoverageFactor;  // the decision rule's k (--coverage-k)
  // The audit entry of every result stored (stored_result.h): who ran the
  // batch (--operator, else the login name) and its command line.
  std::string operatorName, command;
  // Names this batch (OUT's header): a result it stored says so in its
  // settings' `analysed_by` ("fogbench-cli batch <id>").
  std::string batchId;

  std::string producedBy() const { return "fogbench-cli batch " + batchId; }
  // The header's "settings": {"constants": {option: value given}, "imu_delay_limit_ms": L,
  // "coverage_factor_k": k}.
  // Two batches with equal settings analyse every file alike.
  nlohmann::json settingsJson() const;
};

// One file's outcome: the content of its line in OUT.
struct BatchLine {
  std::string path;
  enum class Status { kStored, kRefused, kAlreadyStored } status = Status::kRefused;
  int result = 0;  // 1-based among the session's stored results; 0: none
  // The verdict shown with the stored result (session::judgeShown); unset
  // (kNone, no points) for a refused file.
  session::ShownVerdict verdict;
  std::string error;  // a refused file: why (the reader's, the analysis' or the store's words)
  std::string note;   // a session read from its raw stream because its samples are damaged, ...

  // {"path", "status", "result", "verdict", "points": [{"index", "verdict",
  // "imu_delay_ms", "imu_delay_std_ms"} when vouched, else {"index",
  // "verdict", "refusal"}], "error"}: a refused delay is never written bare.
  nlohmann::ordered_json toJson() const;  // keys in this order
};
const char* batchStatusName(BatchLine::Status status);

// Opens `path` as a session, analyses it with `settings` and stores the
// result as a new one (session::analyseAndStore), unless its newest stored
// result is this batch's with the same settings (then "already_stored").
// Never throws and never stops: anything wrong is a refused line saying why.
BatchLine batchOneFile(const std::string& path, const BatchSettings& settings);

// batch DIR|FILE... --jsonl OUT.jsonl [--jobs N] [constants] [--limit-ms L]
int batchCommand(CliArguments& args);

}  // namespace fog::app
