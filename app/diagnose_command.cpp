#include "app/diagnose_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>

#include "app/cli_common.h"
#include "core/diagnosis/blind_check.h"
#include "core/diagnosis/diagnosis.h"
#include "app/session_input.h"
#include "core/common/text.h"

namespace fog::app {

namespace {

Result<int> wholeNumber(CliArguments& args, const std::string& name, double fallback, double min, double max) {
  FOG_ASSIGN_OR_RETURN(auto v, args.number(name, fallback));
  // Checked before the cast: --seeds 1e12 is outside int.
  if (!(v >= min && v <= max) || v != std::floor(v))
    return invalidArgument("--" + name + " must be a whole number in " + std::to_string(static_cast<int>(min)) +
                           " .. " + std::to_string(static_cast<int>(max)));
  return static_cast<int>(v);
}

// --bias-instability DEG_H and --bias-correlation S: the IMU's Gauss-Markov
// bias as its static noise test measured it (unset: the replays' default).
Status readBiasInstability(CliArguments& args, diagnosis::DiagnosisOptions& options) {
  if (args.has("bias-instability")) {
    FOG_ASSIGN_OR_RETURN(const double v, args.number("bias-instability", 0.0));
    if (!(v >= 0.0 && v <= 3600.0))
      return invalidArgument("--bias-instability must be a rate in 0 .. 3600 deg/h (the IMU's bias instability, "
                             "1 sigma, from its static noise test)");
    options.biasInstabilityDegPerH = v;
  }
  if (args.has("bias-correlation")) {
    FOG_ASSIGN_OR_RETURN(const double v, args.number("bias-correlation", 0.0));
    if (!(v >= 1.0 && v <= 1e6))
      return invalidArgument("--bias-correlation must be a time in 1 .. 1e6 s (the bias instability's correlation time)");
    if (!options.biasInstabilityDegPerH)
      return invalidArgument("--bias-correlation needs --bias-instability: state the IMU's bias instability with it");
    options.biasCorrelationS = v;
  }
  return Status::ok();
}

}  // namespace

int diagnoseCommand(CliArguments& args) {
  const bool json = args.flag("json");
  auto seeds = wholeNumber(args, "seeds", 4, 2, 10000);
  auto threads = wholeNumber(args, "threads", 2, 1, 256);
  if (!seeds) return fail(seeds.status(), 2);
  if (!threads) return fail(threads.status(), 2);
  diagnosis::DiagnosisOptions options;
  if (Status s = readBiasInstability(args, options); !s.isOk()) return fail(s, 2);
  int failed = 0;
  auto opened = openFileArgument(args, "diagnose needs exactly one SESSION.fbs or raw stream FILE", failed);
  if (!opened) return failed;
  // The shown result's constants (a raw stream's pulse equivalent only from
  // the command line), unless the command line gives others; said on stderr.
  auto settings = shownResultSettings(args, *opened);
  if (!settings) return fail(settings.status(), 2);
  const BenchConstants* constants = &settings->constants;
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!settings->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(settings->note) << "\n";
  options.monteCarloSeeds = *seeds;
  options.threads = *threads;
  auto d = diagnosis::diagnose(opened->recording, opened->isSession ? &opened->info : nullptr, *constants, options);
  if (!d) return fail(d.status(), exitCodeFor(d.status()));
  std::cout << (json ? diagnosis::formatDiagnosisJson(*d) + "\n" : diagnosis::formatDiagnosisText(*d));
  return 0;
}

int benchDiagnosisCommand(CliArguments& args) {
  auto trials = wholeNumber(args, "trials", 40, 1, 100000);
  auto seed = wholeNumber(args, "seed", 1, 0, 2147483647.0);
  auto threads = wholeNumber(args, "threads", 2, 1, 256);
  for (const auto* r : {&trials, &seed, &threads})
    if (!*r) return fail(r->status(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("unexpected argument '" + args.positionals()[0] + "'"), 2);
  diagnosis::BlindCheckOptions options;
  options.trials = *trials;
  options.seed = static_cast<std::uint64_t>(*seed);
  options.threads = *threads;
  auto summary = diagnosis::runBlindCheck(options, [](const diagnosis::TrialResult& r) {
    std::string truth;
    for (const auto& t : r.truth) truth += (truth.empty() ? "" : " + ") + t;
    std::fprintf(stderr, "trial %3d %-7s %-48s x%-5.1f -> %-26s shrink %4.0f %%, left %5.1f sigma in %-10s (%.2f s)%s\n",
                 r.trial + 1, diagnosis::trialKindName(r.kind), truth.empty() ? "-" : truth.c_str(), r.magnitude,
                 r.verdict.c_str(), 100.0 * r.heldOutShrink, r.worstRemainderSigma, r.worstChannel.c_str(), r.elapsedS,
                 r.error.empty() ? "" : (" " + r.error).c_str());
  });
  if (!summary) return fail(summary.status(), exitCodeFor(summary.status()));
  std::cout << diagnosis::formatBlindCheck(*summary);
  return 0;
}

}  // namespace fog::app
