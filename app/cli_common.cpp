#include "cli_common.h"

#include <algorithm>
#include <iostream>

namespace fog::app {

int fail(const Status& s, int code) {
  std::cerr << "fogbench-cli: " << s.message() << "\n";
  return code;
}

int exitCodeFor(const Status& s) {
  return s.code() == StatusCode::kInsufficientData || s.code() == StatusCode::kNotConverged ? 1 : 2;
}

void storeConstants(const analysis::BenchConstants& c, BenchSettings& bench) {
  bench.tableReadDelayMs = c.tableReadDelayMs;
  bench.tableReadDelayStdMs = c.tableReadDelayStdMs;
  bench.boardDelayMs = c.boardDelayMs;
  bench.boardDelayStdMs = c.boardDelayStdMs;
  if (c.pulseEquivalentDeg > 0) bench.pulseEquivalentDeg = c.pulseEquivalentDeg;
}

Result<analysis::BenchConstants> readConstants(CliArguments& args, const BenchSettings& defaults) {
  analysis::BenchConstants c = analysis::benchConstantsOf(defaults);
  struct Field {
    const char* name;
    double* target;
  } fields[] = {{"read-delay-ms", &c.tableReadDelayMs},
                {"read-delay-std-ms", &c.tableReadDelayStdMs},
                {"board-delay-ms", &c.boardDelayMs},
                {"board-delay-std-ms", &c.boardDelayStdMs},
                {"pulse-equivalent-deg", &c.pulseEquivalentDeg}};
  for (auto& f : fields) {
    auto v = args.number(f.name, *f.target);
    if (!v) return v.status();
    *f.target = *v;
  }
  if (c.tableReadDelayStdMs < 0 || c.boardDelayStdMs < 0)
    return invalidArgument("uncertainties of bench constants must be >= 0");
  if (c.pulseEquivalentDeg < 0) return invalidArgument("--pulse-equivalent-deg must be >= 0");
  if (auto signs = args.text("gyro-sign")) {
    auto parsed = parseGyroSigns(*signs);
    if (!parsed) return parsed.status();
    c.gyroSign = *parsed;
  }
  return c;
}

Result<std::array<int, kAxisCount>> parseGyroSigns(const std::string& text) {
  std::array<int, kAxisCount> signs{1, 1, 1};
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
  auto limit = args.number("limit-ms", analysis::kDefaultImuDelayLimitMs);
  if (!limit) return limit.status();
  if (!(*limit > 0.0) || *limit > 1e6) return invalidArgument("--limit-ms must be a number of milliseconds > 0");
  return *limit;
}

}  // namespace fog::app
