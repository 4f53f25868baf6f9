#include "core/catalog/catalog.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "core/common/parallel.h"
#include "core/common/sha256.h"
#include "core/common/text.h"
#include "core/session/session_file.h"
#include "core/session/shown_csv.h"
#include "core/session/shown_verdict.h"
#include "core/session/stored_result.h"

namespace fog::catalog {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The schema: portable SQL that SQLite and PostgreSQL read alike (TEXT,
// BIGINT, DOUBLE PRECISION; flags as 0/1). docs/catalog.md describes it.
constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS catalog_info (
  key TEXT PRIMARY KEY,
  value TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS indexed_file (
  path TEXT PRIMARY KEY,
  size_bytes BIGINT NOT NULL,
  mtime_ns BIGINT NOT NULL,
  session_key TEXT,
  file_sha256 TEXT,
  indexed_utc TEXT NOT NULL,
  refusal TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS result (
  result_key TEXT PRIMARY KEY,
  session_key TEXT NOT NULL,
  result_number BIGINT NOT NULL,
  path TEXT NOT NULL,
  file_sha256 TEXT NOT NULL,
  imu_serial TEXT NOT NULL,
  imu_model TEXT NOT NULL,
  lot TEXT NOT NULL,
  bench_id TEXT NOT NULL,
  operator TEXT NOT NULL,
  session_created_utc TEXT NOT NULL,
  result_created_utc TEXT NOT NULL,
  mean_temperature_c DOUBLE PRECISION,
  run_complete BIGINT NOT NULL,
  verdict TEXT NOT NULL,
  verdict_reason TEXT NOT NULL,
  limit_ms DOUBLE PRECISION,
  constants_hash TEXT NOT NULL,
  constants TEXT NOT NULL,
  software_version TEXT NOT NULL,
  analysed_by TEXT NOT NULL,
  audit TEXT NOT NULL,
  shown BIGINT NOT NULL,
  pushed BIGINT NOT NULL
);
CREATE INDEX IF NOT EXISTS result_by_serial ON result (imu_serial);
CREATE INDEX IF NOT EXISTS result_by_lot ON result (lot);
CREATE INDEX IF NOT EXISTS result_by_path ON result (path);
CREATE TABLE IF NOT EXISTS result_point (
  result_key TEXT NOT NULL,
  point_index BIGINT NOT NULL,
  axis TEXT NOT NULL,
  frequency_hz DOUBLE PRECISION,
  amplitude_deg DOUBLE PRECISION,
  verdict TEXT NOT NULL,
  imu_delay_ms DOUBLE PRECISION,
  imu_delay_std_ms DOUBLE PRECISION,
  refusal TEXT NOT NULL,
  PRIMARY KEY (result_key, point_index)
);
)sql";

constexpr const char* kResultColumns =
    "result_key, session_key, result_number, path, file_sha256, imu_serial, imu_model, lot, bench_id, operator, "
    "session_created_utc, result_created_utc, mean_temperature_c, run_complete, verdict, verdict_reason, limit_ms, "
    "constants_hash, constants, software_version, analysed_by, audit, shown, pushed";

std::string nowUtc() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

bool statFile(const std::string& path, std::int64_t& size, std::int64_t& mtimeNs) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0) return false;
  size = static_cast<std::int64_t>(st.st_size);
  mtimeNs = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
  return true;
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

// RAII transaction: rolled back unless committed.
class Transaction {
 public:
  explicit Transaction(CatalogDb& db) : db_(db) { begun_ = db_.exec("BEGIN"); }
  ~Transaction() {
    if (begun_.isOk() && !done_) (void)db_.exec("ROLLBACK");
  }
  const Status& begun() const { return begun_; }
  Status commit() {
    done_ = true;
    return db_.exec("COMMIT");
  }

 private:
  CatalogDb& db_;
  Status begun_;
  bool done_ = false;
};

// Sessions under `p` (recursively) or `p` itself, as `sessions` lists them:
// SQLite's side files of a session are not sessions of their own.
void collect(const std::string& p, std::vector<std::string>& out, std::vector<std::pair<std::string, std::string>>& bad) {
  std::error_code ec;
  // One name per file, whichever working folder or spelling (./s, s, a
  // symbolic link) named it: the catalog's rows and the incremental check go
  // by path.
  auto canonical = [](const fs::path& f) {
    std::error_code e;
    const fs::path c = fs::weakly_canonical(fs::absolute(f, e), e);
    return e ? fs::absolute(f, e).lexically_normal().string() : c.string();
  };
  if (!fs::is_directory(p, ec)) {
    if (fs::exists(p, ec)) {
      out.push_back(canonical(p));
    } else {
      bad.emplace_back(p, "no such file or folder");
    }
    return;
  }
  for (fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const std::string f = it->path().string();
    if (it->path().extension() == ".fbs" || session::looksLikeSession(f)) out.push_back(canonical(it->path()));
  }
  if (ec) bad.emplace_back(p, "cannot list it: " + ec.message());
}

}  // namespace

std::string constantsJsonOf(const BenchConstants& c) {
  // Fixed keys in a fixed order: the hash changes only with a value.
  auto num = [](double v) { return textOf(numberValue(v)); };
  std::string out = "{";
  const std::pair<const char*, std::string> fields[] = {
      {"table_read_delay_ms", num(c.tableReadDelayMs)},
      {"table_read_delay_std_ms", num(c.tableReadDelayStdMs)},
      {"board_delay_ms", num(c.boardDelayMs)},
      {"board_delay_std_ms", num(c.boardDelayStdMs)},
      {"pulse_equivalent_deg", num(c.pulseEquivalentDeg)},
      {"gain_tolerance", num(c.gainToleranceFraction)},
      {"gyro_sign_x", std::to_string(c.gyroSign[0])},
      {"gyro_sign_y", std::to_string(c.gyroSign[1])},
      {"gyro_sign_z", std::to_string(c.gyroSign[2])},
  };
  for (const auto& [k, v] : fields) out += std::string(out.size() > 1 ? "," : "") + "\"" + k + "\":" + v;
  return out + "}";
}

IndexedFile describeSessionFile(const std::string& path) {
  IndexedFile f;
  f.path = path;
  if (!statFile(path, f.sizeBytes, f.mtimeNs)) {
    f.refusal = "cannot be read: it vanished while indexing";
    return f;
  }
  auto opened = session::SessionReader::open(path);
  if (!opened) {
    f.refusal = toValidUtf8(opened.status().message());
    return f;
  }
  const session::SessionReader& r = **opened;
  if (r.beingRecorded()) {
    f.refusal = "being recorded; it is indexed once the run has finished";
    return f;
  }
  // The raw stream's checks (order, offsets, checksums) and its SHA-256 in
  // one walk: a damaged source of truth is a refusal.
  auto rawSha = r.rawSha256();
  if (!rawSha) {
    f.refusal = toValidUtf8(rawSha.status().message());
    return f;
  }
  auto sha = sha256OfFile(path);
  if (!sha) {
    f.refusal = sha.status().message();
    return f;
  }
  f.fileSha256 = *sha;
  const SessionInfo& info = r.info();
  // What names the session wherever its file lies: its identity and the
  // hash of its raw stream (the data). A copy or a move of the file is the
  // same session (its results are counted once); two sessions with the same
  // identity but other data are two.
  f.sessionKey = sha256Hex(info.createdUtc + "\n" + info.source + "\n" + info.operatorName + "\n" + info.imuModel +
                           "\n" + info.imuSerial + "\n" + info.lot + "\n" + info.benchId + "\n" + *rawSha)
                     .substr(0, 32);

  double temperature = kNaN;
  if (auto rec = r.recording()) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& point : rec->testPoints)
      for (const auto& s : point.imu) {
        sum += s.temperatureC;
        ++n;
      }
    if (n > 0) temperature = sum / static_cast<double>(n);
  }

  auto stored = r.results();
  if (!stored) {
    f.refusal = toValidUtf8(stored.status().message());
    return f;
  }
  const auto records = session::readStoredResults(*stored, info.bench);
  const session::StoredResultRecord* newest = session::newestUsable(records);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& rec = records[i];
    CatalogResult c;
    c.sessionKey = f.sessionKey;
    // The row id and its content: two copies of a session re-analysed apart
    // both have a row 3, and they are two results.
    c.resultKey = f.sessionKey + ":" + std::to_string(rec.id) + ":" +
                  sha256Hex((*stored)[i].settingsJson + "\n" + (*stored)[i].reportJson).substr(0, 12);
    c.resultNumber = static_cast<int>(i + 1);
    c.path = path;
    c.fileSha256 = f.fileSha256;
    c.imuSerial = info.imuSerial;
    c.imuModel = info.imuModel;
    c.lot = info.lot;
    c.benchId = info.benchId;
    c.operatorName = info.operatorName;
    c.sessionCreatedUtc = info.createdUtc;
    c.resultCreatedUtc = rec.createdUtc;
    c.meanTemperatureC = temperature;
    c.runComplete = r.complete();
    // The session's result: the newest usable one; when none can be read,
    // the newest row (no verdict, its reason): the session still counts.
    c.shown = newest ? rec.id == newest->id : i + 1 == records.size();
    if (!rec.usable) {
      c.verdictReason = "the stored result cannot be read: " + rec.problem;
      f.results.push_back(std::move(c));
      continue;
    }
    c.constantsJson = constantsJsonOf(rec.constants);
    c.constantsHash = sha256Hex(c.constantsJson).substr(0, 16);
    c.softwareVersion = rec.softwareVersion;
    c.analysedBy = rec.analysedBy;
    if (auto settings = json::parse((*stored)[i].settingsJson, nullptr, false);
        settings.is_object() && settings.contains("audit"))
      c.auditJson = settings["audit"].dump();
    const session::ShownVerdict shown =
        session::judgeShown(&rec, nullptr, r.complete(), r.incompleteReason(), rec.imuDelayLimitMs);
    c.verdict = session::shownVerdictName(shown.verdict);
    c.verdictReason = join(shown.reasons, "; ");
    if (shown.verdict == session::ShownVerdictKind::kIncomplete && !shown.incompleteReason.empty())
      c.verdictReason = shown.incompleteReason + (c.verdictReason.empty() ? "" : "; " + c.verdictReason);
    c.limitMs = shown.limitMs;
    for (const auto& p : shown.points) {
      CatalogPoint cp;
      cp.index = p.index;
      if (p.index >= 0 && p.index < static_cast<int>(info.plan.points.size())) {
        const TestPoint& tp = info.plan.points[static_cast<std::size_t>(p.index)];
        cp.axis = axisName(tp.axis);
        cp.frequencyHz = tp.frequencyHz;
        cp.amplitudeDeg = tp.amplitudeDeg;
      }
      cp.verdict = session::shownVerdictName(p.verdict);
      if (p.vouched()) {
        cp.imuDelayMs = p.imuDelayMs;
        cp.imuDelayStdMs = p.imuDelayStdMs;
      } else {
        cp.refusal = p.refusal();
      }
      c.points.push_back(std::move(cp));
    }
    f.results.push_back(std::move(c));
  }
  return f;
}

