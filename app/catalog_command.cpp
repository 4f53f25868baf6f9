#include "app/catalog_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "core/analysis/verdict.h"
#include "core/catalog/catalog.h"
#include "core/common/text.h"
#include "core/session/shown_csv.h"

namespace fog::app {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using catalog::CatalogResult;

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s.empty() ? "NO VERDICT" : s;
}

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// A CSV field of text (RFC 4180 quoting; one starting like a formula is
// prefixed with a single quote, shown_csv.h). Numbers never go through it.
std::string csvText(const std::string& text) { return session::csvTextField(text); }

// The catalog a command works on. `--db` names a SQLite file, a folder (its
// fogbench-catalog.sqlite) or a PostgreSQL server; without it, `index` uses
// its first folder's catalog and the other commands the current folder's.
// Only `index` creates a SQLite catalog: a query never leaves an empty file
// where a catalog was mistyped.
Result<std::unique_ptr<catalog::Catalog>> openCatalog(CliArguments& args, const std::string& defaultFolder,
                                                       bool mayCreate) {
  std::string target = args.text("db").value_or("");
  std::error_code ec;
  if (target.empty()) target = defaultFolder;
  if (!catalog::isPostgresTarget(target)) {
    if (fs::is_directory(target, ec)) target = (fs::path(target) / catalog::kDefaultCatalogFileName).string();
    if (!mayCreate && !fs::exists(target, ec))
      return invalidArgument("no catalog at '" + target +
                             "'; index a folder first (fogbench-cli catalog index DIR) or name the catalog with "
                             "--db FILE|FOLDER|postgresql://…");
  }
  FOG_ASSIGN_OR_RETURN(auto db, catalog::CatalogDb::open(target));
  return catalog::Catalog::open(std::move(db));
}

std::string pointText(const catalog::CatalogPoint& p) {
  const std::string where = p.axis + " " + fixed(p.frequencyHz, 3) + " Hz";
  if (p.vouched()) {
    const int d = analysis::decimalsFor(p.imuDelayStdMs);
    return where + ": " + fixed(p.imuDelayMs, d) + " ± " + fixed(p.imuDelayStdMs, d) + " ms " + upper(p.verdict);
  }
  return where + ": refused (" + p.refusal + ")";
}

json pointJson(const catalog::CatalogPoint& p) {
  json j = {{"index", p.index},
            {"axis", p.axis},
            {"frequency_hz", number(p.frequencyHz)},
            {"amplitude_deg", number(p.amplitudeDeg)},
            {"verdict", p.verdict},
            {"vouched", p.vouched()}};
  // A refused delay leaves without its number, with why (shown_verdict.h).
  if (p.vouched()) {
    j["imu_delay_ms"] = number(p.imuDelayMs);
    j["imu_delay_std_ms"] = number(p.imuDelayStdMs);
  } else {
    j["refusal"] = p.refusal;
  }
  return j;
}

json resultJson(const CatalogResult& r) {
  json points = json::array();
  for (const auto& p : r.points) points.push_back(pointJson(p));
  json audit = r.auditJson.empty() ? json(nullptr) : json::parse(r.auditJson, nullptr, false);
  if (audit.is_discarded()) audit = nullptr;
  return {{"imu_serial", r.imuSerial},
          {"imu_model", r.imuModel},
          {"lot", r.lot},
          {"bench_id", r.benchId},
          {"operator", r.operatorName},
          {"session_created_utc", r.sessionCreatedUtc},
          {"result", r.resultNumber},
          {"result_created_utc", r.resultCreatedUtc},
          {"shown", r.shown},
          {"run_complete", r.runComplete},
          {"mean_temperature_c", number(r.meanTemperatureC)},
          {"verdict", r.verdict},
          {"verdict_reason", r.verdictReason},
          {"limit_ms", number(r.limitMs)},
          {"constants_hash", r.constantsHash},
          {"constants", r.constantsJson.empty() ? json(nullptr) : json::parse(r.constantsJson, nullptr, false)},
          {"software_version", r.softwareVersion},
          {"analysed_by", r.analysedBy},
          {"audit", audit},
          {"path", r.path},
          {"file_sha256", r.fileSha256},
          {"test_points", points}};
}

