#include "app/session_commands.h"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/catalog_command.h"
#include "app/cli_common.h"
#include "core/session/shown_csv.h"
#include "core/acquisition/acquisition.h"
#include "core/acquisition/replay_source.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/analysis/frequency_response.h"
#include "core/io/csv_export.h"
#include "core/io/hdf5_export.h"
#include "core/io/csv_import.h"
#include "core/io/imported_session.h"
#include "core/session/session_file.h"
#include "core/session/session_list.h"
#include "app/session_input.h"

namespace fog::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;



}  // namespace

Result<std::optional<SessionOutput>> readSessionOutput(CliArguments& args) {
  auto out = args.text("out");
  auto op = args.text("operator");
  auto model = args.text("imu-model");
  auto serial = args.text("imu-serial");
  auto lot = args.text("lot");
  auto benchId = args.text("bench-id");
  auto notes = args.text("notes");
  if (!out) {
    if (op || model || serial || lot || benchId || notes)
      return invalidArgument("--operator, --imu-model, --imu-serial, --lot, --bench-id and --notes describe a "
                             "session: give --out SESSION.fbs too");
    return std::optional<SessionOutput>();
  }
  std::error_code ec;
  if (fs::exists(*out, ec))
    return invalidArgument("'" + *out + "' already exists; a session file is never overwritten: choose another name");
  SessionOutput s;
  s.path = *out;
  // A terminal in another encoding (Latin-1) passes bytes that are not UTF-8.
  s.info.operatorName = toValidUtf8(op.value_or(""));
  s.info.imuModel = toValidUtf8(model.value_or(""));
  s.info.imuSerial = toValidUtf8(serial.value_or(""));
  s.info.lot = toValidUtf8(lot.value_or(""));
  s.info.benchId = toValidUtf8(benchId.value_or(""));
  s.info.notes = toValidUtf8(notes.value_or(""));
  return std::optional<SessionOutput>(std::move(s));
}

Result<std::string> readCatalogDb(CliArguments& args) {
  auto db = args.text("db");
  if (db && !args.has("out"))
    return invalidArgument("--db names the catalog the run's stored result goes to: give --out SESSION.fbs too");
  return db.value_or("");
}

SessionInfo simulatedSessionInfo(const SessionInfo& given, const TestPlan& plan, const model::SimConfig& config,
                                 const BenchConstants& constants) {
  SessionInfo info = given;
  info.softwareVersion = FOG_VERSION;
  info.createdUtc = session::utcNow();
  info.plan = plan;
  storeConstants(constants, info.bench);
  info.bench.latitudeDeg = config.earth.latitudeDeg;
  info.bench.pulseEquivalentDeg = config.fog.pulseEquivalentDeg;
  info.bench.counterHz = config.samplingBoard.counterHz;
  info.bench.counterBits = config.samplingBoard.counterBits;
  return info;
}

