#include "report_command.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>

#include "analysis/delay_analysis.h"
#include "common/version.h"
#include "model/simulator.h"
#include "protocol/recording_builder.h"
#include "ui/report/calibration_report.h"

namespace fog::app {

namespace {

int fail(const std::string& message, int code) {
  std::cerr << "fogbench-cli: " << message << "\n";
  return code;
}

// The bench constants, as `run` and `analyze` read them.
Result<analysis::BenchConstants> readConstants(CliArguments& args) {
  analysis::BenchConstants c;
  struct Field {
    const char* name;
    double* target;
  } fields[] = {{"read-delay-ms", &c.tableReadDelayMs},
                {"read-delay-std-ms", &c.tableReadDelayStdMs},
                {"board-delay-ms", &c.boardDelayMs},
                {"board-delay-std-ms", &c.boardDelayStdMs},
                {"pulse-equivalent-deg", &c.pulseEquivalentDeg}};
  for (auto& fld : fields) {
    auto v = args.number(fld.name, *fld.target);
    if (!v) return v.status();
    *fld.target = *v;
  }
  if (c.tableReadDelayStdMs < 0 || c.boardDelayStdMs < 0)
    return invalidArgument("uncertainties of bench constants must be >= 0");
  return c;
}

// The presets of `run`.
Result<TestPlan> presetPlan(const std::string& name) {
  if (name == "paper-slow") return TestPlan::paperSlow();
  if (name == "paper-fast") return TestPlan::paperFast();
  if (name == "paper") {
    TestPlan plan = TestPlan::paperSlow();
    plan.points.push_back(TestPlan::paperFast().points.front());
    return plan;
  }
  return invalidArgument("unknown preset '" + name + "' (paper, paper-slow, paper-fast)");
}

std::string nowUtc() {
  return QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
}

// A simulated session, exactly as `run` makes it.
Result<report::ReportInput> simulatedSession(const std::string& preset, double seed) {
  auto plan = presetPlan(preset);
  if (!plan) return plan.status();
  if (seed < 0 || seed != std::floor(seed)) return invalidArgument("--seed must be a whole number >= 0");
  model::SimConfig config;
  config.seed = static_cast<std::uint64_t>(seed);
  auto run = model::simulate(config, *plan);
  if (!run) return run.status();
  auto recording = protocol::decodeRecording(run->bytes);
  if (!recording) return recording.status();
  report::ReportInput in;
  in.info.source = "simulator, seed " + std::to_string(config.seed) + ", preset " + preset;
  in.info.imuModel = "simulated FOG IMU";
  in.info.softwareVersion = FOG_VERSION;
  in.info.createdUtc = nowUtc();
  in.info.plan = *plan;
  std::string truth;
  for (const auto& t : run->truth) {
    char line[96];
    std::snprintf(line, sizeof line, "%ssimulator truth, test point %d: lag %.5f ms", truth.empty() ? "" : "; ",
                  t.index + 1, t.lagS * 1e3);
    truth += line;
  }
  in.info.notes = truth;
  in.recording = std::move(*recording);
  in.rawBytes = std::move(run->bytes);
  return in;
}

// A saved raw sampling-board stream, as `analyze` reads it.
Result<report::ReportInput> rawStreamSession(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return ioError("cannot read '" + path + "'");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  auto recording = protocol::decodeRecording(bytes);
  if (!recording) return Status(StatusCode::kCorruptData, path + ": " + recording.status().message());
  report::ReportInput in;
  in.info.source = "raw stream " + path;
  in.recording = std::move(*recording);
  in.rawBytes = std::move(bytes);
  return in;
}

// Qt needs a platform; with no display, the offscreen one draws the same pages.
void chooseQtPlatform() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
      qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
}

// Errors are one line of ours: Qt's own chatter (XDG_RUNTIME_DIR unset, font
// fallbacks) is dropped, its critical and fatal messages kept.
void quietQtMessages(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtCriticalMsg || type == QtFatalMsg) std::cerr << "fogbench-cli: Qt: " << message.toStdString() << "\n";
}

}  // namespace

