#include "cli_commands.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "acquisition/acquisition.h"
#include "acquisition/simulator_source.h"
#include "analysis/delay_analysis.h"
#include "analysis/report_writer.h"
#include "analysis/statistics.h"
#include "analysis/theory.h"
#include "common/version.h"
#include "model/simulator.h"
#include "protocol/recording_builder.h"
#include "session/session_file.h"
#include "cli_common.h"
#include "session_commands.h"

namespace fog::app {

namespace {

#define FOG_TRY_NUMBER(var, args, name, fallback) \
  double var = 0.0;                               \
  {                                               \
    auto v_ = (args).number(name, fallback);      \
    if (!v_) return fail(v_.status(), 2);         \
    var = *v_;                                    \
  }

Result<TestPlan> readPlan(CliArguments& args) {
  auto file = args.text("plan");
  auto preset = args.text("preset");
  auto axis = args.text("axis");
  auto freq = args.number("freq-hz", 0.0);
  auto amp = args.number("amp-deg", 0.0);
  auto duration = args.number("duration-s", 0.0);
  auto settle = args.number("settle-s", -1.0);
  for (const auto* r : {&freq, &amp, &duration, &settle})
    if (!*r) return r->status();
  const bool single = axis || args.text("freq-hz") || args.text("amp-deg") || args.text("duration-s");
  if ((file ? 1 : 0) + (preset ? 1 : 0) + (single ? 1 : 0) > 1)
    return invalidArgument("give one of --plan, --preset or --axis/--freq-hz/--amp-deg/--duration-s");
  if (file) {
    std::ifstream in(*file);
    if (!in) return ioError("cannot read plan file '" + *file + "'");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto plan = testPlanFromJson(text);
    if (!plan) return invalidArgument(*file + ": " + plan.status().message());
    return plan;
  }
  if (single) {
    TestPoint p;
    if (axis) {
      auto a = parseAxis(*axis);
      if (!a) return a.status();
      p.axis = *a;
    }
    if (!args.text("freq-hz") || !args.text("amp-deg"))
      return invalidArgument("a single test point needs --freq-hz and --amp-deg");
    p.frequencyHz = *freq;
    p.amplitudeDeg = *amp;
    p.durationS = args.text("duration-s") ? *duration : 30.0 / std::max(p.frequencyHz, 1e-9);
    p.settleS = *settle >= 0.0 ? *settle : std::min(5.0, 1.0 / std::max(p.frequencyHz, 1e-9));
    TestPlan plan;
    plan.points.push_back(p);
    return plan;
  }
  return presetPlan(preset.value_or("paper"));
}

Result<model::SimConfig> readSimConfig(CliArguments& args) {
  model::SimConfig c;
  auto seed = args.number("seed", 1.0);
  if (!seed) return seed.status();
  if (*seed < 0 || *seed != std::floor(*seed)) return invalidArgument("--seed must be a whole number >= 0");
  c.seed = static_cast<std::uint64_t>(*seed);
  struct Field {
    const char* name;
    double* target;
    double scale;
  } fields[] = {{"arw-deg-sqrt-h", &c.fog.arwDegPerSqrtH, 1.0},
                {"bias-instability-deg-h", &c.fog.biasInstabilityDegPerH, 1.0},
                {"pulse-equivalent-deg", &c.fog.pulseEquivalentDeg, 1.0},
                {"table-freq-error-ppm", &c.turntable.frequencyErrorPpm, 1.0},
                {"counter-hz", &c.samplingBoard.counterHz, 1.0},
                {"latitude-deg", &c.earth.latitudeDeg, 1.0}};
  for (auto& f : fields) {
    auto v = args.number(f.name, *f.target);
    if (!v) return v.status();
    *f.target = *v;
  }
  auto gyroDelay = args.number("gyro-delay-ms", c.fog.ownDelayS() * 1e3);
  auto bits = args.number("counter-bits", c.samplingBoard.counterBits);
  auto start = args.number("counter-start", c.samplingBoard.counterStart);
  for (const auto* r : {&gyroDelay, &bits, &start})
    if (!*r) return r->status();
  c.fog.setOwnDelayS(*gyroDelay * 1e-3);
  c.samplingBoard.counterBits = static_cast<int>(*bits);
  if (*start < 0 || *start > 4294967295.0) return invalidArgument("--counter-start must be within 0 .. 2^32-1");
  c.samplingBoard.counterStart = static_cast<std::uint32_t>(*start);
  std::string why;
  if (!c.isValid(&why)) return invalidArgument(why);
  return c;
}

int printReport(const Result<analysis::DelayReport>& report, const analysis::ReportContext& context, bool json) {
  if (!report) return fail(report.status(), exitCodeFor(report.status()));
  std::cout << (json ? analysis::formatReportJson(*report, context) + "\n"
                     : analysis::formatReportText(*report, context));
  return 0;
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

}  // namespace

int runCommand(CliArguments& args) {
  const bool json = args.flag("json");
  auto source = args.text("source").value_or("sim");
  auto savePath = args.text("save-raw");
  auto speed = args.number("speed", 0.0);
  if (!speed) return fail(speed.status(), 2);
  auto constants = readConstants(args);
  if (!constants) return fail(constants.status(), 2);
  auto plan = readPlan(args);
  if (!plan) return fail(plan.status(), 2);
  auto config = readSimConfig(args);
  if (!config) return fail(config.status(), 2);
  auto sessionOut = readSessionOutput(args);
  if (!sessionOut) return fail(sessionOut.status(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!args.positionals().empty()) return fail(invalidArgument("unexpected argument '" + args.positionals()[0] + "'"), 2);
  if (source != "sim") return fail(invalidArgument("source '" + source + "' is not available; use --source sim"), 2);
  if (*speed < 0) return fail(invalidArgument("--speed must be >= 0 (1 = real time, 0 = as fast as possible)"), 2);

  auto simulator = acquisition::SimulatorSource::create(*config, *plan, *speed);
  if (!simulator) return fail(simulator.status(), 2);
  acquisition::AcquisitionOptions options;
  options.constants = *constants;
  options.reportContext.source = "simulator, seed " + std::to_string(config->seed) + ", fogbench " + FOG_VERSION;
  for (const auto& t : (*simulator)->truth()) options.reportContext.trueLagMs.push_back(t.lagS * 1e3);
  if (*sessionOut) {
    options.sessionPath = (*sessionOut)->path;
    options.info = simulatedSessionInfo((*sessionOut)->info, *plan, *config, *constants);
    options.info.source = options.reportContext.source;
  }
  std::unique_ptr<RawFileTee> tee;
  acquisition::ByteSource* from = simulator->get();
  if (savePath) {
    tee = std::make_unique<RawFileTee>(*from, *savePath);
    if (!tee->isOpen()) return fail(ioError("cannot write raw stream to '" + *savePath + "'"), 2);
    from = tee.get();
  }
  auto run = acquisition::acquire(*from, options, nullptr);
  if (!run) return fail(run.status(), 2);
  if (tee && !tee->close()) return fail(ioError("cannot write raw stream to '" + *savePath + "'"), 2);
  if (!run->recordingStatus.isOk()) return fail(run->recordingStatus, 1);
  return printReport(run->report, options.reportContext, json);
}

int analyzeCommand(CliArguments& args) {
  // A session file (any SQLite file: the session reader says clearly when it
  // is a foreign or damaged one) rather than a raw stream.
  if (args.positionals().size() == 1 && session::isSqliteFile(args.positionals()[0]))
    return analyzeSessionCommand(args, args.positionals()[0]);
  const bool json = args.flag("json");
  // A raw stream states its pulse equivalent in its STATUS frames; there is
  // no session to fall back on, so only the command line can supply one.
  BenchSettings noPulseEquivalent;
  noPulseEquivalent.pulseEquivalentDeg = 0.0;
  auto constants = readConstants(args, noPulseEquivalent);
  if (!constants) return fail(constants.status(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (args.positionals().size() != 1) return fail(invalidArgument("analyze needs exactly one FILE"), 2);
  const std::string path = args.positionals()[0];
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ioError("cannot read '" + path + "'"), 2);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto recording = protocol::decodeRecording(bytes);
  if (!recording) return fail(Status(recording.status().code(), path + ": " + recording.status().message()), 2);
  analysis::ReportContext context;
  context.source = "raw stream " + path;
  return printReport(analysis::analyzeRecording(*recording, *constants), context, json);
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
    std::cout << doc.dump(2) << "\n";
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
  if (seeds < 3 || threads < 1) return fail(invalidArgument("--seeds must be >= 3 and --threads >= 1"), 2);

  struct Condition {
    const char* name;
    TestPlan plan;
    double gyroDelayMs;
  };
  const Condition conditions[] = {{"0.1 Hz / 10 deg, 294 s", TestPlan::paperSlow(), 0.2358},
                                  {"1 Hz / 3 deg, 60 s", TestPlan::paperFast(), 0.2967}};
  std::printf("| condition | seeds | true lag (ms) | bias (us) | scatter (us) | mean reported std (us) | "
              "CRLB (us) | std/scatter | scatter/CRLB | |bias| < 0.2 us + 0.1 scatter |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  for (const auto& cond : conditions) {
    const int n = static_cast<int>(seeds);
    std::vector<double> lag(n), sd(n), bound(n);
    std::atomic<int> next{0};
    std::mutex errorMutex;
    std::string error;
    double trueLagMs = 0.0;
    auto worker = [&] {
      for (int i = next++; i < n; i = next++) {
        model::SimConfig config;
        config.seed = static_cast<std::uint64_t>(i + 1);
        config.fog.setOwnDelayS(cond.gyroDelayMs * 1e-3);
        auto run = model::simulate(config, cond.plan);
        auto rec = run ? protocol::decodeRecording(run->bytes) : Result<Recording>(run.status());
        auto rep = rec ? analysis::analyzeRecording(*rec, analysis::BenchConstants{})
                       : Result<analysis::DelayReport>(rec.status());
        if (!rep) {
          std::lock_guard<std::mutex> lock(errorMutex);
          error = rep.status().message();
          continue;
        }
        lag[i] = rep->points[0].lagMs;
        sd[i] = rep->points[0].lagStdMs;
        bound[i] = rep->points[0].crlbMs;
        trueLagMs = config.trueLagS() * 1e3;
      }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < static_cast<int>(threads); ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (!error.empty()) return fail(Status(StatusCode::kInternal, "a trial failed: " + error), 1);
    const auto l = analysis::meanAndSpread(lag);
    const auto s = analysis::meanAndSpread(sd);
    const auto b = analysis::meanAndSpread(bound);
    const double biasUs = (l.mean - trueLagMs) * 1e3, scatterUs = l.stdDev * 1e3;
    const bool biasOk = std::abs(biasUs) < 0.2 + 0.1 * scatterUs;
    const bool stdOk = std::abs(s.mean / l.stdDev - 1.0) <= 0.15;
    const bool boundOk = l.stdDev <= 1.2 * b.mean;
    failures += !biasOk + !stdOk + !boundOk;
    std::printf("| %s | %d | %.4f | %+.3f ± %.3f | %.3f | %.3f | %.3f | %.3f %s | %.3f %s | %s |\n", cond.name, n,
                trueLagMs, biasUs, l.stdOfMean * 1e3, scatterUs, s.mean * 1e3, b.mean * 1e3, s.mean / l.stdDev,
                stdOk ? "ok" : "FAIL", l.stdDev / b.mean, boundOk ? "ok" : "FAIL", biasOk ? "ok" : "FAIL");
    std::fflush(stdout);
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace fog::app