int analyzeCommand(CliArguments& args) {
  const bool json = args.flag("json");
  const bool noStore = args.flag("no-store");
  int failed = 0;
  auto opened = openFileArgument(args, "analyze needs exactly one FILE", failed);
  if (!opened) return failed;
  // A session's own constants, unless the command line gives others; a raw
  // stream states its pulse equivalent in its STATUS frames, so only the
  // command line can supply one (openSessionOrStream leaves it 0).
  session::AnalysisSettings settings;
  settings.producedBy = "fogbench-cli analyze";
  // Who analysed it (the audit trail): the operator named here, else the
  // login name. It describes the analysis, not the session: nothing else.
  settings.operatorName = toValidUtf8(args.text("operator").value_or(""));
  settings.command = auditCommandLine();
  // As a session's operator is bounded (SessionWriter::create): every
  // reader of the results holds it in memory and prints it.
  if (settings.operatorName.size() > 4096)
    return fail(invalidArgument("--operator is " + std::to_string(settings.operatorName.size()) +
                                " bytes; at most 4096: give the operator's name"),
                2);
  auto constants = readConstants(args, opened->info.bench);
  if (!constants) return fail(constants.status(), 2);
  auto limit = readDelayLimit(args);
  if (!limit) return fail(limit.status(), 2);
  auto coverageK = readCoverageK(args);
  if (!coverageK) return fail(coverageK.status(), 2);
  // The catalog the stored result goes to (else the session folder's, when it has one).
  const std::string catalogDb = args.text("db").value_or("");
  if (!catalogDb.empty() && noStore)
    return fail(invalidArgument("--db names the catalog a stored result goes to; --no-store stores none"), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  settings.constants = *constants;
  settings.imuDelayLimitMs = *limit;
  settings.coverageK = *coverageK;
  const auto result = session::analyseAndStore(*opened, settings, !noStore);
  if (!result.report) return fail(result.report.status(), exitCodeFor(result.report.status()));
  std::cout << reportOutput(*result.report, result.context, json);
  if (!result.storeStatus.isOk()) return fail(result.storeStatus, 2);
  if (!result.notStored.empty())
    std::cerr << "fogbench-cli: note: the result was not stored: " << forTerminal(result.notStored) << "\n";
  if (result.stored && !json) std::cout << "Result stored in session " << opened->path << ".\n";
  if (result.stored) updateCatalogAfterAnalysis(catalogDb, opened->path, json);
  return 0;
}

int sessionsCommand(CliArguments& args) {
  const bool asJson = args.flag("json");
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (args.positionals().size() != 1) return fail(invalidArgument("sessions needs exactly one DIR"), 2);
  const std::string dir = args.positionals()[0];
  auto listing = session::listSessions(dir);
  if (!listing) return fail(listing.status(), 2);

  json list = json::array();
  for (const auto& s : listing->sessions) {
    json e = {{"file", s.fileName}};
    if (!s.error.empty()) {
      e["error"] = s.error;
      list.push_back(e);
      continue;
    }
    e["created_utc"] = s.info.createdUtc;
    e["operator"] = s.info.operatorName;
    e["imu_model"] = s.info.imuModel;
    e["imu_serial"] = s.info.imuSerial;
    e["lot"] = s.info.lot;
    e["bench_id"] = s.info.benchId;
    e["axes"] = session::axesOf(s.info.plan);
    e["complete"] = s.complete;
    if (!s.complete) e["incomplete_reason"] = s.incompleteReason;
    if (!s.rawDamage.empty()) e["raw_stream_damaged"] = s.rawDamage;
    e["results"] = s.results;
    e["damaged_results"] = s.damagedResults;
    e["shown_result"] = s.shownResult;  // 1-based; 0: none intact
    e["verdict"] = session::shownVerdictName(s.shown.verdict);
    // Each point's numbers with their verdict: a refused delay is marked
    // (vouched false, with why), never a bare number in a list.
    e["test_points"] = json::array();
    for (const auto& p : s.shown.points)
      e["test_points"].push_back({{"index", p.index},
                                  {"verdict", session::shownVerdictName(p.verdict)},
                                  {"vouched", p.vouched()},
                                  {"refusal", p.refusal()},
                                  {"lag_ms", p.lagMs},
                                  {"imu_delay_ms", p.imuDelayMs},
                                  {"imu_delay_std_ms", p.imuDelayStdMs}});
    list.push_back(e);
  }
  if (asJson) {
    std::cout << json({{"folder", toValidUtf8(dir)}, {"sessions", list}, {"skipped_files", listing->skippedFiles}})
                     .dump(2, ' ', false, json::error_handler_t::replace)
              << "\n";
    return 0;
  }
  // "0.4655 / refused (0.5155, INVALID)": a refused number keeps its mark.
  auto joinMs = [](const json& points, const char* key) {
    std::string s;
    char buf[32];
    for (const auto& p : points) {
      const double v = p[key].is_number() ? p[key].get<double>() : NAN;
      std::snprintf(buf, sizeof buf, "%.4f", v);
      std::string item = buf;
      if (!p["vouched"].get<bool>()) {
        std::string word = p["verdict"].get<std::string>();
        for (auto& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        item = "refused (" + item + ", " + (word.empty() ? std::string("NO VERDICT") : word) + ")";
      }
      s += (s.empty() ? "" : " / ") + item;
    }
    return s.empty() ? std::string("-") : s;
  };
  std::vector<std::vector<std::string>> rows = {
      {"file", "created (UTC)", "operator", "IMU", "lot", "bench", "axes", "state", "result", "lag (ms)",
       "IMU delay (ms)"}};
  // "PASS (2 of 2)", "INVALID (1 of 3; 2 damaged)", "damaged (1 of 1)", "-".
  auto resultColumn = [](const json& e) {
    const std::size_t n = e["results"], damaged = e["damaged_results"], shown = e["shown_result"];
    if (n == 0) return std::string("-");
    if (shown == 0) return "damaged (" + std::to_string(damaged) + " of " + std::to_string(n) + ")";
    std::string verdict = e["verdict"];
    for (auto& c : verdict) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return (verdict.empty() ? std::string("stored") : verdict) + " (" + std::to_string(shown) + " of " +
           std::to_string(n) + (damaged > 0 ? "; " + std::to_string(damaged) + " damaged" : std::string()) + ")";
  };
  auto orDash = [](const json& text) { return text.get<std::string>().empty() ? std::string("-") : text.get<std::string>(); };
  for (const auto& e : list) {
    if (e.contains("error")) {
      rows.push_back(
          {e["file"], "-", "-", "-", "-", "-", "-", "unreadable: " + e["error"].get<std::string>(), "-", "-", "-"});
      continue;
    }
    std::string imu = e["imu_model"].get<std::string>();
    if (!e["imu_serial"].get<std::string>().empty()) imu += (imu.empty() ? "" : " ") + e["imu_serial"].get<std::string>();
    rows.push_back({e["file"], e["created_utc"], e["operator"].get<std::string>().empty() ? "-" : e["operator"],
                    imu.empty() ? "-" : imu, orDash(e["lot"]), orDash(e["bench_id"]), e["axes"],
                    std::string(e["complete"].get<bool>() ? "complete" : "incomplete") +
                        (e.contains("raw_stream_damaged") ? ", raw stream damaged" : ""),
                    resultColumn(e), joinMs(e["test_points"], "lag_ms"), joinMs(e["test_points"], "imu_delay_ms")});
  }
  printColumns(rows);
  const int skipped = listing->skippedFiles;
  std::cout << list.size() << (list.size() == 1 ? " session" : " sessions") << " in " << dir << "; " << skipped
            << " other " << (skipped == 1 ? "file" : "files") << " skipped\n";
  return 0;
}

int replayCommand(CliArguments& args) {
  const bool json = args.flag("json");
  const bool afap = args.flag("afap");
  auto speedText = args.text("speed");
  auto speed = args.number("speed", 1.0);
  if (!speed) return fail(speed.status(), 2);
  if (afap && speedText) return fail(invalidArgument("give --speed X or --afap, not both"), 2);
  if (*speed <= 0) return fail(invalidArgument("--speed must be > 0 (1 = real time); --afap for as fast as possible"), 2);
  int failed = 0;
  auto opened =
      openFileArgument(args, "replay needs exactly one SESSION.fbs", failed, session::OpenOptions::sessionStream());
  if (!opened) return failed;
  const std::string& path = opened->path;
  auto constants = readConstants(args, opened->info.bench);
  if (!constants) return fail(constants.status(), 2);
  auto limit = readDelayLimit(args);
  if (!limit) return fail(limit.status(), 2);
  auto coverageK = readCoverageK(args);
  if (!coverageK) return fail(coverageK.status(), 2);
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);

  acquisition::ReplaySource source(std::move(opened->rawBytes), afap ? 0.0 : *speed, "session " + path);
  if (!afap) std::cerr << "fogbench-cli: " << source.description() << " (Ctrl-C stops)\n";
  acquisition::AcquisitionOptions options;
  options.constants = *constants;
  auto replayed = acquisition::acquire(source, options, nullptr);
  if (!replayed) return fail(replayed.status(), 2);
  if (!replayed->recordingStatus.isOk())
    return fail(Status(replayed->recordingStatus.code(), path + ": " + replayed->recordingStatus.message()),
                exitCodeFor(replayed->recordingStatus));
  analysis::ReportContext context;
  context.source = opened->sourceLine("replay of session");
  if (!opened->complete) context.incompleteReason = opened->incompleteReason;
  context.imuDelayLimitMs = *limit;
  context.coverageK = *coverageK;
  const auto& report = replayed->report;
  if (!report) return fail(report.status(), exitCodeFor(report.status()));
  std::cout << reportOutput(*report, context, json);
  return 0;
}

int importCommand(CliArguments& args) {
  auto out = readSessionOutput(args);
  if (!out) return fail(out.status(), 2);
  io::ImportOptions options;
  options.segmentation = args.text("segment").value_or("");
  options.gyroRateConvention = args.text("rate-convention").value_or("");
  auto framePeriod = args.number("frame-period-ms", 0.0);
  if (!framePeriod) return fail(framePeriod.status(), 2);
  options.gyroFramePeriodMs = *framePeriod;
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!*out) return fail(invalidArgument("import needs --out SESSION.fbs: the session file to create"), 2);
  const auto& inputs = args.positionals();
  if (inputs.size() != 1 && inputs.size() != 3)
    return fail(invalidArgument("import takes one DIR (metadata.json, table.csv, gyro.csv) or those three FILES"), 2);
  auto imported = inputs.size() == 1 ? io::importCsvDirectory(inputs[0], options) : io::importCsvFiles(inputs, options);
  if (!imported) return fail(imported.status(), 2);
  if (!imported->windows.empty()) {
    std::cout << "Swing windows (" << (options.segmentation == "auto" ? "found" : "given")
              << "; override with --segment START-END,...):\n";
    for (std::size_t i = 0; i < imported->windows.size(); ++i) {
      const auto& w = imported->windows[i];
      char line[200];
      if (w.frequencyHz > 0.0)
        std::snprintf(line, sizeof line, "  test point %zu: %.3f - %.3f s, %.5g Hz / %.4g deg (%.1f periods)\n",
                      i + 1, w.startS, w.endS, w.frequencyHz, w.amplitudeDeg, (w.endS - w.startS) * w.frequencyHz);
      else
        std::snprintf(line, sizeof line, "  test point %zu: %.3f - %.3f s\n", i + 1, w.startS, w.endS);
      std::cout << line;
    }
  }

  const std::string from = inputs.size() == 1 ? inputs[0] : inputs[0] + ", " + inputs[1] + ", " + inputs[2];
  // Metadata given on the command line wins over the files'.
  const SessionInfo& cli = (*out)->info;
  SessionInfo& info = imported->info;
  for (auto [field, given] : {std::pair{&info.operatorName, &cli.operatorName}, {&info.imuModel, &cli.imuModel},
                              {&info.imuSerial, &cli.imuSerial}, {&info.lot, &cli.lot},
                              {&info.benchId, &cli.benchId}, {&info.notes, &cli.notes}})
    if (!given->empty()) *field = *given;
  if (auto s = io::saveImportedSession(*imported, from, (*out)->path); !s.isOk()) return fail(s, 2);

  std::size_t tableSamples = 0, imuSamples = 0;
  for (const auto& tp : imported->recording.testPoints) {
    tableSamples += tp.table.size();
    imuSamples += tp.imu.size();
  }
  std::cout << "Imported " << imported->recording.testPoints.size() << " test point(s), " << tableSamples
            << " table and " << imuSamples << " gyro samples from " << from << " into " << (*out)->path << ".\n";
  for (const auto& note : imported->notes) std::cout << "  note: " << forTerminal(note) << "\n";
  std::cout << "Analyse it with: fogbench-cli analyze " << (*out)->path << "\n";
  return 0;
}

