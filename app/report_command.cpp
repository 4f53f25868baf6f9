#include "app/report_command.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>

#include "core/analysis/delay_analysis.h"
#include "app/cli_common.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "app/session_input.h"
#include "ui/language/language.h"
#include "ui/report/calibration_report.h"

namespace fog::app {

namespace {

std::string nowUtc() {
  return QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
}

// A simulated session, exactly as `run` makes it.
Result<report::ReportInput> simulatedSession(const std::string& preset, double seed) {
  FOG_ASSIGN_OR_RETURN(auto plan, presetPlan(preset));
  if (seed < 0 || seed != std::floor(seed)) return invalidArgument("--seed must be a whole number >= 0");
  model::SimConfig config;
  config.seed = static_cast<std::uint64_t>(seed);
  FOG_ASSIGN_OR_RETURN(auto run, model::simulate(config, plan));
  FOG_ASSIGN_OR_RETURN(auto recording, protocol::decodeRecording(run.bytes));
  report::ReportInput in;
  in.info.source = "simulator, seed " + std::to_string(config.seed) + ", preset " + preset;
  in.info.imuModel = "simulated FOG IMU";
  in.info.softwareVersion = FOG_VERSION;
  in.info.createdUtc = nowUtc();
  in.info.plan = plan;
  std::string truth;
  for (const auto& t : run.truth) {
    char line[96];
    std::snprintf(line, sizeof line, "%ssimulator truth, test point %d: lag %.5f ms", truth.empty() ? "" : "; ",
                  t.index + 1, t.lagS * 1e3);
    truth += line;
  }
  in.info.notes = truth;
  in.recording = std::move(recording);
  in.rawBytes = std::move(run.bytes);
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

// --png-dir writes report-page-N.png: existing ones are replaced only with
// --overwrite (and never a session that happens to carry such a name).
Status checkPageFiles(const std::string& dir, bool overwrite) {
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("report-page-", 0) == 0 && name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0)
      if (auto s = checkOutputFile(it->path().string(), overwrite, "--png-dir"); !s.isOk()) return s;
  }
  return Status::ok();
}

}  // namespace

