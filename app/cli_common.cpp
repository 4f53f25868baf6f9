#include "cli_common.h"

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
  return c;
}

}  // namespace fog::app
