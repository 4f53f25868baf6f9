#include "app/cli_commands.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/acquisition/acquisition.h"
#include "core/acquisition/simulator_source.h"
#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/analysis/theory.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/analysis/frequency_response.h"
#include "core/diagnosis/accuracy_study.h"
#include "core/diagnosis/effects.h"
#include "core/model/simulator.h"
#include "app/catalog_command.h"
#include "app/cli_common.h"
#include "app/session_commands.h"
#include "app/sim_options.h"
#include "app/serial_command.h"

namespace fog::app {

namespace {

#define FOG_TRY_NUMBER(var, args, name, fallback) \
  double var = 0.0;                               \
  {                                               \
    auto v_ = (args).number(name, fallback);      \
    if (!v_) return fail(v_.status(), 2);         \
    var = *v_;                                    \
  }

int printReport(const Result<analysis::DelayReport>& report, const analysis::ReportContext& context, bool json) {
  if (!report) return fail(report.status(), exitCodeFor(report.status()));
  std::cout << reportOutput(*report, context, json);
  return 0;
}

// --effect NAME=V[,V...][+NAME=V...]: unmodelled effects from the diagnosis
// library (docs/diagnosis.md) added to the simulated chain.
Result<std::vector<std::unique_ptr<model::Effect>>> readEffects(const std::string& text, const model::SimConfig& config) {
  std::vector<std::unique_ptr<model::Effect>> effects;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, '+')) {
    const auto eq = item.find('=');
    FOG_ASSIGN_OR_RETURN(auto id, diagnosis::effectIdFromName(item.substr(0, eq)));
    const auto& spec = diagnosis::effectSpec(id);
    std::vector<double> values;
    std::stringstream numbers(eq == std::string::npos ? "" : item.substr(eq + 1));
    std::string number;
    while (std::getline(numbers, number, ',')) {
      // A value may be written in a parameter's meaning before issue 44
      // (e.g. asymmetry_k:49.4 or h2_at_10deg:-2.83): converted, with a note.
      const std::size_t j = values.size();
      const auto colon = number.find(':');
      double scale = 1.0;
      if (colon != std::string::npos) {
        const std::string old = number.substr(0, colon);
        if (j >= spec.parameters.size() || spec.parameters[j].legacyName.empty() || spec.parameters[j].legacyName != old)
          return invalidArgument("--effect " + spec.name + ": '" + old + ":' names no earlier definition of value " +
                                 std::to_string(j + 1) +
                                 (j < spec.parameters.size() && !spec.parameters[j].legacyName.empty()
                                      ? " (it is " + spec.parameters[j].legacyName + ":)"
                                      : ""));
        scale = spec.parameters[j].legacyScale;
        number = number.substr(colon + 1);
      }
      char* end = nullptr;
      const double v = std::strtod(number.c_str(), &end);
      if (number.empty() || *end != '\0' || !std::isfinite(v))
        return invalidArgument("--effect " + spec.name + ": '" + number + "' is not a number");
      if (colon != std::string::npos) {
        const auto& q = spec.parameters[j];
        std::cerr << "note: --effect " << spec.name << ": " << q.legacyName << " " << v << " (its definition before "
                  << "issue 44) is " << q.name << " " << scale * v << " " << q.unit << ": " << q.definition << "\n";
      }
      values.push_back(scale * v);
    }
    // Values typed without a name are in today's definitions; say so where
    // a definition changed (docs/diagnosis.md, "Parameters and their definitions").
    for (std::size_t j = 0; j < values.size() && j < spec.parameters.size(); ++j)
      if (!spec.parameters[j].legacyName.empty() && (eq == std::string::npos || item.find(':', eq) == std::string::npos))
        std::cerr << "note: --effect " << spec.name << ": " << spec.parameters[j].name << " is " << spec.parameters[j].definition
                  << " (since issue 44; a value in the earlier definition is written " << spec.parameters[j].legacyName
                  << ":V, = " << spec.parameters[j].legacyScale << " x V today)\n";
    if (values.size() != spec.parameters.size()) {
      std::string names;
      for (const auto& p : spec.parameters) names += (names.empty() ? "" : ",") + p.name + " (" + p.unit + ")";
      return invalidArgument("--effect " + spec.name + " takes " + std::to_string(spec.parameters.size()) +
                             " value(s): " + names);
    }
    diagnosis::EffectContext context;
    context.earth = config.earth;
    effects.push_back(diagnosis::makeEffect(id, values, context));
  }
  return effects;
}

