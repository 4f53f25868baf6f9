#include "app/cli_common.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/analysis/frequency_response.h"
#include "core/analysis/report_writer.h"
#include "core/common/text.h"
#include "core/session/session_file.h"

namespace fog::app {

namespace {
std::string& commandLineStore() {
  static std::string line;
  return line;
}
}  // namespace

void setAuditCommandLine(const std::string& line) { commandLineStore() = line; }
const std::string& auditCommandLine() { return commandLineStore(); }

int fail(const Status& s, int code) {
  std::cerr << "fogbench-cli: " << forTerminal(s.message()) << "\n";
  return code;
}

Status checkOutputFile(const std::string& path, bool overwrite, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return Status::ok();
  if (fs::is_directory(st)) return invalidArgument(option + " '" + path + "' is a folder; give a file name");
  if (session::isSqliteFile(path))
    return invalidArgument(option + " '" + path + "' is a session (or another database); a session is never "
                           "overwritten, not even with --overwrite: choose another name");
  if (!overwrite) return invalidArgument(option + " '" + path + "' already exists; add --overwrite to replace it");
  return Status::ok();
}

void printIncompleteRun(const acquisition::AcquisitionResult& run) {
  std::cerr << "fogbench-cli: run incomplete: " << run.incompleteReason << "; " << run.bytesReceived
            << " bytes received"
            << (run.sessionPath.empty()                      ? std::string()
                : run.sessionBytes == run.bytesReceived ? ", all kept in " + run.sessionPath
                                                        : ", the first " + std::to_string(run.sessionBytes) +
                                                              " kept in " + run.sessionPath)
            << "\n";
}

void printColumns(const std::vector<std::vector<std::string>>& rows) {
  if (rows.empty()) return;
  std::vector<std::size_t> width(rows[0].size(), 0);
  // Widths in code points, so that "±" and "°C" do not push columns apart.
  auto length = [](const std::string& t) {
    std::size_t n = 0;
    for (unsigned char c : t) n += (c & 0xC0) != 0x80 ? 1 : 0;
    return n;
  };
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], length(row[c]));
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c)
      line += row[c] + (c + 1 < row.size() && c < width.size() ? std::string(width[c] - length(row[c]) + 2, ' ') : "");
    std::cout << forTerminal(line) << "\n";
  }
}

int exitCodeFor(const Status& s) {
  return s.code() == StatusCode::kInsufficientData || s.code() == StatusCode::kNotConverged ? 1 : 2;
}

void storeConstants(const BenchConstants& c, BenchConstants& bench) {
  bench.tableReadDelayMs = c.tableReadDelayMs;
  bench.tableReadDelayStdMs = c.tableReadDelayStdMs;
  bench.boardDelayMs = c.boardDelayMs;
  bench.boardDelayStdMs = c.boardDelayStdMs;
  if (c.pulseEquivalentDeg > 0) bench.pulseEquivalentDeg = c.pulseEquivalentDeg;
  bench.gyroSign = c.gyroSign;
  bench.imuFrame = c.imuFrame;
  bench.gainToleranceFraction = c.gainToleranceFraction;
}