int reportCommand(CliArguments& args) {
  const auto pdf = args.text("pdf");
  const auto pngDir = args.text("png-dir");
  const auto preset = args.text("preset");
  auto seed = args.number("seed", 1.0);
  auto limit = args.number("limit-ms", 0.8);
  auto coverageK = readCoverageK(args);
  auto dpi = args.number("dpi", 100.0);
  const auto imuModel = args.text("imu-model");
  const auto imuSerial = args.text("imu-serial");
  const auto operatorName = args.text("operator");
  const auto lot = args.text("lot");
  const auto benchId = args.text("bench-id");
  const auto language = args.text("language");
  const bool overwrite = args.flag("overwrite");
  for (const auto* r : {&seed, &limit, &dpi, &coverageK})
    if (!*r) return fail(r->status(), 2);
  const auto& files = args.positionals();
  Status bad;
  if (!pdf && !pngDir) bad = invalidArgument("report needs --pdf OUT.pdf and/or --png-dir DIR");
  else if (!(*limit > 0.0)) bad = invalidArgument("--limit-ms must be > 0");
  else if (*dpi < 30 || *dpi > 600 || *dpi != std::floor(*dpi))
    bad = invalidArgument("--dpi must be a whole number in 30 .. 600");
  else if (args.text("seed") && !preset) bad = invalidArgument("--seed applies to --preset only");
  else if (language && *language != "en" && *language != "zh_CN")
    bad = invalidArgument("--language must be en or zh_CN");
  else if (pdf) bad = checkOutputFile(*pdf, overwrite, "--pdf");
  if (bad.isOk() && pngDir) bad = checkPageFiles(*pngDir, overwrite);
  if (!bad.isOk()) {
    (void)args.checkAllUsed();
    return fail(bad, 2);
  }
  if (files.size() > 1) {
    (void)args.checkAllUsed();
    return fail(invalidArgument("report takes one SESSION file"), 2);
  }
  if (files.empty() == !preset) {
    (void)args.checkAllUsed();
    return fail(invalidArgument("report needs one SESSION file or --preset NAME"), 2);
  }
  report::ReportInput in;
  if (preset) {
    auto simulated = simulatedSession(*preset, *seed);
    if (!simulated) {
      (void)args.checkAllUsed();
      return fail(simulated.status(), 2);
    }
    in = std::move(*simulated);
    auto constants = readConstants(args, in.info.bench);
    if (!constants) return fail(constants.status(), 2);
    if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
    auto delays = analysis::analyzeRecording(in.recording, *constants);
    if (!delays) return fail(delays.status(), exitCodeFor(delays.status()));
    storeConstants(*constants, in.info.bench);
    in.delays = std::move(*delays);
    in.imuDelayLimitMs = *limit;
    in.coverageK = *coverageK;
  } else {
    // A session file (recorded or imported) or a saved raw sampling-board
    // stream, read as every command reads them. A session brings its own
    // identity, bench constants and stored results; a raw stream has none.
    int failed = 0;  // the raw bytes are hashed onto the report
    auto opened = openFileArgument(args, "report takes one SESSION file", failed, session::OpenOptions::withRawBytes());
    if (!opened) return failed;
    if (const auto* record = session::newestUsable(opened->results)) {
      // A stored result is a record: reported with the settings and verdict
      // it was stored with. Other settings are another analysis, stored as a
      // new result first; never a silent re-judgement on paper.
      for (const char* option : {"limit-ms", "coverage-k", "read-delay-ms", "read-delay-std-ms", "board-delay-ms",
                                 "board-delay-std-ms", "pulse-equivalent-deg", "gyro-sign", "imu-frame"})
        if (args.has(option)) {
          (void)args.checkAllUsed();
          return fail(invalidArgument(std::string("--") + option + " does not apply: the report shows the "
                                      "session's stored result with the settings it was stored with (" +
                                      session::describeResult(opened->results, *record) + "); to report other settings, store a result with them "
                                      "first: fogbench-cli analyze " + files.front() + " --" + option +
                                      " ..., then report again"),
                      2);
        }
    }
    // Without a stored result: the session's own constants, unless the
    // command line gives others.
    auto constants = readConstants(args, opened->info.bench);
    if (!constants) return fail(constants.status(), 2);
    if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
    auto shown = session::showResult(*opened, 0, *constants, *limit, *coverageK);
    if (!shown.report) return fail(shown.report.status(), exitCodeFor(shown.report.status()));
    SessionInfo info = opened->info;
    info.source = shown.context.source;
    storeConstants(shown.constants, info.bench);
    in = report::makeReportInput(std::move(info), std::move(opened->recording), std::move(*shown.report),
                                 std::move(opened->rawBytes), shown.record ? &*shown.record : nullptr,
                                 shown.context.imuDelayLimitMs, shown.context.incompleteReason,
                                 QString::fromStdString(shown.description), shown.context.coverageK);
    in.analyses = opened->results;
  }
  if (imuModel) in.info.imuModel = *imuModel;
  if (imuSerial) in.info.imuSerial = *imuSerial;
  if (operatorName) in.info.operatorName = *operatorName;
  // A terminal in another encoding passes bytes that are not UTF-8 (as
  // readSessionOutput does for a recorded session's texts).
  if (lot) in.info.lot = toValidUtf8(*lot);
  if (benchId) in.info.benchId = toValidUtf8(*benchId);

  chooseQtPlatform();
  qInstallMessageHandler(quietQtMessages);
  static int argc = 1;
  static char name[] = "fogbench-cli";
  static char* argv[] = {name, nullptr};
  QApplication app(argc, argv);
  // The report in the GUI's languages; English unless asked (not the
  // system's locale: a script's output should not change with it).
  fog::ui::installTranslations(app, QString::fromStdString(language.value_or("en")));

  if (pdf) {
    if (auto s = report::writeCalibrationPdf(in, QString::fromStdString(*pdf)); !s.isOk()) return fail(s, 2);
    std::cout << "calibration report: " << *pdf << "\n";
  }
  if (pngDir) {
    const QString dir = QString::fromStdString(*pngDir);
    if (!QDir().mkpath(dir)) return fail(ioError("cannot create the directory '" + *pngDir + "'"), 2);
    auto pages = report::renderCalibrationPages(in, static_cast<int>(*dpi));
    if (!pages) return fail(pages.status(), 2);
    for (std::size_t i = 0; i < pages->size(); ++i) {
      const QString path = QDir(dir).filePath(QString("report-page-%1.png").arg(i + 1));
      if (!(*pages)[i].save(path)) return fail(ioError("cannot write '" + path.toStdString() + "'"), 2);
      std::cout << "page " << i + 1 << ": " << path.toStdString() << "\n";
    }
  }
  const auto verdict = report::calibrationVerdict(in);
  // The unit, then the session's audit trail: every stored analysis of it,
  // who made it with what on which data (a preset or a raw stream has none).
  auto orDash = [](const std::string& t) { return t.empty() ? std::string("not recorded") : t; };
  std::cout << "unit: IMU " << forTerminal(orDash(in.info.imuModel)) << ", serial "
            << forTerminal(orDash(in.info.imuSerial)) << ", lot " << forTerminal(orDash(in.info.lot)) << ", bench "
            << forTerminal(orDash(in.info.benchId)) << ", operator " << forTerminal(orDash(in.info.operatorName))
            << "\n";
  if (!in.analyses.empty()) {
    std::cout << "analyses of this session:\n";
    for (const auto& line : session::auditTrailLines(in.analyses)) std::cout << "  " << forTerminal(line) << "\n";
  }
  if (!in.resultShown.isEmpty()) std::cout << "result shown: " << in.resultShown.toStdString() << "\n";
  std::cout << verdict.headline.toStdString() << "\n";
  // The rule the verdict applied, with the shown result's own k (ISO/IEC 17025 §7.8.6).
  std::cout << analysis::decisionRuleStatement(verdict.coverageK, verdict.limitMs)
            << (verdict.ruleProvenance.isEmpty() ? std::string() : " (k " + verdict.ruleProvenance.toStdString() + ")")
            << "\n";
  for (const auto& p : verdict.points) {
    std::cout << "  test point " << p.index + 1 << ": " << p.line.toStdString() << "\n";
    if (p.vouched && std::isfinite(p.falseAcceptProbability))
      std::cout << "    guard band " << analysis::coverageFactorText(verdict.coverageK) << "σ = "
                << QString::number(p.guardBandMs, 'g', 4).toStdString()
                << " ms; probability that the true delay is at or above the limit: "
                << analysis::probabilityText(p.falseAcceptProbability) << "\n";
  }
  return 0;
}

}  // namespace fog::app