json sharedJson(const catalog::SyncReport& s) {
  return {{"catalog", s.shared},
          {"answered", s.reached},
          {"pushed", s.push.pushed},
          {"already_pushed", s.push.alreadyPushed},
          {"pending", s.pending},
          {"problem", s.problem}};
}

std::string catalogFileIn(const std::string& folder) {
  return (fs::path(folder.empty() ? "." : folder) / catalog::kDefaultCatalogFileName).string();
}

Result<std::unique_ptr<catalog::Catalog>> openTarget(const std::string& target) {
  FOG_ASSIGN_OR_RETURN(auto db, catalog::CatalogDb::open(target));
  return catalog::Catalog::open(std::move(db));
}

int indexCommand(CliArguments& args, const std::vector<std::string>& dirs) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  const std::string db = args.text("db").value_or("");
  if (dirs.empty()) return fail(invalidArgument("catalog index: name one or more folders (or session files)"), 2);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  std::error_code ec;
  const std::string firstFolder = fs::is_directory(dirs[0], ec) ? dirs[0] : fs::path(dirs[0]).parent_path().string();
  const bool tty = ::isatty(2) == 1;
  auto update = updateCatalog(db, firstFolder, dirs, true, [&](int done, int total) {
    if (tty && (done % 10 == 0 || done == total))
      std::cerr << "\rcatalog: " << done << "/" << total << " files" << (done == total ? "\n" : "") << std::flush;
  });
  if (!update) return fail(update.status(), 2);
  const auto& report = update->index;
  if (!update->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(update->note) << "\n";
  if (asCsv) {
    // One row per file refused by this run (the counts repeated), or one
    // row without a refusal: the counts always have their row.
    std::cout << "catalog,files_found,indexed,unchanged,refused,results_stored,shared_catalog,shared_answered,"
                 "pushed,pending,path,refusal\n";
    std::string head = csvText(update->catalog) + "," + std::to_string(report.filesFound) + "," +
                       std::to_string(report.indexed) + "," + std::to_string(report.unchanged) + "," +
                       std::to_string(report.refused) + "," + std::to_string(report.resultsStored) + ",";
    if (update->shared)
      head += csvText(update->shared->shared) + "," + (update->shared->reached ? "1" : "0") + "," +
              std::to_string(update->shared->push.pushed) + "," + std::to_string(update->shared->pending);
    else
      head += ",,,";
    if (report.refusals.empty()) std::cout << head << ",,\n";
    for (const auto& [p, why] : report.refusals) std::cout << head << "," << csvText(p) << "," << csvText(why) << "\n";
  } else if (asJson) {
    json refusals = json::array();
    for (const auto& [p, why] : report.refusals) refusals.push_back({{"path", p}, {"refusal", why}});
    json out = {{"catalog", update->catalog},
                {"files_found", report.filesFound},
                {"indexed", report.indexed},
                {"unchanged", report.unchanged},
                {"refused", report.refused},
                {"results_stored", report.resultsStored},
                {"refusals", refusals}};
    if (update->shared) out["shared"] = sharedJson(*update->shared);
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << update->catalog << "\n"
              << report.filesFound << " session files: " << report.indexed << " indexed ("
              << report.resultsStored << " results), " << report.unchanged << " unchanged since last indexed, "
              << report.refused << " refused\n";
    for (const auto& [p, why] : report.refusals) std::cout << "  refused " << forTerminal(p) << ": " << forTerminal(why) << "\n";
    if (update->shared) std::cout << "shared catalog: " << forTerminal(sharedCatalogText(*update->shared, update->catalog)) << "\n";
  }
  // The bench's rows are in its own catalog; the shared one did not take them.
  if (update->shared && !update->shared->reached) {
    std::cerr << "fogbench-cli: the shared catalog was not updated; the rows wait in the " << update->catalog << "\n";
    return 3;
  }
  return 0;
}