Result<std::unique_ptr<Catalog>> Catalog::open(std::unique_ptr<CatalogDb> db) {
  auto version = db->query("SELECT value FROM catalog_info WHERE key = 'schema_version'");
  if (version && !version->empty()) {
    const long long v = integerOf((*version)[0][0], -1);
    if (v > kCatalogSchemaVersion)
      return invalidArgument(db->describe() + " is of catalog schema " + std::to_string(v) +
                             ", newer than this fogbench reads (" + std::to_string(kCatalogSchemaVersion) +
                             "); update fogbench");
    if (v < 1) return corruptData(db->describe() + " states no valid catalog schema; it is damaged");
  } else {
    // A new catalog: its tables and its schema version, in one transaction
    // (SQLite and PostgreSQL both roll DDL back).
    Transaction t(*db);
    FOG_RETURN_IF_ERROR(t.begun());
    FOG_RETURN_IF_ERROR(db->exec(kSchema));
    FOG_RETURN_IF_ERROR(db->exec("INSERT INTO catalog_info (key, value) VALUES ('format', 'fogbench-catalog') "
                                 "ON CONFLICT (key) DO NOTHING"));
    FOG_RETURN_IF_ERROR(db->exec("INSERT INTO catalog_info (key, value) VALUES ('schema_version', ?) "
                                 "ON CONFLICT (key) DO NOTHING",
                                 {std::to_string(kCatalogSchemaVersion)}));
    FOG_RETURN_IF_ERROR(t.commit());
  }
  return std::unique_ptr<Catalog>(new Catalog(std::move(db)));
}

