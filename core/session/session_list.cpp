#include "core/session/session_list.h"

#include <algorithm>
#include <filesystem>

#include "core/common/text.h"
#include "core/session/session_file.h"
#include "core/session/stored_result.h"

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
    if (Status raw = (*r)->checkRawStream(); !raw.isOk()) s.rawDamage = toValidUtf8(raw.message());
    auto results = (*r)->results();
    if (results) {
      s.results = results->size();
      const auto records = readStoredResults(*results, s.info.bench);
      for (const auto& rec : records) s.damagedResults += rec.usable ? 0 : 1;
      // The latest usable result, judged by the one rule (shown_verdict.h).
      if (const StoredResultRecord* latest = newestUsable(records)) {
        for (std::size_t i = 0; i < records.size(); ++i)
          if (records[i].id == latest->id) s.shownResult = i + 1;
        s.shown = judgeShown(latest, nullptr, s.complete, s.incompleteReason, latest->imuDelayLimitMs,
                             latest->coverageK);
      }
    }
    listing.sessions.push_back(std::move(s));
  }
  return listing;
}

}  // namespace fog::session