// Copies every byte a source delivers into a file (--save-raw) on its way
// to the acquisition.
class RawFileTee : public acquisition::ByteSource {
 public:
  RawFileTee(acquisition::ByteSource& inner, const std::string& path)
      : inner_(inner), file_(path, std::ios::binary | std::ios::trunc) {}
  bool isOpen() const { return file_.is_open(); }
  bool close() {
    file_.close();
    return !file_.fail();
  }
  Result<acquisition::ReadOutcome> read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) override {
    const std::size_t before = out.size();
    auto r = inner_.read(out, timeout);
    file_.write(reinterpret_cast<const char*>(out.data() + before), static_cast<std::streamsize>(out.size() - before));
    return r;
  }
  std::string description() const override { return inner_.description(); }

 private:
  acquisition::ByteSource& inner_;
  std::ofstream file_;
};

// Ctrl-C or SIGTERM during a simulated run: the run ends as incomplete
// ("stopped by the operator"), the session keeps everything and is marked
// incomplete, and what was received is analysed, as for a serial run.
std::atomic<bool> gStop{false};
extern "C" void onStopSignal(int) { gStop = true; }

}  // namespace

int runCommand(CliArguments& args) {
  const bool json = args.flag("json");
  auto source = args.text("source").value_or("sim");
  // --table manual|remote:ADDR: the bench drives the turntable (docs/table-control.md).
  if (auto table = args.text("table"); table && *table != "sim") {
    return runTableCommand(args, *table);
  }
  if (source == "serial") {
    return runSerialCommand(args);
  }
  auto savePath = args.text("save-raw");
  const bool overwrite = args.flag("overwrite");
  auto speed = args.number("speed", 0.0);
  if (!speed) return fail(speed.status(), 2);
  auto constants = readConstants(args);
  if (!constants) return fail(constants.status(), 2);
  auto limit = readDelayLimit(args);
  if (!limit) return fail(limit.status(), 2);
  auto coverageK = readCoverageK(args);
  if (!coverageK) return fail(coverageK.status(), 2);
  auto plan = readPlan(args);
  if (!plan) return fail(plan.status(), 2);
  const bool headingGiven = args.has("heading-deg");
  auto config = readSimConfig(args);
  if (!config) return fail(config.status(), 2);
  // The simulated bench stands in the stated frame; a heading given beside
  // a frame that names another is a contradiction, not a choice.
  if (const auto h = constants->imuFrame.xHeadingDeg();
      h && headingGiven && std::abs(std::remainder(*h - config->earth.headingDeg, 360.0)) > 1e-9) {
    char heading[32];
    std::snprintf(heading, sizeof heading, "%g", *h);
    return fail(invalidArgument("--heading-deg " + *args.text("heading-deg") + " contradicts --imu-frame " +
                                imuFrameToText(constants->imuFrame) + ", whose x axis points at " + heading +
                                " deg; give one of them"),
                2);
  }
  model::applyImuFrame(constants->imuFrame, config->earth);
  auto sessionOut = readSessionOutput(args);
  if (!sessionOut) return fail(sessionOut.status(), 2);
  auto catalogDb = readCatalogDb(args);
  if (!catalogDb) return fail(catalogDb.status(), 2);
  const auto effectText = args.text("effect");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("unexpected argument '" + args.positionals()[0] + "'"), 2);
  if (source != "sim") return fail(invalidArgument("source '" + source + "' is not available; use --source sim or serial"), 2);
  if (*speed < 0) return fail(invalidArgument("--speed must be >= 0 (1 = real time, 0 = as fast as possible)"), 2);
  if (savePath)
    if (auto s = checkOutputFile(*savePath, overwrite, "--save-raw"); !s.isOk()) return fail(s, 2);
  auto effects = effectText ? readEffects(*effectText, *config) : Result<std::vector<std::unique_ptr<model::Effect>>>(
                                                                      std::vector<std::unique_ptr<model::Effect>>{});
  if (!effects) return fail(effects.status(), 2);

  auto simulator = acquisition::SimulatorSource::create(*config, *plan, *speed, std::move(*effects));
  if (!simulator) return fail(simulator.status(), 2);
  acquisition::AcquisitionOptions options;
  options.constants = *constants;
  options.reportContext.source = "simulator, seed " + std::to_string(config->seed) +
                                 (effectText ? ", effect " + *effectText : std::string()) + ", fogbench " + FOG_VERSION;
  for (const auto& t : (*simulator)->truth()) options.reportContext.trueLagMs.push_back(t.lagS * 1e3);
  options.reportContext.imuDelayLimitMs = *limit;
  options.reportContext.coverageK = *coverageK;
  if (*sessionOut) {
    options.sessionPath = (*sessionOut)->path;
    options.info = simulatedSessionInfo((*sessionOut)->info, *plan, *config, *constants);
    options.info.source = options.reportContext.source;
    options.auditCommand = auditCommandLine();
  }
  std::unique_ptr<RawFileTee> tee;
  acquisition::ByteSource* from = simulator->get();
  if (savePath) {
    tee = std::make_unique<RawFileTee>(*from, *savePath);
    if (!tee->isOpen()) return fail(ioError("cannot write raw stream to '" + *savePath + "'"), 2);
    from = tee.get();
  }
  gStop = false;
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  auto run = acquisition::acquire(*from, options, &gStop);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (!run) return fail(run.status(), 2);
  if (tee && !tee->close()) return fail(ioError("cannot write raw stream to '" + *savePath + "'"), 2);
  if (!run->complete) printIncompleteRun(*run);
  if (!run->recordingStatus.isOk()) return fail(run->recordingStatus, 1);
  const int code = printReport(run->report, acquisition::reportContextOf(*run, options), json);
  // The stored result reaches the catalog (docs/catalog.md).
  if (!run->sessionPath.empty() && run->report) updateCatalogAfterAnalysis(*catalogDb, run->sessionPath, json);
  return code;
}