Status Catalog::storeResult(const CatalogResult& r, bool pushed) {
  std::vector<Value> v = {r.resultKey,
                          r.sessionKey,
                          integerValue(r.resultNumber),
                          r.path,
                          r.fileSha256,
                          r.imuSerial,
                          r.imuModel,
                          r.lot,
                          r.benchId,
                          r.operatorName,
                          r.sessionCreatedUtc,
                          r.resultCreatedUtc,
                          numberValue(r.meanTemperatureC),
                          integerValue(r.runComplete ? 1 : 0),
                          r.verdict,
                          r.verdictReason,
                          numberValue(r.limitMs),
                          r.constantsHash,
                          r.constantsJson,
                          r.softwareVersion,
                          r.analysedBy,
                          r.auditJson,
                          integerValue(r.shown ? 1 : 0),
                          integerValue(pushed ? 1 : 0)};
  std::string sql = std::string("INSERT INTO result (") + kResultColumns + ") VALUES (";
  for (std::size_t i = 0; i < v.size(); ++i) sql += i ? ", ?" : "?";
  sql += ") ON CONFLICT (result_key) DO UPDATE SET ";
  std::string cols = kResultColumns;
  bool first = true;
  for (std::size_t at = 0; at < cols.size();) {
    std::size_t comma = cols.find(", ", at);
    const std::string col = cols.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    at = comma == std::string::npos ? cols.size() : comma + 2;
    if (col == "result_key") continue;
    sql += (first ? "" : ", ") + col + " = excluded." + col;
    first = false;
  }
  FOG_RETURN_IF_ERROR(db_->exec(sql, v));
  FOG_RETURN_IF_ERROR(db_->exec("DELETE FROM result_point WHERE result_key = ?", {r.resultKey}));
  for (const auto& p : r.points)
    FOG_RETURN_IF_ERROR(db_->exec(
        "INSERT INTO result_point (result_key, point_index, axis, frequency_hz, amplitude_deg, verdict, "
        "imu_delay_ms, imu_delay_std_ms, refusal) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {r.resultKey, integerValue(p.index), p.axis, numberValue(p.frequencyHz), numberValue(p.amplitudeDeg),
         p.verdict, p.vouched() ? numberValue(p.imuDelayMs) : Value{},
         p.vouched() ? numberValue(p.imuDelayStdMs) : Value{}, p.refusal}));
  return Status::ok();
}