int unitsCommand(CliArguments& args) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  const std::string lot = args.text("lot").value_or("");
  auto cat = openCatalog(args, ".", false);
  if (!cat) return fail(cat.status(), 2);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  auto results = (*cat)->results("", lot, false);
  if (!results) return fail(results.status(), 2);
  const auto units = catalog::summariseUnits(*results);
  auto joinList = [](const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
    return s;
  };
  if (asJson) {
    json out = json::array();
    for (const auto& u : units)
      out.push_back({{"imu_serial", u.serial}, {"imu_model", u.model}, {"lots", u.lots}, {"benches", u.benches},
                     {"sessions", u.sessions}, {"results", u.results}, {"latest_session_utc", u.latestUtc},
                     {"latest_verdict", u.latestVerdict}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  if (asCsv) {
    std::cout << "imu_serial,imu_model,lots,benches,sessions,results,latest_session_utc,latest_verdict\n";
    for (const auto& u : units)
      std::cout << session::csvTextField(u.serial) << "," << session::csvTextField(u.model) << ","
                << session::csvTextField(joinList(u.lots)) << "," << session::csvTextField(joinList(u.benches)) << ","
                << u.sessions << "," << u.results << "," << session::csvTextField(u.latestUtc) << "," << u.latestVerdict << "\n";
    return 0;
  }
  std::vector<std::vector<std::string>> rows = {
      {"IMU serial", "model", "lot", "benches", "sessions", "results", "latest session (UTC)", "its verdict"}};
  for (const auto& u : units)
    rows.push_back({u.serial.empty() ? "(none)" : u.serial, u.model.empty() ? "-" : u.model,
                    u.lots.empty() ? "-" : joinList(u.lots), u.benches.empty() ? "-" : joinList(u.benches),
                    std::to_string(u.sessions), std::to_string(u.results), u.latestUtc.empty() ? "-" : u.latestUtc,
                    u.latestUtc.empty() ? "-" : upper(u.latestVerdict)});
  printColumns(rows);
  std::cout << units.size() << (units.size() == 1 ? " unit" : " units") << " in the " << (*cat)->describe() << "\n";
  return 0;
}

// "session 2026-11-01T08:00:00Z result 2: analysed 2026-11-02T09:10:00Z by
// li (operator) with fogbench-cli analyze [analyze s.fbs --board-delay-ms 0.2]
// | constants 3fa9c1d2e4b5a6f7 | fogbench 0.9.0 | input 3fa9c1d2e4b5".
std::string auditText(const CatalogResult& r) {
  std::string line = "session " + r.sessionCreatedUtc + " result " + std::to_string(r.resultNumber) + ": ";
  if (r.constantsHash.empty())  // a stored result that cannot be read: its reason
    return line + (r.verdictReason.empty() ? "the stored result cannot be read" : r.verdictReason);
  const json a = r.auditJson.empty() ? json() : json::parse(r.auditJson, nullptr, false);
  auto field = [&](const char* key) {
    return a.is_object() && a.contains(key) && a[key].is_string() ? a[key].get<std::string>() : std::string();
  };
  line += "analysed " + (r.resultCreatedUtc.empty() ? std::string("(time not stated)") : r.resultCreatedUtc);
  if (!a.is_object()) {
    line += " with " + (r.analysedBy.empty() ? std::string("(tool not stated)") : r.analysedBy) +
            " (audit not recorded)";
  } else {
    const std::string who = field("who"), source = field("who_source"), command = field("command");
    const std::string tool = field("tool").empty() ? r.analysedBy : field("tool");
    if (!who.empty()) line += " by " + who + (source.empty() ? "" : " (" + source + ")");
    line += " with " + (tool.empty() ? std::string("(tool not stated)") : tool);
    if (!command.empty()) line += " [" + command + "]";
  }
  line += " | constants " + (r.constantsHash.empty() ? std::string("-") : r.constantsHash);
  line += " | fogbench " + (r.softwareVersion.empty() ? std::string("?") : r.softwareVersion);
  const std::string input = field("input_sha256");
  line += " | input " + (input.empty() ? std::string("not recorded") : input.substr(0, 12));
  return line;
}

int unitCommand(CliArguments& args, const std::string& serial) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  auto cat = openCatalog(args, ".", false);
  if (!cat) return fail(cat.status(), 2);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  auto results = (*cat)->results(serial, "", false);
  if (!results) return fail(results.status(), 2);
  if (results->empty())
    return fail(invalidArgument("no result for IMU serial '" + serial + "' in the " + (*cat)->describe() +
                                "; `catalog units` lists the serials it holds"),
                1);
  const auto slope = catalog::delayAgainstTemperature(*results);
  if (asJson) {
    json history = json::array();
    for (const auto& r : *results) history.push_back(resultJson(r));
    json t = {{"vouched_points", slope.n}};
    if (std::isfinite(slope.msPerC)) {
      t["slope_ms_per_c"] = slope.msPerC;
      t["slope_std_ms_per_c"] = slope.stdMsPerC;
    }
    std::cout << json({{"imu_serial", serial}, {"history", history}, {"delay_against_temperature", t}}).dump(2) << "\n";
    return 0;
  }
  if (asCsv) {
    std::cout << catalog::resultsCsv(*results);
    return 0;
  }
  const auto& first = results->front();
  std::cout << "IMU " << forTerminal(serial) << (first.imuModel.empty() ? "" : " (" + forTerminal(first.imuModel) + ")")
            << ": " << results->size() << " results, oldest session first; a superseded result is marked "
            << "\"superseded\" (a later analysis of the same session is shown)\n";
  std::vector<std::vector<std::string>> rows = {{"session (UTC)", "result", "lot", "bench", "operator", "temp (°C)",
                                                 "verdict", "IMU delay per test point", "limit (ms)", "constants",
                                                 "software", "analysed by", "file"}};
  for (const auto& r : *results) {
    std::string points;
    for (const auto& p : r.points) points += (points.empty() ? "" : " / ") + pointText(p);
    if (r.points.empty()) points = r.verdictReason.empty() ? "-" : r.verdictReason;
    rows.push_back({r.sessionCreatedUtc, std::to_string(r.resultNumber) + (r.shown ? "" : " superseded"),
                    r.lot.empty() ? "-" : r.lot, r.benchId.empty() ? "-" : r.benchId,
                    r.operatorName.empty() ? "-" : r.operatorName, fixed(r.meanTemperatureC, 1), upper(r.verdict),
                    points, fixed(r.limitMs, 3), r.constantsHash.empty() ? "-" : r.constantsHash,
                    r.softwareVersion.empty() ? "-" : r.softwareVersion, catalog::analysedByText(r),
                    fs::path(r.path).filename().string()});
  }
  printColumns(rows);
  // The audit trail (docs/sessions.md): per result when it was analysed, by
  // whom, with which command, constants and software, on which raw stream.
  // The hashes shortened here; the JSON has them whole.
  std::cout << "audit trail, one line per result (hashes shortened; --json has them whole):\n";
  for (const auto& r : *results) std::cout << "  " << forTerminal(auditText(r)) << "\n";
  if (std::isfinite(slope.msPerC))
    std::cout << "IMU delay against temperature: " << fixed(slope.msPerC * 1000.0, 3) << " ± "
              << fixed(slope.stdMsPerC * 1000.0, 3) << " µs/°C (least squares over " << slope.n
              << " vouched points of shown results)\n";
  else
    std::cout << "IMU delay against temperature: not stated (needs 3 or more vouched points at two or more "
                 "temperatures; has "
              << slope.n << ")\n";
  return 0;
}

int lotCommand(CliArguments& args, const std::string& lot) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  double limit = NAN;
  if (args.has("limit-ms")) {
    auto l = readDelayLimit(args);
    if (!l) return fail(l.status(), 2);
    limit = *l;
  }
  auto cat = openCatalog(args, ".", false);
  if (!cat) return fail(cat.status(), 2);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  auto results = (*cat)->results("", lot, false);
  if (!results) return fail(results.status(), 2);
  if (results->empty())
    return fail(invalidArgument("no result of lot '" + lot + "' in the " + (*cat)->describe()), 1);
  auto stats = catalog::lotStatistics(lot, *results, limit);
  if (!stats) return fail(stats.status(), 2);
  const auto& s = *stats;
  if (asJson || asCsv) {
    json delay = json::array();
    for (const auto& d : s.delay)
      delay.push_back({{"axis", d.axis}, {"n", d.n}, {"mean_ms", number(d.meanMs)}, {"std_ms", number(d.stdMs)},
                       {"cpk", number(d.cpk)}});
    if (asCsv) {
      std::cout << "lot,units,sessions,pass,fail,invalid,incomplete,no_verdict,superseded,pass_rate,first_pass_yield,"
                   "limit_ms,limit_source,axis,n,mean_ms,std_ms,cpk\n";
      // A lot without a vouched delay still has its row (its counts and
      // yields), with empty delay cells.
      std::vector<catalog::DelayStatistics> rows = s.delay;
      if (rows.empty()) rows.emplace_back();
      for (const auto& d : rows)
        std::cout << session::csvTextField(lot) << "," << s.units << "," << s.sessions << "," << s.pass << "," << s.fail
                  << "," << s.invalid << "," << s.incomplete << "," << s.noVerdict << "," << s.superseded << ","
                  << catalog::textOf(catalog::numberValue(s.passRate)) << ","
                  << catalog::textOf(catalog::numberValue(s.firstPassYield)) << ","
                  << catalog::textOf(catalog::numberValue(s.limitMs)) << "," << s.limitSource << "," << d.axis << ","
                  << d.n << "," << catalog::textOf(catalog::numberValue(d.meanMs)) << ","
                  << catalog::textOf(catalog::numberValue(d.stdMs)) << "," << catalog::textOf(catalog::numberValue(d.cpk))
                  << "\n";
      return 0;
    }
    std::cout << json({{"lot", lot},
                       {"units", s.units},
                       {"sessions", s.sessions},
                       {"by_verdict",
                        {{"pass", s.pass}, {"fail", s.fail}, {"invalid", s.invalid}, {"incomplete", s.incomplete},
                         {"no_verdict", s.noVerdict}}},
                       {"superseded_results", s.superseded},
                       {"pass_rate", number(s.passRate)},
                       {"first_pass_yield", number(s.firstPassYield)},
                       {"limit_ms", number(s.limitMs)},
                       {"limit_source", s.limitSource},
                       {"imu_delay", delay},
                       {"definitions",
                        {{"pass_rate", catalog::kPassRateDefinition},
                         {"first_pass_yield", catalog::kFirstPassYieldDefinition},
                         {"imu_delay", catalog::kLotDelayDefinition},
                         {"cpk", catalog::kCpkDefinition}}}})
                     .dump(2)
              << "\n";
    return 0;
  }
  auto pct = [](double f, int of) {
    return fixed(f * 100.0, 1) + " % (" + std::to_string(static_cast<int>(std::lround(f * of))) + " of " +
           std::to_string(of) + ")";
  };
  std::cout << "lot " << forTerminal(lot) << ": " << s.units << (s.units == 1 ? " unit, " : " units, ") << s.sessions
            << " sessions — PASS " << s.pass << ", FAIL " << s.fail << ", INVALID " << s.invalid << ", INCOMPLETE "
            << s.incomplete << (s.noVerdict ? ", no verdict " + std::to_string(s.noVerdict) : std::string()) << "; "
            << s.superseded << " superseded results (re-analysed) not counted\n"
            << "pass rate:        " << pct(s.passRate, s.units) << " — units whose latest session shows PASS\n"
            << "first-pass yield: " << pct(s.firstPassYield, s.units) << " — units whose first session shows PASS\n"
            << "IMU delay over the vouched test points of PASS and FAIL results (INVALID and INCOMPLETE results are "
               "counted above, never averaged):\n";
  std::vector<std::vector<std::string>> rows = {
      {"axis", "points", "mean (ms)", "s (ms)",
       "Cpk against " + fixed(s.limitMs, 3) + " ms (" + (s.limitSource.empty() ? "none" : s.limitSource) + ")"}};
  for (const auto& d : s.delay)
    rows.push_back({d.axis, std::to_string(d.n), fixed(d.meanMs, 4), fixed(d.stdMs, 4), fixed(d.cpk, 2)});
  if (s.delay.empty()) rows.push_back({"-", "0", "-", "-", "-"});
  printColumns(rows);
  std::cout << "Cpk = (limit − mean) / (3 s), one-sided (the IMU delay has an upper limit only); s is the spread "
               "of the units' delays, not their measurement σ\n";
  return 0;
}