int theoryCommand(CliArguments& args) {
  const bool json = args.flag("json");
  analysis::TheoryInputs in;
  analysis::PlannedTest test;
  FOG_TRY_NUMBER(fibre, args, "fibre-length-m", in.fibreLengthM);
  FOG_TRY_NUMBER(stability, args, "stability-deg-h", 0.5);
  FOG_TRY_NUMBER(freq, args, "freq-hz", 1.0);
  FOG_TRY_NUMBER(amp, args, "amp-deg", 3.0);
  FOG_TRY_NUMBER(duration, args, "duration-s", 60.0);
  FOG_TRY_NUMBER(arw, args, "arw-deg-sqrt-h", test.arwDegPerSqrtH);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (fibre <= 0 || stability < 0 || freq <= 0 || amp <= 0 || duration <= 0 || arw < 0)
    return fail(invalidArgument("lengths, frequency, amplitude and duration must be > 0"), 2);
  // Physical ranges (a frequency of 1e300 Hz printed a budget of zeros).
  if (fibre > 1e5 || stability > 3600 || freq > 1000 || amp > 3600 || duration > 86400 || arw > 100)
    return fail(invalidArgument("theory takes a fibre up to 100 km, a frequency up to 1000 Hz, an amplitude up to "
                                "3600 deg, a duration up to 24 h, a stability up to 3600 deg/h and an ARW up to 100 "
                                "deg/sqrt(h)"),
                2);
  in.fibreLengthM = fibre;
  test.frequencyHz = freq;
  test.amplitudeDeg = amp;
  test.durationS = duration;
  test.arwDegPerSqrtH = arw;
  const auto budget = analysis::delayBudget(in);
  const double resolution = analysis::paperResolutionS(stability, freq, amp);
  const double bound = analysis::predictedLagStdS(test);
  if (json) {
    nlohmann::json doc;
    doc["eigen_period_us"] = budget.eigenPeriodUs;
    for (const auto& l : budget.lines)
      doc["budget"].push_back({{"stage", l.stage}, {"min_ms", l.minMs}, {"max_ms", l.maxMs}, {"basis", l.basis}});
    doc["board_max_ms"] = budget.boardMaxMs;
    doc["total_min_ms"] = budget.totalMinMs;
    doc["total_max_ms"] = budget.totalMaxMs;
    doc["paper_resolution_us"] = resolution * 1e6;
    doc["predicted_lag_std_us"] = bound * 1e6;
    std::cout << doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }
  std::printf("Delay budget (the paper's theory), fibre %.0f m: eigen period %.2f us\n", fibre, budget.eigenPeriodUs);
  for (const auto& l : budget.lines)
    std::printf("  %-32s %7.4f .. %7.4f ms   %s\n", l.stage.c_str(), l.minMs, l.maxMs, l.basis.c_str());
  std::printf("  %-32s %7.4f .. %7.4f ms   (processing board %.3f ms)\n", "total", budget.totalMinMs,
              budget.totalMaxMs, budget.boardMaxMs);
  std::printf("\nResolution (the paper's argument) at %g Hz / %g deg with %g deg/h stability:\n", freq, amp, stability);
  std::printf("  angle error per period %.3g deg -> smallest resolvable time difference %.2f us\n",
              stability / 3600.0 / freq, resolution * 1e6);
  std::printf("\nCramer-Rao bound for a %g s record (encoder 0.36\", pulse %.2g deg, ARW %g deg/sqrt(h)):\n",
              duration, test.pulseEquivalentDeg, arw);
  std::printf("  lag standard deviation >= %.3f us\n", bound * 1e6);
  return 0;
}