int reportCommand(CliArguments& args) {
  const auto pdf = args.text("pdf");
  const auto pngDir = args.text("png-dir");
  const auto preset = args.text("preset");
  auto seed = args.number("seed", 1.0);
  auto limit = args.number("limit-ms", 0.8);
  auto dpi = args.number("dpi", 100.0);
  auto constants = readConstants(args);
  const auto imuModel = args.text("imu-model");
  const auto imuSerial = args.text("imu-serial");
  const auto operatorName = args.text("operator");
  for (const auto* r : {&seed, &limit, &dpi})
    if (!*r) return fail(r->status().message(), 2);
  if (!constants) return fail(constants.status().message(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s.message(), 2);
  const auto& files = args.positionals();
  if (files.size() > 1) return fail("report takes one SESSION file", 2);
  if (files.empty() == !preset) return fail("report needs one SESSION file or --preset NAME", 2);
  if (!pdf && !pngDir) return fail("report needs --pdf OUT.pdf and/or --png-dir DIR", 2);
  if (!(*limit > 0.0)) return fail("--limit-ms must be > 0", 2);
  if (*dpi < 30 || *dpi > 600 || *dpi != std::floor(*dpi)) return fail("--dpi must be a whole number in 30 .. 600", 2);
  if (args.text("seed") && !preset) return fail("--seed applies to --preset only", 2);

  auto input = preset ? simulatedSession(*preset, *seed) : rawStreamSession(files.front());
  if (!input) return fail(input.status().message(), 2);
  report::ReportInput& in = *input;
  if (imuModel) in.info.imuModel = *imuModel;
  if (imuSerial) in.info.imuSerial = *imuSerial;
  if (operatorName) in.info.operatorName = *operatorName;
  in.info.bench.tableReadDelayMs = constants->tableReadDelayMs;
  in.info.bench.tableReadDelayStdMs = constants->tableReadDelayStdMs;
  in.info.bench.boardDelayMs = constants->boardDelayMs;
  in.info.bench.boardDelayStdMs = constants->boardDelayStdMs;
  in.imuDelayLimitMs = *limit;

  auto delays = analysis::analyzeRecording(in.recording, *constants);
  if (!delays) {
    const bool noResult = delays.status().code() == StatusCode::kInsufficientData ||
                          delays.status().code() == StatusCode::kNotConverged;
    return fail(delays.status().message(), noResult ? 1 : 2);
  }
  in.delays = std::move(*delays);

  chooseQtPlatform();
  qInstallMessageHandler(quietQtMessages);
  static int argc = 1;
  static char name[] = "fogbench-cli";
  static char* argv[] = {name, nullptr};
  QApplication app(argc, argv);

  if (pdf) {
    if (auto s = report::writeCalibrationPdf(in, QString::fromStdString(*pdf)); !s.isOk()) return fail(s.message(), 2);
    std::cout << "calibration report: " << *pdf << "\n";
  }
  if (pngDir) {
    const QString dir = QString::fromStdString(*pngDir);
    if (!QDir().mkpath(dir)) return fail("cannot create the directory '" + *pngDir + "'", 2);
    auto pages = report::renderCalibrationPages(in, static_cast<int>(*dpi));
    if (!pages) return fail(pages.status().message(), 2);
    for (std::size_t i = 0; i < pages->size(); ++i) {
      const QString path = QDir(dir).filePath(QString("report-page-%1.png").arg(i + 1));
      if (!(*pages)[i].save(path)) return fail("cannot write '" + path.toStdString() + "'", 2);
      std::cout << "page " << i + 1 << ": " << path.toStdString() << "\n";
    }
  }
  const auto verdict = report::calibrationVerdict(in.delays, in.imuDelayLimitMs);
  std::cout << verdict.headline.toStdString() << "\n";
  for (const auto& p : verdict.points) std::cout << "  test point " << p.index + 1 << ": " << p.line.toStdString() << "\n";
  return 0;
}

}  // namespace fog::app