Status Catalog::store(const IndexedFile& file) {
  Transaction t(*db_);
  FOG_RETURN_IF_ERROR(t.begun());
  FOG_RETURN_IF_ERROR(storeRows(file));
  return t.commit();
}

Status Catalog::storeRows(const IndexedFile& file) {
  FOG_RETURN_IF_ERROR(db_->exec(
      "DELETE FROM result_point WHERE result_key IN (SELECT result_key FROM result WHERE path = ?)", {file.path}));
  FOG_RETURN_IF_ERROR(db_->exec("DELETE FROM result WHERE path = ?", {file.path}));
  for (const auto& r : file.results) FOG_RETURN_IF_ERROR(storeResult(r, false));
  FOG_RETURN_IF_ERROR(db_->exec(
      "INSERT INTO indexed_file (path, size_bytes, mtime_ns, session_key, file_sha256, indexed_utc, refusal) "
      "VALUES (?, ?, ?, ?, ?, ?, ?) ON CONFLICT (path) DO UPDATE SET size_bytes = excluded.size_bytes, "
      "mtime_ns = excluded.mtime_ns, session_key = excluded.session_key, file_sha256 = excluded.file_sha256, "
      "indexed_utc = excluded.indexed_utc, refusal = excluded.refusal",
      // A refused file is read again next time (-1 never matches): what
      // refused it may have been passing (a lock, a read error, a recording).
      {file.path, integerValue(file.sizeBytes), integerValue(file.refusal.empty() ? file.mtimeNs : -1),
       file.sessionKey.empty() ? Value{} : Value{file.sessionKey},
       file.fileSha256.empty() ? Value{} : Value{file.fileSha256}, nowUtc(), file.refusal}));
  return Status::ok();
}