int pushCommand(CliArguments& args) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  const auto from = args.text("from");
  if (!from) return fail(invalidArgument("catalog push: name the local catalog with --from FILE|FOLDER"), 2);
  if (!args.has("db") || !catalog::isPostgresTarget(*args.text("db")))
    return fail(invalidArgument("catalog push: name the shared catalog with --db postgresql://…"), 2);
  std::error_code ec;
  std::string local = *from;
  if (fs::is_directory(local, ec)) local = (fs::path(local) / catalog::kDefaultCatalogFileName).string();
  if (!fs::exists(local, ec)) return fail(invalidArgument("no local catalog at '" + local + "'"), 2);
  auto localDb = catalog::CatalogDb::open(local);
  if (!localDb) return fail(localDb.status(), 2);
  auto localCat = catalog::Catalog::open(std::move(*localDb));
  if (!localCat) return fail(localCat.status(), 2);
  auto remote = openCatalog(args, "", true);
  if (!remote) return fail(remote.status(), 3);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  auto report = (*localCat)->pushTo(**remote);
  if (!report) return fail(report.status(), 3);
  if (asCsv) {
    std::cout << "from,to,pushed,already_pushed\n"
              << csvText((*localCat)->describe()) << "," << csvText((*remote)->describe()) << "," << report->pushed
              << "," << report->alreadyPushed << "\n";
    return 0;
  }
  if (asJson) {
    std::cout << json({{"from", (*localCat)->describe()},
                       {"to", (*remote)->describe()},
                       {"pushed", report->pushed},
                       {"already_pushed", report->alreadyPushed}})
                     .dump(2)
              << "\n";
    return 0;
  }
  std::cout << "pushed " << report->pushed << " results from the " << (*localCat)->describe() << " to the "
            << (*remote)->describe() << "; " << report->alreadyPushed << " pushed before and unchanged\n";
  return 0;
}

