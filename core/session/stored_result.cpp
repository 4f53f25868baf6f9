#include "core/session/stored_result.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <pwd.h>
#include <unistd.h>

#include <cstdlib>

#include "core/common/version.h"

namespace fog::session {

namespace {

using nlohmann::json;

double numberOr(const json& o, const char* key, double fallback) {
  if (!o.is_object()) return fallback;
  const auto it = o.find(key);
  return it != o.end() && it->is_number() ? it->get<double>() : fallback;
}

std::string textOr(const json& o, const char* key, const std::string& fallback = {}) {
  if (!o.is_object()) return fallback;
  const auto it = o.find(key);
  return it != o.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::vector<std::string> texts(const json& o, const char* key) {
  std::vector<std::string> out;
  if (!o.is_object()) return out;
  const auto it = o.find(key);
  if (it == o.end() || !it->is_array()) return out;
  for (const auto& v : *it)
    if (v.is_string()) out.push_back(v.get<std::string>());
  return out;
}

}  // namespace

const StoredPointVerdict* StoredResultRecord::point(int index) const {
  for (const auto& p : points)
    if (p.index == index) return &p;
  return nullptr;
}

StoredResultRecord readStoredResult(const session::StoredResult& stored, const BenchConstants& fallback) {
  StoredResultRecord r;
  r.id = stored.id;
  r.createdUtc = stored.createdUtc;
  r.constants = fallback;
  r.constants.gyroSign = {1, 1, 1};  // what every row before gyro signs were stored was analysed with
  if (!stored.intact) {
    r.problem = "the stored result fails its checksum";
    return r;
  }
  const json settings = json::parse(stored.settingsJson, nullptr, false);
  const json report = json::parse(stored.reportJson, nullptr, false);
  if (!settings.is_object()) {
    r.problem = "the stored settings are not a JSON object";
    return r;
  }
  if (!report.is_object()) {
    r.problem = "the stored report is not a JSON object";
    return r;
  }
  r.usable = true;
  r.softwareVersion = textOr(settings, "software_version");
  r.analysedBy = textOr(settings, "analysed_by");
  const json reported = report.is_object() && report.contains("constants") ? report["constants"] : json();
  auto constant = [&](const char* key, double otherwise) {
    return numberOr(settings, key, numberOr(reported, key, otherwise));
  };
  auto& c = r.constants;
  c.tableReadDelayMs = constant("table_read_delay_ms", fallback.tableReadDelayMs);
  c.tableReadDelayStdMs = constant("table_read_delay_std_ms", fallback.tableReadDelayStdMs);
  c.boardDelayMs = constant("board_delay_ms", fallback.boardDelayMs);
  c.boardDelayStdMs = constant("board_delay_std_ms", fallback.boardDelayStdMs);
  c.pulseEquivalentDeg = constant("pulse_equivalent_deg", fallback.pulseEquivalentDeg);
  // The scale tolerance the gain check judged with (rows stored before it
  // was kept: the report's, else the session's).
  c.gainToleranceFraction = constant("gain_tolerance", fallback.gainToleranceFraction);
  if (settings.contains("gyro_sign") && settings["gyro_sign"].is_object()) {
    r.gyroSignStated = true;
    for (int a = 0; a < kAxisCount; ++a) {
      const double s = numberOr(settings["gyro_sign"], axisName(static_cast<Axis>(a)), 1.0);
      c.gyroSign[static_cast<std::size_t>(a)] = s < 0 ? -1 : 1;
    }
  }
  // A row stored before its settings held the signs: its report states the
  // sign applied to each analysed test point's swing axis (`gyro_sign`), so
  // e.g. an older `analyze --gyro-sign x=-1` is still reviewed with -1.
  if (!r.gyroSignStated && report.contains("test_points") && report["test_points"].is_array())
    for (const auto& tp : report["test_points"]) {
      const std::string axis = textOr(tp, "axis");
      const double sign = numberOr(tp, "gyro_sign", 0.0);
      for (int a = 0; a < kAxisCount; ++a)
        if (axis == axisName(static_cast<Axis>(a)) && sign != 0.0) {
          c.gyroSign[static_cast<std::size_t>(a)] = sign < 0 ? -1 : 1;
          r.gyroSignStated = true;
        }
    }
  if (settings.contains("audit") && settings["audit"].is_object()) {
    const json& a = settings["audit"];
    r.audit = AnalysisAudit{textOr(a, "who"), textOr(a, "who_source"), textOr(a, "tool"), textOr(a, "command"),
                            textOr(a, "input_sha256")};
  }
  if (settings.contains("import")) {
    auto imported = importSettingsFromJson(settings["import"].dump());
    if (imported) r.imported = std::move(*imported);
  }
  // The limit the verdict used: the report's own field is what judged it.
  const double limit = numberOr(report, "imu_delay_limit_ms", numberOr(settings, "imu_delay_limit_ms", NAN));
  if (std::isfinite(limit) && limit > 0.0) {
    r.imuDelayLimitMs = limit;
    r.limitStated = true;
  }
  // The rule's k: the report's own decision_rule judged it, as the limit.
  const auto ruleOf = [](const json& o) { return o.is_object() && o.contains("decision_rule") ? o["decision_rule"] : json(); };
  const double k = numberOr(ruleOf(report), "coverage_factor_k", numberOr(ruleOf(settings), "coverage_factor_k", NAN));
  if (analysis::coverageFactorProblem(k).empty()) {
    r.coverageK = k;
    r.coverageKStated = true;
  }
  r.verdict = textOr(report, "verdict");
  r.verdictReasons = texts(report, "verdict_reasons");
  r.dataVerdict = textOr(report, "data_verdict");
  if (report.contains("run") && report["run"].is_object()) {
    r.incompleteReason = textOr(report["run"], "incomplete_reason", "the run ended early");
    r.recordedS = numberOr(report["run"], "recorded_s", 0.0);
    r.plannedS = numberOr(report["run"], "planned_s", 0.0);
  }
  if (report.contains("test_points") && report["test_points"].is_array())
    for (const auto& tp : report["test_points"]) {
      if (!tp.is_object() || !tp.contains("index") || !tp["index"].is_number_integer()) continue;
      StoredPointVerdict p;
      p.index = tp["index"].get<int>();
      p.verdict = textOr(tp, "verdict");
      p.reasons = texts(tp, "verdict_reasons");
      p.lagMs = numberOr(tp, "lag_ms", NAN);
      p.lagStdMs = numberOr(tp, "lag_std_ms", NAN);
      p.imuDelayMs = numberOr(tp, "imu_delay_ms", NAN);
      p.imuDelayStdMs = numberOr(tp, "imu_delay_std_ms", NAN);
      r.points.push_back(std::move(p));
    }
  return r;
}

std::vector<StoredResultRecord> readStoredResults(const std::vector<session::StoredResult>& stored,
                                                  const BenchConstants& fallback) {
  std::vector<StoredResultRecord> out;
  out.reserve(stored.size());
  for (const auto& s : stored) out.push_back(readStoredResult(s, fallback));
  return out;
}

std::string decisionRuleProvenance(const StoredResultRecord& record) {
  if (record.coverageKStated) return {};
  return "not stored: the rule of that version, k = " + analysis::coverageFactorText(analysis::kDefaultCoverageFactor);
}

const StoredResultRecord* newestUsable(const std::vector<StoredResultRecord>& records) {
  for (auto r = records.rbegin(); r != records.rend(); ++r)
    if (r->usable) return &*r;
  return nullptr;
}

std::vector<std::string> differencesFromRecord(const StoredResultRecord& record, const analysis::DelayReport& now) {
  std::vector<std::string> out;
  char buf[256];
  for (const auto& p : now.points) {
    const StoredPointVerdict* s = record.point(p.index);
    const std::string tp = "test point " + std::to_string(p.index + 1);
    if (!s) {
      out.push_back(tp + ": the stored result has no delay for it; this version's analysis gives one");
      continue;
    }
    // Rounding: the JSON keeps 17 digits; 1e-6 ms is far below any reported digit.
    if (!(std::abs(s->imuDelayMs - p.imuDelayMs) <= 1e-6)) {
      std::snprintf(buf, sizeof buf, "%s: IMU delay %.4f ms stored, %.4f ms by this version's analysis", tp.c_str(),
                    s->imuDelayMs, p.imuDelayMs);
      out.push_back(buf);
    }
    const std::string judged = analysis::verdictName(analysis::judgePoint(p, record.imuDelayLimitMs, record.coverageK).verdict);
    if (!s->verdict.empty() && s->verdict != judged) out.push_back(tp + ": " + s->verdict + " stored, " + judged +
                                                                   " by this version's analysis");
  }
  for (const auto& s : record.points) {
    const bool analysed = std::any_of(now.points.begin(), now.points.end(),
                                      [&](const analysis::TestPointResult& p) { return p.index == s.index; });
    if (!analysed)
      out.push_back("test point " + std::to_string(s.index + 1) +
                    ": the stored result has a delay; this version's analysis gives none");
  }
  return out;
}

std::string analysisSettingsJson(const BenchConstants& c, double imuDelayLimitMs,
                                 const std::string& producedBy, const ImportSettings& imported,
                                 const AnalysisAudit* audit, double coverageK) {
  json doc = {{"table_read_delay_ms", c.tableReadDelayMs},
              {"table_read_delay_std_ms", c.tableReadDelayStdMs},
              {"board_delay_ms", c.boardDelayMs},
              {"board_delay_std_ms", c.boardDelayStdMs},
              {"pulse_equivalent_deg", c.pulseEquivalentDeg},
              {"gain_tolerance", c.gainToleranceFraction},
              {"gyro_sign", {{"x", c.gyroSign[0]}, {"y", c.gyroSign[1]}, {"z", c.gyroSign[2]}}},
              {"imu_delay_limit_ms", imuDelayLimitMs},
              {"software_version", FOG_VERSION},
              {"analysed_by", producedBy}};
  if (!imported.empty()) doc["import"] = json::parse(importSettingsToJson(imported));
  if (audit)
    doc["audit"] = {{"who", audit->who},
                    {"who_source", audit->whoSource},
                    {"tool", audit->tool},
                    {"command", audit->command},
                    {"input_sha256", audit->inputSha256}};
  doc["decision_rule"] = {{"rule", analysis::kDecisionRuleName},
                          {"coverage_factor_k", coverageK},
                          {"limit_ms", imuDelayLimitMs}};
  // Replaced, not thrown: an argument line or a name that is not UTF-8
  // must not cost the result.
  return doc.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string loginName() {
  // getpwuid: the account's name even under sudo -u or without $USER set
  // (a service, a cron job); $USER only when the passwd entry is missing.
  if (const passwd* pw = ::getpwuid(::geteuid()); pw && pw->pw_name && *pw->pw_name) return pw->pw_name;
  if (const char* user = std::getenv("USER"); user && *user) return user;
  return "uid " + std::to_string(::geteuid());
}

AnalysisAudit makeAudit(const std::string& operatorName, std::string tool, std::string command,
                        std::string inputSha256) {
  AnalysisAudit a;
  const bool named = !operatorName.empty();
  a.who = named ? operatorName : loginName();
  a.whoSource = named ? "operator" : "login";
  a.tool = std::move(tool);
  a.command = std::move(command);
  a.inputSha256 = std::move(inputSha256);
  return a;
}

std::string commandLineOf(const std::string& program, int argc, const char* const* argv) {
  std::string out = program;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i] ? argv[i] : "";
    if (arg.empty() || arg.find_first_of(" \t'\"") != std::string::npos) {
      std::string q = "'";
      for (char ch : arg) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
      arg = q + "'";
    }
    if (!out.empty()) out += ' ';
    out += arg;
  }
  return out;
}

std::vector<std::string> auditTrailLines(const std::vector<StoredResultRecord>& records) {
  std::vector<std::string> out;
  char buf[512];
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    std::string line = "#";
    line += std::to_string(i + 1);
    line += ' ';
    line += r.createdUtc.empty() ? std::string("(no time)") : r.createdUtc;
    if (!r.usable) {
      out.push_back(line + " | cannot be read: " + r.problem);
      continue;
    }
    if (r.audit) {
      const auto& a = *r.audit;
      line += " by " + (a.who.empty() ? std::string("(no one named)") : a.who);
      if (!a.whoSource.empty()) line += " (" + a.whoSource + ")";
      line += " " + (a.tool.empty() ? r.analysedBy : a.tool);
      if (!a.command.empty()) line += " [" + a.command + "]";
    } else {
      line += " " + (r.analysedBy.empty() ? std::string("(tool not stated)") : r.analysedBy) +
              " (audit not recorded)";
    }
    const auto& c = r.constants;
    std::snprintf(buf, sizeof buf, " | constants: table read %.3f ± %.3f ms, board %.3f ± %.3f ms",
                  c.tableReadDelayMs, c.tableReadDelayStdMs, c.boardDelayMs, c.boardDelayStdMs);
    line += buf;
    // 0: none given, the stream's own statement converted the pulses.
    if (c.pulseEquivalentDeg > 0.0) std::snprintf(buf, sizeof buf, ", pulse %.6g deg", c.pulseEquivalentDeg);
    else std::snprintf(buf, sizeof buf, ", pulse as the stream states");
    line += buf;
    std::snprintf(buf, sizeof buf, ", limit %g ms%s, k %g%s", r.imuDelayLimitMs,
                  r.limitStated ? "" : " (not stated: default)", r.coverageK, r.coverageKStated ? "" : " (not stated)");
    line += buf;
    if (c.gyroSign != std::array<int, kAxisCount>{1, 1, 1})
      line += ", gyro signs x" + std::string(c.gyroSign[0] < 0 ? "-" : "+") + " y" +
              (c.gyroSign[1] < 0 ? "-" : "+") + " z" + (c.gyroSign[2] < 0 ? "-" : "+");
    line += " | fogbench " + (r.softwareVersion.empty() ? std::string("(version not stated)") : r.softwareVersion);
    if (!r.audit) line += " | input not recorded";
    else if (r.audit->inputSha256.empty()) line += " | input hash not known";
    else line += " | input " + r.audit->inputSha256.substr(0, 12);
    // The verdict as stored, never re-judged (shown_verdict.h): the record's
    // word; a row that states none says so.
    std::string verdict = r.verdict;
    for (auto& ch : verdict) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    line += " | " + (verdict.empty() ? std::string("NO VERDICT") : verdict);
    if (r.verdict == "incomplete" && !r.dataVerdict.empty()) line += " (its data give " + r.dataVerdict + ")";
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace fog::session