Result<IndexReport> Catalog::index(const std::vector<std::string>& paths,
                                   const std::function<void(int, int)>& progress) {
  IndexReport report;
  std::vector<std::string> files;
  for (const auto& p : paths) collect(p, files, report.refusals);
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  report.filesFound = static_cast<int>(files.size());
  report.refused = static_cast<int>(report.refusals.size());

  // What was indexed before, in one query: an unchanged file is one stat().
  FOG_ASSIGN_OR_RETURN(auto known, db_->query("SELECT path, size_bytes, mtime_ns FROM indexed_file"));
  std::map<std::string, std::pair<long long, long long>> seen;
  for (const auto& row : known) seen[textOf(row[0])] = {integerOf(row[1], -1), integerOf(row[2], -1)};

  // Changed files are read side by side (reading is most of the work: the
  // SHA-256 and the checks of every byte) and stored in order, a batch per
  // transaction.
  std::vector<std::string> changed;
  for (const auto& path : files) {
    std::int64_t size = 0, mtime = 0;
    auto it = seen.find(path);
    if (it != seen.end() && statFile(path, size, mtime) && it->second.first == size && it->second.second == mtime) {
      ++report.unchanged;
    } else {
      changed.push_back(path);
    }
  }
  if (progress && report.unchanged > 0) progress(report.unchanged, static_cast<int>(files.size()));
  const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
  const std::size_t batch = 8 * static_cast<std::size_t>(threads);
  for (std::size_t from = 0; from < changed.size(); from += batch) {
    const std::size_t n = std::min(batch, changed.size() - from);
    std::vector<IndexedFile> read(n);
    parallelFor(n, threads, [&](std::size_t i) { read[i] = describeSessionFile(changed[from + i]); });
    Transaction t(*db_);
    FOG_RETURN_IF_ERROR(t.begun());
    for (const auto& f : read) {
      FOG_RETURN_IF_ERROR(storeRows(f));
      if (f.refusal.empty()) {
        ++report.indexed;
        report.resultsStored += static_cast<int>(f.results.size());
      } else {
        ++report.refused;
        report.refusals.emplace_back(f.path, f.refusal);
      }
    }
    FOG_RETURN_IF_ERROR(t.commit());
    if (progress) progress(report.unchanged + static_cast<int>(from + n), static_cast<int>(files.size()));
  }
  return report;
}

Result<std::vector<CatalogResult>> Catalog::results(const std::string& serial, const std::string& lot, bool shownOnly) {
  std::string where = " WHERE 1 = 1";
  std::vector<Value> params;
  if (!serial.empty()) {
    where += " AND imu_serial = ?";
    params.emplace_back(serial);
  }
  if (!lot.empty()) {
    where += " AND lot = ?";
    params.emplace_back(lot);
  }
  if (shownOnly) where += " AND shown = 1";
  FOG_ASSIGN_OR_RETURN(auto rows,
                       db_->query(std::string("SELECT ") + kResultColumns + " FROM result" + where, params));
  std::vector<CatalogResult> out;
  std::map<std::string, std::size_t> byKey;
  for (const auto& row : rows) {
    CatalogResult r;
    std::size_t i = 0;
    r.resultKey = textOf(row[i++]);
    r.sessionKey = textOf(row[i++]);
    r.resultNumber = static_cast<int>(integerOf(row[i++]));
    r.path = textOf(row[i++]);
    r.fileSha256 = textOf(row[i++]);
    r.imuSerial = textOf(row[i++]);
    r.imuModel = textOf(row[i++]);
    r.lot = textOf(row[i++]);
    r.benchId = textOf(row[i++]);
    r.operatorName = textOf(row[i++]);
    r.sessionCreatedUtc = textOf(row[i++]);
    r.resultCreatedUtc = textOf(row[i++]);
    r.meanTemperatureC = numberOf(row[i++]);
    r.runComplete = integerOf(row[i++]) != 0;
    r.verdict = textOf(row[i++]);
    r.verdictReason = textOf(row[i++]);
    r.limitMs = numberOf(row[i++]);
    r.constantsHash = textOf(row[i++]);
    r.constantsJson = textOf(row[i++]);
    r.softwareVersion = textOf(row[i++]);
    r.analysedBy = textOf(row[i++]);
    r.auditJson = textOf(row[i++]);
    r.shown = integerOf(row[i++]) != 0;
    byKey[r.resultKey] = out.size();
    out.push_back(std::move(r));
  }
  FOG_ASSIGN_OR_RETURN(auto points,
                       db_->query("SELECT result_key, point_index, axis, frequency_hz, amplitude_deg, verdict, "
                                  "imu_delay_ms, imu_delay_std_ms, refusal FROM result_point WHERE result_key IN "
                                  "(SELECT result_key FROM result" +
                                      where + ") ORDER BY result_key, point_index",
                                  params));
  for (const auto& row : points) {
    auto it = byKey.find(textOf(row[0]));
    if (it == byKey.end()) continue;
    CatalogPoint p;
    p.index = static_cast<int>(integerOf(row[1]));
    p.axis = textOf(row[2]);
    p.frequencyHz = numberOf(row[3]);
    p.amplitudeDeg = numberOf(row[4]);
    p.verdict = textOf(row[5]);
    p.imuDelayMs = numberOf(row[6]);
    p.imuDelayStdMs = numberOf(row[7]);
    p.refusal = textOf(row[8]);
    out[it->second].points.push_back(std::move(p));
  }
  // Ordered here, by bytes, as on every back end (PostgreSQL would order
  // text by its locale): oldest session first, then by result number.
  std::stable_sort(out.begin(), out.end(), [](const CatalogResult& a, const CatalogResult& b) {
    return std::tie(a.sessionCreatedUtc, a.sessionKey, a.resultNumber) <
           std::tie(b.sessionCreatedUtc, b.sessionKey, b.resultNumber);
  });
  return out;
}

