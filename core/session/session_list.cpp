#include "core/session/session_list.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/common/text.h"
#include "core/session/session_file.h"

namespace fog::session {

namespace fs = std::filesystem;

std::string axesOf(const TestPlan& plan) {
  std::string out;
  for (int a = 0; a < kAxisCount; ++a) {
    const bool used = std::any_of(plan.points.begin(), plan.points.end(),
                                  [&](const TestPoint& p) { return static_cast<int>(p.axis) == a; });
    if (!used) continue;
    if (!out.empty()) out += ',';
    out += axisName(static_cast<Axis>(a));
  }
  return out.empty() ? "-" : out;
}

Result<SessionListing> listSessions(const std::string& dirText) {
  const fs::path dir = dirText;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return ioError(dirText + " is not a folder");
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(it->path());
  if (ec) return ioError("cannot list '" + dir.string() + "': " + ec.message());
  std::sort(files.begin(), files.end());

  SessionListing listing;
  for (const auto& f : files) {
    const std::string p = f.string();
    const std::string name = f.filename().string();
    // SQLite's side files of a session being recorded (or killed while
    // recording) belong to that session: neither listed nor "skipped".
    bool sideFile = false;
    for (const std::string sfx : {"-wal", "-shm", "-journal"})
      if (name.size() > sfx.size() && name.compare(name.size() - sfx.size(), sfx.size(), sfx) == 0 &&
          fs::exists(p.substr(0, p.size() - sfx.size()), ec))
        sideFile = true;
    if (sideFile) continue;
    // A damaged .fbs (truncated, overwritten) is listed as unreadable with
    // the reason, not counted among the other files.
    if (!looksLikeSession(p) && f.extension() != ".fbs") {
      ++listing.skippedFiles;
      continue;
    }
    SessionSummary s;
    s.path = p;
    s.fileName = toValidUtf8(name);  // for display: a file name need not be UTF-8
    auto r = SessionReader::open(p);
    if (!r) {
      s.error = toValidUtf8(r.status().message());
      listing.sessions.push_back(std::move(s));
      continue;
    }
    s.info = (*r)->info();
    s.complete = (*r)->complete();
    s.incompleteReason = (*r)->incompleteReason();
    auto results = (*r)->results();
    if (results) s.results = results->size();
    // The latest result that passes its checksum and parses as a report.
    nlohmann::json latest;
    if (results)
      for (std::size_t i = 0; i < results->size(); ++i) {
        const auto& res = (*results)[i];
        auto doc = res.intact ? nlohmann::json::parse(res.reportJson, nullptr, false) : nlohmann::json();
        if (!doc.is_object()) {
          ++s.damagedResults;
          continue;
        }
        latest = std::move(doc);
        s.shownResult = i + 1;
      }
    if (s.shownResult > 0) {
      if (latest.contains("verdict") && latest["verdict"].is_string()) s.verdict = latest["verdict"];
      if (latest.contains("test_points") && latest["test_points"].is_array()) {
        for (const auto& tp : latest["test_points"]) {
          if (tp.contains("lag_ms") && tp["lag_ms"].is_number()) s.lagMs.push_back(tp["lag_ms"]);
          if (tp.contains("imu_delay_ms") && tp["imu_delay_ms"].is_number()) s.imuDelayMs.push_back(tp["imu_delay_ms"]);
        }
      }
    }
    listing.sessions.push_back(std::move(s));
  }
  return listing;
}

}  // namespace fog::session