Result<BenchConstants> readConstants(CliArguments& args, const BenchConstants& defaults) {
  BenchConstants c = defaults;
  struct Field {
    const char* name;
    double* target;
  } fields[] = {{"read-delay-ms", &c.tableReadDelayMs},
                {"read-delay-std-ms", &c.tableReadDelayStdMs},
                {"board-delay-ms", &c.boardDelayMs},
                {"board-delay-std-ms", &c.boardDelayStdMs},
                {"pulse-equivalent-deg", &c.pulseEquivalentDeg},
                {"gain-tolerance", &c.gainToleranceFraction}};
  for (auto& f : fields) {
    FOG_ASSIGN_OR_RETURN(auto v, args.number(f.name, *f.target));
    *f.target = v;
  }
  if (auto signs = args.text("gyro-sign")) {
    FOG_ASSIGN_OR_RETURN(auto parsed, parseGyroSigns(*signs, c.gyroSign));
    c.gyroSign = parsed;
  }
  FOG_ASSIGN_OR_RETURN(c.imuFrame, readImuFrame(args, c.imuFrame));
  // The ranges of every constant, as the GUI's dialog and the importer check
  // them (checkBenchConstants): an option given names itself; a value the
  // session stored (never the built-in defaults, which are in range) says
  // where it came from and how to override it.
  const auto problems = benchConstantProblems(c);
  if (problems.empty()) return c;
  const auto& first = problems.front();
  const std::string option = benchConstantOption(first.field);
  if (!option.empty() && args.has(option.substr(2))) return invalidArgument(option + ": " + first.message);
  return invalidArgument("the session's stored bench constants: " + first.message +
                         (option.empty() ? std::string() : "; give " + option + " to analyse with another value"));
}

Result<ImuFrame> readImuFrame(CliArguments& args, const ImuFrame& defaults) {
  const auto text = args.text("imu-frame");
  if (!text) return defaults;
  auto parsed = imuFrameFromText(*text);
  if (!parsed) return invalidArgument("--imu-frame: " + parsed.status().message());
  return *parsed;
}

Result<std::array<int, kAxisCount>> parseGyroSigns(const std::string& text, std::array<int, kAxisCount> signs) {
  std::size_t at = 0;
  while (at <= text.size()) {
    const auto end = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, end - at);
    const auto eq = item.find('=');
    const std::string axis = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    const int index = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
    if (index < 0 || (value != "-1" && value != "1" && value != "+1"))
      return invalidArgument("--gyro-sign takes AXIS=SIGN items such as x=-1 or x=-1,z=-1 (axes x, y, z; signs 1 "
                             "or -1), not '" + item + "'");
    signs[static_cast<std::size_t>(index)] = value == "-1" ? -1 : 1;
    at = end + 1;
  }
  return signs;
}

Result<double> readDelayLimit(CliArguments& args) {
  FOG_ASSIGN_OR_RETURN(auto limit, args.number("limit-ms", analysis::kDefaultImuDelayLimitMs));
  // A microsecond to a second: an IMU delay limit outside is a unit error
  // (a subnormal 1e-320 ms was accepted and failed every point).
  if (!(limit >= 1e-3 && limit <= 1000.0))
    return invalidArgument("--limit-ms must be within 0.001 .. 1000 milliseconds (the IMU delay limit), not " +
                           *args.text("limit-ms"));
  return limit;
}

Result<double> readCoverageK(CliArguments& args) {
  FOG_ASSIGN_OR_RETURN(auto k, args.number("coverage-k", analysis::kDefaultCoverageFactor));
  if (const std::string why = analysis::coverageFactorProblem(k); !why.empty())
    return invalidArgument("--coverage-k: " + why + " ('" + args.text("coverage-k").value_or("") +
                           "'); give e.g. --coverage-k 2 (2.28 % false-accept risk) or 3 (0.135 %)");
  return k;
}

std::string reportOutput(const analysis::DelayReport& report, const analysis::ReportContext& context, bool json) {
  auto responses = analysis::analyzeResponses(report);
  std::erase_if(responses, [](const auto& r) { return r.points.size() < 3; });
  if (json) {
    std::string text = analysis::formatReportJson(report, context);
    if (!responses.empty()) {
      auto doc = nlohmann::json::parse(text);
      doc["responses"] = nlohmann::json::parse(analysis::formatResponseJson(responses))["responses"];
      text = doc.dump(2);
    }
    return text + "\n";
  }
  std::string text = forTerminal(analysis::formatReportText(report, context));
  if (!responses.empty()) text.append("\n").append(analysis::formatResponseText(responses));
  return text;
}

}  // namespace fog::app