Result<std::vector<std::pair<std::string, std::string>>> Catalog::refusals() {
  FOG_ASSIGN_OR_RETURN(auto rows, db_->query("SELECT path, refusal FROM indexed_file WHERE refusal <> ''"));
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& row : rows) out.emplace_back(textOf(row[0]), textOf(row[1]));
  // Sorted here: SQLite orders text by bytes, PostgreSQL by its locale.
  std::sort(out.begin(), out.end());
  return out;
}

Result<PushReport> Catalog::pushTo(Catalog& remote) {
  PushReport report;
  FOG_ASSIGN_OR_RETURN(auto counts, db_->query("SELECT count(*) FROM result WHERE pushed = 1"));
  report.alreadyPushed = counts.empty() ? 0 : static_cast<int>(integerOf(counts[0][0]));
  FOG_ASSIGN_OR_RETURN(auto pending, db_->query("SELECT result_key FROM result WHERE pushed = 0"));
  if (pending.empty()) return report;
  FOG_ASSIGN_OR_RETURN(auto all, results("", "", false));
  std::set<std::string> wanted;
  for (const auto& row : pending) wanted.insert(textOf(row[0]));
  // One transaction on the server: a push cut off midway leaves nothing
  // half-written there, and the rows stay pending here.
  {
    Transaction t(remote.db());
    FOG_RETURN_IF_ERROR(t.begun());
    for (const auto& r : all)
      if (wanted.count(r.resultKey)) FOG_RETURN_IF_ERROR(remote.storeResult(r, true));
    FOG_RETURN_IF_ERROR(t.commit());
  }
  // Then marked here. A stop between the two only sends them again next
  // time, which updates the same rows.
  Transaction t(*db_);
  FOG_RETURN_IF_ERROR(t.begun());
  for (const auto& key : wanted) {
    FOG_RETURN_IF_ERROR(db_->exec("UPDATE result SET pushed = 1 WHERE result_key = ?", {key}));
    ++report.pushed;
  }
  FOG_RETURN_IF_ERROR(t.commit());
  return report;
}

Result<int> Catalog::pendingCount() {
  FOG_ASSIGN_OR_RETURN(auto rows, db_->query("SELECT count(*) FROM result WHERE pushed = 0"));
  return rows.empty() ? 0 : static_cast<int>(integerOf(rows[0][0]));
}

Result<SyncReport> pushPending(Catalog& local, const std::string& sharedTarget) {
  SyncReport r;
  r.shared = describeTarget(sharedTarget);
  auto problem = [&](const Status& s) -> Result<SyncReport> {
    r.problem = s.message();
    FOG_ASSIGN_OR_RETURN(r.pending, local.pendingCount());
    return r;
  };
  auto db = CatalogDb::open(sharedTarget);
  if (!db) return problem(db.status());
  auto shared = Catalog::open(std::move(*db));
  if (!shared) return problem(shared.status());
  r.shared = (*shared)->describe();
  auto pushed = local.pushTo(**shared);
  if (!pushed) return problem(pushed.status());
  r.reached = true;
  r.push = *pushed;
  FOG_ASSIGN_OR_RETURN(r.pending, local.pendingCount());
  return r;
}