int exportCommand(CliArguments& args) {
  const auto csvDir = args.text("csv");
  const auto jsonPath = args.text("results-json");
  const auto hdf5Path = args.text("hdf5");
  const bool overwrite = args.flag("overwrite");
  int failed = 0;
  auto opened = openFileArgument(args, "export needs exactly one SESSION.fbs", failed, session::OpenOptions::session());
  if (!opened) return failed;
  const std::string& path = opened->path;
  // The shown result's constants and limit, as `report` shows them, unless
  // the command line gives others (said on stderr).
  auto settings = shownResultSettings(args, *opened, true);
  if (!settings) return fail(settings.status(), 2);
  const BenchConstants* constants = &settings->constants;
  const double* limit = &settings->imuDelayLimitMs;
  if (auto s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  if (!csvDir && !jsonPath && !hdf5Path)
    return fail(invalidArgument("export needs --csv DIR, --hdf5 FILE.h5 and/or --results-json FILE.json"), 2);
  std::error_code ec;
  if (jsonPath)
    if (auto s = checkOutputFile(*jsonPath, overwrite, "--results-json"); !s.isOk()) return fail(s, 2);
  // Checked before any work, as --results-json: a session is never replaced.
  if (hdf5Path)
    if (auto s = checkOutputFile(*hdf5Path, overwrite, "--hdf5"); !s.isOk()) return fail(s, 2);

  const Recording& recording = opened->recording;
  // The fits and residuals come from an analysis with the shown result's
  // constants (or those given); data that supports no delay is still
  // exported, only without fits.
  auto report = analysis::analyzeRecording(recording, *constants);
  if (!report)
    std::cerr << "fogbench-cli: note: no analysis to export (" << report.status().message()
              << "); samples are exported without fits\n";
  analysis::ReportContext context;
  context.source = opened->sourceLine();
  if (!opened->complete) context.incompleteReason = opened->incompleteReason;
  context.imuDelayLimitMs = *limit;
  context.coverageK = settings->coverageK;

  if (csvDir) {
    SessionInfo info = opened->info;
    storeConstants(*constants, info.bench);
    // delays.csv: the numbers with the verdict shown with them (the stored
    // result's when these are its settings, else judged now).
    const auto verdict = session::judgeShown(settings->shownResult, report ? &*report : nullptr, opened->complete,
                                             opened->incompleteReason, *limit,
                                             settings->coverageK);
    const std::string delays = report ? session::delayBreakdownCsv(*report, verdict, opened->sourceLine()) : "";
    if (auto s = io::exportCsv(*csvDir, info, recording, report ? &*report : nullptr, overwrite, delays); !s.isOk())
      return fail(overwrite || s.code() != StatusCode::kInvalidArgument ? s : Status(s.code(), s.message() + " (--overwrite)"), 2);
    std::cout << "CSV export of " << path << ": " << *csvDir << "\n";
    if (!settings->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(settings->note) << "\n";
  }
  if (hdf5Path) {
    // The same inputs as the CSV export (info with these constants, this
    // analysis, the shown result's verdict), so the files hold the same doubles.
    SessionInfo info = opened->info;
    storeConstants(*constants, info.bench);
    const auto verdict = session::judgeShown(settings->shownResult, report ? &*report : nullptr, opened->complete,
                                             opened->incompleteReason, *limit,
                                             settings->coverageK);
    io::Hdf5ExportInput in;
    in.info = &info;
    in.recording = &recording;
    in.report = report ? &*report : nullptr;
    in.shown = &verdict;
    in.constants = constants;
    in.sessionPath = path;
    in.source = opened->sourceLine();
    // The frequency responses and the static segments' noise, as `response`
    // and `noise` give them by default.
    const io::Hdf5Extras extras = io::hdf5Extras(recording, in.report, info.bench);
    in.responses = &extras.responses;
    in.noise = &extras.noise;
    if (auto s = io::exportHdf5(*hdf5Path, in, overwrite); !s.isOk())
      return fail(overwrite || s.code() != StatusCode::kInvalidArgument ? s : Status(s.code(), s.message() + " (--overwrite)"), 2);
    std::cout << "HDF5 export of " << path << ": " << *hdf5Path << "\n";
    if (!csvDir && !settings->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(settings->note) << "\n";
  }
  if (jsonPath) {
    const SessionInfo& info = opened->info;
    const auto* stored = &opened->stored;
    json results = json::array();
    int damaged = 0;
    // A stored text that is not JSON (damaged, or written by something else)
    // is exported as a string beside an error, never as invalid JSON.
    bool notJson = false;
    auto storedJson = [&](const std::string& text, const char* what) {
      json doc = json::parse(text, nullptr, false);
      if (!doc.is_discarded()) return doc;
      notJson = true;
      return json{{"error", std::string("the stored ") + what + " is not valid JSON; the session is damaged"},
                  {"text", text}};
    };
    for (const auto& r : *stored) {
      notJson = false;
      json entry = {{"id", r.id},
                    {"created_utc", r.createdUtc},
                    {"settings", storedJson(r.settingsJson, "settings")},
                    {"report", storedJson(r.reportJson, "report")}};
      if (!r.intact || notJson) {
        ++damaged;
        entry["error"] = r.intact ? "this stored result is not valid JSON: the session is damaged"
                                  : "this stored result fails its checksum: the session is damaged; do not trust it";
      }
      results.push_back(std::move(entry));
    }
    json doc = {{"format", "fogbench-results"},
                {"format_version", 1},
                {"session",
                 {{"file", toValidUtf8(path)},
                  {"operator", info.operatorName},
                  {"imu_model", info.imuModel},
                  {"imu_serial", info.imuSerial},
                  {"lot", info.lot},
                  {"bench_id", info.benchId},
                  {"source", info.source},
                  {"software_version", info.softwareVersion},
                  {"created_utc", info.createdUtc},
                  {"notes", info.notes},
                  {"complete", opened->complete},
                  {"incomplete_reason", opened->incompleteReason},
                  {"raw_bytes", opened->rawByteCount}}},
                {"stored_results", results},
                {"current_analysis",
                 report ? json{{"settings", json::parse(session::analysisSettingsJson(*constants, context.imuDelayLimitMs, "fogbench-cli export", info.imported, nullptr, context.coverageK))},
                               {"report", json::parse(analysis::formatReportJson(*report, context))}}
                        : json{{"error", report.status().message()}}}};
    // Serialised before the file is opened: nothing can leave it empty.
    const std::string text = doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
    std::ofstream file(*jsonPath, std::ios::binary | std::ios::trunc);
    file << text;
    file.close();
    if (!file) return fail(ioError("cannot write '" + *jsonPath + "'"), 2);
    std::cout << "JSON results of " << path << ": " << *jsonPath << " (" << stored->size() << " stored result"
              << (stored->size() == 1 ? "" : "s") << " and the current analysis)\n";
    if (damaged > 0)
      return fail(corruptData(std::to_string(damaged) + " of the stored results of session '" + toValidUtf8(path) +
                              "' are damaged (checksum or JSON); " + *jsonPath +
                              " holds them with an \"error\"; restore the session from a backup"),
                  2);
  }
  return 0;
}

}  // namespace fog::app