int accuracyCommand(CliArguments& args) {
  FOG_TRY_NUMBER(seeds, args, "seeds", 200.0);
  FOG_TRY_NUMBER(threads, args, "threads", 2.0);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  // Bounded before any cast to int or allocation (--seeds 1e9 used to abort).
  if (!(seeds >= 3 && seeds <= 100000) || seeds != std::floor(seeds) || !(threads >= 1 && threads <= 256) ||
      threads != std::floor(threads))
    return fail(invalidArgument("--seeds must be a whole number in 3 .. 100000 and --threads in 1 .. 256"), 2);
  std::printf("| condition | seeds | true lag (ms) | bias (us) | scatter (us) | mean reported std (us) | "
              "CRLB (us) | std/scatter | scatter/CRLB | |bias| < 0.2 us + 0.1 scatter |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  for (const auto& condition : diagnosis::paperAccuracyConditions()) {
    auto r = diagnosis::runAccuracyStudy(condition, static_cast<int>(seeds), static_cast<int>(threads));
    if (!r) return fail(r.status(), 1);
    failures += !r->ok();
    auto mark = [](bool ok) { return ok ? "ok" : "FAIL"; };
    std::printf("| %s | %d | %.4f | %+.3f ± %.3f | %.3f | %.3f | %.3f | %.3f %s | %.3f %s | %s |\n", r->name.c_str(),
                r->seeds, r->trueLagMs, r->biasUs, r->biasStdUs, r->scatterUs, r->meanReportedStdUs, r->meanCrlbUs,
                r->meanReportedStdUs / r->scatterUs, mark(r->stdOk), r->scatterUs / r->meanCrlbUs, mark(r->boundOk),
                mark(r->biasOk));
    std::fflush(stdout);
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace fog::app