std::vector<UnitSummary> summariseUnits(const std::vector<CatalogResult>& results) {
  std::map<std::string, UnitSummary> units;
  for (const auto& r : results) {
    UnitSummary& u = units[r.imuSerial];
    u.serial = r.imuSerial;
    if (!r.imuModel.empty()) u.model = r.imuModel;
    if (!r.lot.empty() && std::find(u.lots.begin(), u.lots.end(), r.lot) == u.lots.end()) u.lots.push_back(r.lot);
    if (!r.benchId.empty() && std::find(u.benches.begin(), u.benches.end(), r.benchId) == u.benches.end())
      u.benches.push_back(r.benchId);
    ++u.results;
    if (r.shown) {
      ++u.sessions;
      if (r.sessionCreatedUtc >= u.latestUtc) {
        u.latestUtc = r.sessionCreatedUtc;
        u.latestVerdict = r.verdict;
      }
    }
  }
  std::vector<UnitSummary> out;
  for (auto& [serial, u] : units) out.push_back(std::move(u));
  return out;
}

Result<LotStatistics> lotStatistics(const std::string& lot, const std::vector<CatalogResult>& results,
                                    double limitMs) {
  LotStatistics s;
  s.lot = lot;
  // Each unit's first and latest session (by when it was recorded).
  std::map<std::string, std::pair<const CatalogResult*, const CatalogResult*>> firstLatest;
  std::set<double> limits;
  // One shown result per session: two copies of a session analysed apart
  // each show one; the later analysis counts, the other is superseded.
  std::map<std::string, const CatalogResult*> shownOf;
  for (const auto& r : results)
    if (r.shown) {
      const CatalogResult*& best = shownOf[r.sessionKey];
      if (!best || r.resultCreatedUtc > best->resultCreatedUtc) best = &r;
    }
  auto counts = [&](const CatalogResult& r) { return r.shown && shownOf[r.sessionKey] == &r; };
  for (const auto& r : results) {
    if (!counts(r)) {
      ++s.superseded;
      continue;
    }
    ++s.sessions;
    if (r.verdict == "pass") ++s.pass;
    else if (r.verdict == "fail") ++s.fail;
    else if (r.verdict == "invalid") ++s.invalid;
    else if (r.verdict == "incomplete") ++s.incomplete;
    else ++s.noVerdict;
    if (std::isfinite(r.limitMs)) limits.insert(r.limitMs);
    auto& fl = firstLatest[r.imuSerial];
    if (!fl.first || r.sessionCreatedUtc < fl.first->sessionCreatedUtc) fl.first = &r;
    if (!fl.second || r.sessionCreatedUtc >= fl.second->sessionCreatedUtc) fl.second = &r;
  }
  s.units = static_cast<int>(firstLatest.size());
  if (s.units > 0) {
    int passedLatest = 0, passedFirst = 0;
    for (const auto& [serial, fl] : firstLatest) {
      passedFirst += fl.first->verdict == "pass" ? 1 : 0;
      passedLatest += fl.second->verdict == "pass" ? 1 : 0;
    }
    s.passRate = static_cast<double>(passedLatest) / s.units;
    s.firstPassYield = static_cast<double>(passedFirst) / s.units;
  }
  if (std::isfinite(limitMs)) {
    s.limitMs = limitMs;
    s.limitSource = "given";
  } else if (limits.size() == 1) {
    s.limitMs = *limits.begin();
    s.limitSource = "stored";
  } else if (limits.size() > 1) {
    std::string list;
    for (double l : limits) {
      char b[32];
      std::snprintf(b, sizeof b, "%.6g ms", l);
      list += (list.empty() ? "" : ", ") + std::string(b);
    }
    return invalidArgument("the results of lot '" + lot + "' were judged against different limits (" + list +
                           "); give the limit Cpk is computed against with --limit-ms");
  }
  // The delays: vouched points (PASS or FAIL) of results that show PASS or
  // FAIL. An INVALID or INCOMPLETE result is counted above, never averaged.
  std::map<std::string, std::vector<double>> byAxis;
  for (const auto& r : results) {
    if (!counts(r) || (r.verdict != "pass" && r.verdict != "fail")) continue;
    for (const auto& p : r.points)
      if (p.vouched() && std::isfinite(p.imuDelayMs)) {
        byAxis[p.axis].push_back(p.imuDelayMs);
        byAxis["all"].push_back(p.imuDelayMs);
      }
  }
  for (const std::string axis : {"x", "y", "z", "all"}) {
    auto it = byAxis.find(axis);
    if (it == byAxis.end()) continue;
    if (axis == "all" && s.delay.size() == 1) continue;  // one axis: "all" says the same again
    DelayStatistics d;
    d.axis = axis;
    d.n = static_cast<int>(it->second.size());
    double sum = 0.0;
    for (double v : it->second) sum += v;
    d.meanMs = sum / d.n;
    if (d.n >= 2) {
      double ss = 0.0;
      for (double v : it->second) ss += (v - d.meanMs) * (v - d.meanMs);
      d.stdMs = std::sqrt(ss / (d.n - 1));
      // Not stated for a spread below a picosecond: the delays are the same
      // (rounding apart), and a Cpk of 1e14 would say nothing true.
      if (std::isfinite(s.limitMs) && d.stdMs > kMinSpreadForCpkMs) d.cpk = (s.limitMs - d.meanMs) / (3.0 * d.stdMs);
    }
    s.delay.push_back(d);
  }
  return s;
}

