#include "app/response_command.h"

#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_common.h"
#include "app/session_input.h"
#include "core/analysis/frequency_response.h"
#include "core/common/text.h"

namespace fog::app {

int responseCommand(CliArguments& args) {
  const bool json = args.flag("json");
  auto atHz = args.number("at-hz", analysis::kDefaultGroupDelayAtHz);
  if (!atHz) return fail(atHz.status(), 2);
  if (!(*atHz > 0.0 && *atHz <= analysis::kMaxGroupDelayAtHz))
    return fail(invalidArgument("--at-hz must be a frequency in (0, " +
                                std::to_string(static_cast<int>(analysis::kMaxGroupDelayAtHz)) +
                                "] Hz: the group delay is the fitted model's, which says nothing beyond the gyro's "
                                "output band"),
                2);
  int failed = 0;
  auto opened = openFileArgument(args, "response needs exactly one SESSION.fbs or raw stream FILE", failed);
  if (!opened) return failed;
  // The shown result's constants (the IMU delay `report` shows), unless the
  // command line gives others; said on stderr.
  auto settings = shownResultSettings(args, *opened);
  if (!settings) return fail(settings.status(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!settings->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(settings->note) << "\n";
  auto report = analysis::analyzeRecording(opened->recording, settings->constants);
  if (!report) return fail(report.status(), exitCodeFor(report.status()));
  const auto responses = analysis::analyzeResponses(*report, *atHz);
  if (responses.empty()) {
    std::string counts;
    for (int a = 0; a < kAxisCount; ++a) {
      const auto n = analysis::responsePoints(*report, static_cast<Axis>(a)).size();
      if (n > 0) counts += std::string(counts.empty() ? "" : ", ") + axisLabel(static_cast<Axis>(a)) + " " + std::to_string(n);
    }
    return fail(Status(StatusCode::kInsufficientData,
                       "a frequency response needs two or more test points of one axis that passed their checks; "
                       "this recording has " + (counts.empty() ? std::string("none") : counts) +
                           " (run --preset response records 20)"),
                1);
  }
  // Test points that gave no delay at all are in no axis's response: said
  // after the responses (the text) or as "no_delay" (the JSON).
  if (json) {
    auto doc = nlohmann::json::parse(analysis::formatResponseJson(responses));
    doc["no_delay"] = report->failedPoints;
    std::cout << doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    std::cout << analysis::formatResponseText(responses);
    for (const auto& line : report->failedPoints) std::cout << "left out (no delay): " << forTerminal(line) << "\n";
  }
  return 0;
}

}  // namespace fog::app