int refusedCommand(CliArguments& args) {
  const bool asJson = args.flag("json"), asCsv = args.flag("csv");
  auto cat = openCatalog(args, ".", false);
  if (!cat) return fail(cat.status(), 2);
  if (Status s = args.checkAllUsed(); !s.isOk()) return fail(s, 2);
  auto refusals = (*cat)->refusals();
  if (!refusals) return fail(refusals.status(), 2);
  if (asCsv) {
    std::cout << "path,refusal\n";
    for (const auto& [p, why] : *refusals) std::cout << csvText(p) << "," << csvText(why) << "\n";
    return 0;
  }
  if (asJson) {
    json out = json::array();
    for (const auto& [p, why] : *refusals) out.push_back({{"path", p}, {"refusal", why}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  for (const auto& [p, why] : *refusals) std::cout << forTerminal(p) << ": " << forTerminal(why) << "\n";
  std::cout << refusals->size() << " refused files in the " << (*cat)->describe() << "\n";
  return 0;
}

}  // namespace

Result<CatalogUpdate> updateCatalog(const std::string& db, const std::string& folder,
                                    const std::vector<std::string>& paths, bool create,
                                    const std::function<void(int, int)>& progress) {
  CatalogUpdate u;
  std::error_code ec;
  const std::string own = catalogFileIn(folder);
  std::string target = db;
  if (target.empty()) {
    if (!create && !fs::exists(own, ec)) {
      u.none = true;
      return u;
    }
    target = own;
  } else if (!catalog::isPostgresTarget(target) && fs::is_directory(target, ec)) {
    target = catalogFileIn(target);
  }
  if (!catalog::isPostgresTarget(target)) {
    FOG_ASSIGN_OR_RETURN(auto cat, openTarget(target));
    FOG_ASSIGN_OR_RETURN(u.index, cat->index(paths, progress));
    u.catalog = cat->describe();
    return u;
  }
  // A shared catalog: the bench's own catalog first, which works offline;
  // then what it holds pending is pushed (docs/catalog.md, "A bench offline").
  auto local = openTarget(own);
  if (!local) {
    // A folder the bench cannot write (an archive): straight into the server.
    auto shared = openTarget(target);
    if (!shared)
      return Status(shared.status().code(), shared.status().message() + "; and the bench's own catalog " + own +
                                                " cannot be written either (" + local.status().message() + ")");
    FOG_ASSIGN_OR_RETURN(u.index, (*shared)->index(paths, progress));
    u.catalog = (*shared)->describe();
    u.note = "the bench's own catalog " + own + " cannot be written (" + local.status().message() +
             "): indexed straight into the " + u.catalog + ", nothing kept pending";
    return u;
  }
  FOG_ASSIGN_OR_RETURN(u.index, (*local)->index(paths, progress));
  u.catalog = (*local)->describe();
  FOG_ASSIGN_OR_RETURN(auto sync, catalog::pushPending(**local, target));
  u.shared = std::move(sync);
  return u;
}

std::string sharedCatalogText(const catalog::SyncReport& s, const std::string& local) {
  const std::string pending = std::to_string(s.pending) + (s.pending == 1 ? " result" : " results");
  if (s.reached)
    return "pushed " + std::to_string(s.push.pushed) + " results to the " + s.shared + " (" +
           std::to_string(s.push.alreadyPushed) + " pushed before and unchanged); " +
           (s.pending == 0 ? std::string("none pending") : pending + " pending");
  return "not updated: " + s.problem + "; " + pending + " pending in the " + local +
         ": the next catalog index, batch or catalog push sends them";
}

Status updateCatalogAfterBatch(const std::string& db, const std::string& folder, const std::vector<std::string>& files) {
  FOG_ASSIGN_OR_RETURN(auto u, updateCatalog(db, folder, files, false));
  if (u.none) {
    std::cout << "catalog: none updated (no " << catalog::kDefaultCatalogFileName << " in " << forTerminal(folder)
              << "; give --db, or run fogbench-cli catalog index)\n";
    return Status::ok();
  }
  if (!u.note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(u.note) << "\n";
  std::cout << "catalog: " << u.catalog << " updated: " << u.index.indexed << " sessions re-indexed ("
            << u.index.resultsStored << " results), " << u.index.unchanged << " unchanged, " << u.index.refused
            << " refused\n";
  if (u.shared) {
    std::cout << "shared catalog: " << forTerminal(sharedCatalogText(*u.shared, u.catalog)) << "\n";
    if (!u.shared->reached) return ioError("the shared catalog was not updated: " + u.shared->problem);
  }
  return Status::ok();
}

void updateCatalogAfterAnalysis(const std::string& db, const std::string& sessionPath, bool quiet) {
  std::string folder = fs::path(sessionPath).parent_path().string();
  if (folder.empty()) folder = ".";
  const std::string catchUp = "fogbench-cli catalog index " + folder + (db.empty() ? "" : " --db " + catalog::describeTarget(db));
  auto u = updateCatalog(db, folder, {sessionPath}, false);
  if (!u) {
    std::cerr << "fogbench-cli: note: the catalog was not updated (" << forTerminal(u.status().message())
              << "); the result is stored in the session; catch up with: " << forTerminal(catchUp) << "\n";
    return;
  }
  if (u->none) return;  // this folder keeps no catalog
  if (!u->note.empty()) std::cerr << "fogbench-cli: note: " << forTerminal(u->note) << "\n";
  if (u->index.refused > 0 && !u->index.refusals.empty())
    std::cerr << "fogbench-cli: note: the " << u->catalog << " refused the session ("
              << forTerminal(u->index.refusals.front().second) << "); catch up with: " << forTerminal(catchUp) << "\n";
  else if (!quiet)
    std::cout << "Catalog updated: " << u->catalog << ".\n";
  if (u->shared && !u->shared->reached)
    std::cerr << "fogbench-cli: note: the shared catalog was " << forTerminal(sharedCatalogText(*u->shared, u->catalog))
              << "\n";
}

int catalogCommand(CliArguments& args) {
  const auto& pos = args.positionals();
  if (pos.empty())
    return fail(invalidArgument("catalog: say what to do: index DIR…, units, unit SERIAL, lot LOT, push, refused"), 2);
  const std::string what = pos[0];
  const std::vector<std::string> rest(pos.begin() + 1, pos.end());
  if (what == "index") return indexCommand(args, rest);
  if (what == "units" && rest.empty()) return unitsCommand(args);
  if (what == "unit") {
    if (rest.size() == 1 && !rest[0].empty()) return unitCommand(args, rest[0]);
    return fail(invalidArgument("catalog unit: name one IMU serial"), 2);
  }
  if (what == "lot") {
    if (rest.size() == 1 && !rest[0].empty()) return lotCommand(args, rest[0]);
    return fail(invalidArgument("catalog lot: name one lot"), 2);
  }
  if (what == "push" && rest.empty()) return pushCommand(args);
  if (what == "refused" && rest.empty()) return refusedCommand(args);
  return fail(invalidArgument("catalog: unknown or misused '" + what +
                              "'; use index DIR…, units, unit SERIAL, lot LOT, push, refused"),
              2);
}

}  // namespace fog::app