std::string analysedByText(const CatalogResult& r) {
  if (r.auditJson.empty()) return r.analysedBy.empty() ? "not recorded" : r.analysedBy;
  const json a = json::parse(r.auditJson, nullptr, false);
  if (!a.is_object()) return r.analysedBy;
  const std::string who = a.value("who", std::string());
  const std::string tool = a.value("tool", r.analysedBy);
  return who.empty() ? tool : who + " (" + tool + ")";
}

std::string resultsCsv(const std::vector<CatalogResult>& results) {
  auto text = [](const std::string& t) { return session::csvTextField(t); };
  auto num = [](double v) { return textOf(numberValue(v)); };
  std::string out =
      "imu_serial,imu_model,lot,bench_id,operator,session_created_utc,result,result_created_utc,shown,"
      "mean_temperature_c,verdict,limit_ms,point,axis,frequency_hz,point_verdict,imu_delay_ms,"
      "imu_delay_std_ms,refusal,constants_hash,software_version,analysed_by,path,file_sha256\n";
  for (const auto& r : results) {
    const std::string head = text(r.imuSerial) + "," + text(r.imuModel) + "," + text(r.lot) + "," + text(r.benchId) +
                             "," + text(r.operatorName) + "," + text(r.sessionCreatedUtc) + "," +
                             std::to_string(r.resultNumber) + "," + text(r.resultCreatedUtc) + "," +
                             (r.shown ? "1" : "0") + "," + num(r.meanTemperatureC) + "," + text(r.verdict) + "," +
                             num(r.limitMs);
    const std::string tail = "," + text(r.constantsHash) + "," + text(r.softwareVersion) + "," +
                             text(analysedByText(r)) + "," + text(r.path) + "," + text(r.fileSha256);
    if (r.points.empty()) out += head + ",,,,,,,," + text(r.verdictReason) + tail + "\n";
    for (const auto& p : r.points)
      out += head + "," + std::to_string(p.index) + "," + text(p.axis) + "," + num(p.frequencyHz) + "," +
             text(p.verdict) + "," + (p.vouched() ? num(p.imuDelayMs) : "") + "," +
             (p.vouched() ? num(p.imuDelayStdMs) : "") + "," + text(p.refusal) + tail + "\n";
  }
  return out;
}

TemperatureSlope delayAgainstTemperature(const std::vector<CatalogResult>& results) {
  std::vector<std::pair<double, double>> xy;
  for (const auto& r : results)
    if (r.shown && (r.verdict == "pass" || r.verdict == "fail") && std::isfinite(r.meanTemperatureC))
      for (const auto& p : r.points)
        if (p.vouched() && std::isfinite(p.imuDelayMs)) xy.emplace_back(r.meanTemperatureC, p.imuDelayMs);
  TemperatureSlope s;
  s.n = static_cast<int>(xy.size());
  if (s.n < 3) return s;
  double mx = 0, my = 0;
  for (auto [x, y] : xy) mx += x, my += y;
  mx /= s.n;
  my /= s.n;
  double sxx = 0, sxy = 0;
  for (auto [x, y] : xy) sxx += (x - mx) * (x - mx), sxy += (x - mx) * (y - my);
  if (!(sxx > 1e-12)) return s;
  s.msPerC = sxy / sxx;
  double rss = 0;
  for (auto [x, y] : xy) rss += std::pow(y - my - s.msPerC * (x - mx), 2);
  s.stdMsPerC = std::sqrt(rss / (s.n - 2) / sxx);
  return s;
}

}  // namespace fog::catalog
