#pragma once
// The lab's record across sessions (issue 42, docs/catalog.md): one row per
// stored result of every session indexed — unit, lot, bench, operator, dates,
// mean IMU temperature, the verdict shown with its reason and limit, per test
// point the IMU delay and its σ *only when vouched for* (shown_verdict.h), the
// constants and their hash, the software, who analysed it (the audit), the
// session file's path and SHA-256, the result's number, shown or superseded.
//
// Contracts:
//  - One truth: every row is what the session's stored result says, read
//    through readStoredResult and judgeShown; the catalog never re-analyses.
//    A refused point's delay is stored as NULL with its refusal.
//  - Incremental: a file whose size and modification time are those of its
//    last indexing is not reopened. A damaged file is one refusal row in
//    `indexed_file`, never a stop.
//  - The same schema and statements on SQLite and PostgreSQL (catalog_db.h).
//    A result's key is its session's key and the result's row id, so storing
//    or pushing the same result twice updates one row, never adds another.
// Qt-free; errors are Status values.

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/catalog/catalog_db.h"
#include "core/common/bench_constants.h"
#include "core/common/status.h"

namespace fog::catalog {

inline constexpr const char* kDefaultCatalogFileName = "fogbench-catalog.sqlite";
inline constexpr int kCatalogSchemaVersion = 1;
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct CatalogPoint {
  int index = 0;  // test point index (0-based)
  std::string axis;  // "x", "y", "z"
  double frequencyHz = kNaN, amplitudeDeg = kNaN;
  std::string verdict;  // "pass", "fail", "invalid", "incomplete", "" (shown_verdict.h's names)
  // NaN unless the point is vouched for (PASS or FAIL); then `refusal` is "".
  double imuDelayMs = kNaN, imuDelayStdMs = kNaN;
  std::string refusal;
  bool vouched() const { return refusal.empty() && (verdict == "pass" || verdict == "fail"); }
};

struct CatalogResult {
  std::string resultKey;   // sessionKey + ":" + stored row id
  std::string sessionKey;  // see sessionKeyOf
  int resultNumber = 0;    // 1-based, as `sessions` and `report` number them
  std::string path, fileSha256;
  std::string imuSerial, imuModel, lot, benchId, operatorName;
  std::string sessionCreatedUtc, resultCreatedUtc;
  double meanTemperatureC = kNaN;  // over the session's IMU frames; NaN: none stated
  bool runComplete = true;
  std::string verdict;        // as shown: "pass", "fail", "invalid", "incomplete", ""
  std::string verdictReason;  // the shown result's reasons, "; "-joined
  double limitMs = kNaN;
  std::string constantsHash;  // first 16 hex digits of the SHA-256 of `constantsJson`
  std::string constantsJson;  // the bench constants the result was produced with
  std::string softwareVersion, analysedBy;
  std::string auditJson;  // the stored settings' "audit" object, "" when not recorded
  bool shown = false;     // the session's shown result; false: superseded by a later one
  std::vector<CatalogPoint> points;
};

// What one file gives the catalog.
struct IndexedFile {
  std::string path;
  std::int64_t sizeBytes = 0, mtimeNs = 0;
  std::string refusal;  // non-empty: unreadable or damaged, says why; no results then
  std::string sessionKey, fileSha256;
  std::vector<CatalogResult> results;
};

// Reads a session file into catalog rows (never fails: a file that cannot be
// read, or whose raw stream or metadata fails its checks, gives a refusal).
IndexedFile describeSessionFile(const std::string& path);

// The canonical JSON of bench constants (fixed keys, round-trip exact numbers)
// and its hash, as the catalog stores them.
std::string constantsJsonOf(const BenchConstants& constants);

struct IndexReport {
  int filesFound = 0;   // session files (and *.fbs) under the folders
  int unchanged = 0;    // same size and time as last indexed: not reopened
  int indexed = 0;      // (re)read and stored
  int refused = 0;      // unreadable or damaged: one refusal row each
  int resultsStored = 0;
  std::vector<std::pair<std::string, std::string>> refusals;  // path, why (this run's)
};

struct PushReport {
  int pushed = 0;          // results sent (inserted or updated on the server)
  int alreadyPushed = 0;   // unchanged since their last push: not sent again
};

class Catalog {
 public:
  // Opens the catalog, creating its tables when new; a catalog of a newer
  // schema is refused ("update fogbench").
  static Result<std::unique_ptr<Catalog>> open(std::unique_ptr<CatalogDb> db);

  // Indexes every session under each folder (recursively; a file path is
  // taken as given). `progress(done, total)` is called after each file.
  Result<IndexReport> index(const std::vector<std::string>& paths,
                            const std::function<void(int, int)>& progress = {});
  // Stores one file's rows (replacing what the catalog held for that path).
  Status store(const IndexedFile& file);

  // Results, oldest session first, then by result number. Empty filters
  // match all; `shownOnly` drops superseded results.
  Result<std::vector<CatalogResult>> results(const std::string& serial, const std::string& lot, bool shownOnly);
  // Files the catalog refused, with why.
  Result<std::vector<std::pair<std::string, std::string>>> refusals();

  // Sends every result not pushed since it last changed to `remote` (upsert:
  // a repeated push adds nothing), then marks them pushed here.
  Result<PushReport> pushTo(Catalog& remote);
  // Results not on a shared catalog yet, or changed since they were sent.
  Result<int> pendingCount();

  CatalogDb& db() { return *db_; }
  std::string describe() const { return db_->describe(); }

 private:
  explicit Catalog(std::unique_ptr<CatalogDb> db) : db_(std::move(db)) {}
  Status storeResult(const CatalogResult& r, bool pushed);
  Status storeRows(const IndexedFile& file);  // inside the caller's transaction
  std::unique_ptr<CatalogDb> db_;
};

// A bench's own catalog and the lab's shared one (docs/catalog.md, "A
// bench offline"): after each index the bench's catalog sends what is
// pending. A shared catalog that does not answer, or goes away during the
// push, is no error: the report says so and the rows stay pending for the
// next push, which sends them once.
struct SyncReport {
  std::string shared;    // the shared catalog's describe(), or its address without a password
  bool reached = false;  // it answered and took every pending row
  std::string problem;   // why not (libpq's words, no password)
  PushReport push;
  int pending = 0;       // results still to send after this
};
// Opens `sharedTarget` (a postgresql:// URI, or a SQLite file) and pushes
// `local`'s pending results to it. An error only when `local` cannot be read.
Result<SyncReport> pushPending(Catalog& local, const std::string& sharedTarget);

// ---- Views over results (computed here, the same for every back end).

struct UnitSummary {
  std::string serial, model;
  std::vector<std::string> lots, benches;
  int sessions = 0;  // sessions with a shown result
  int results = 0;   // every result, superseded included
  std::string latestVerdict, latestUtc;  // the newest session's shown result
};
// One per serial (sorted); results with no serial are grouped under "".
std::vector<UnitSummary> summariseUnits(const std::vector<CatalogResult>& results);

// Statistics of a lot's shown results (docs/catalog.md, "Lot statistics").
// Below this spread of the units' delays (1 ps) Cpk is not stated.
inline constexpr double kMinSpreadForCpkMs = 1e-9;

struct DelayStatistics {
  std::string axis;  // "x", "y", "z" or "all"
  int n = 0;         // vouched points
  double meanMs = kNaN, stdMs = kNaN;  // sample mean and standard deviation (n − 1)
  double cpk = kNaN;  // (limit − mean) / (3 s): one-sided, upper limit only; NaN when n < 2 or s < 1 ps
};
struct LotStatistics {
  std::string lot;
  int units = 0, sessions = 0;
  int pass = 0, fail = 0, invalid = 0, incomplete = 0, noVerdict = 0;  // sessions by shown verdict
  int superseded = 0;         // earlier results of the same sessions (re-analysed)
  double passRate = kNaN;     // units whose latest session shows PASS / units
  double firstPassYield = kNaN;  // units whose first session shows PASS / units
  double limitMs = kNaN;      // the limit Cpk is computed against
  std::string limitSource;    // "stored" (all results share it) or "given"
  std::vector<DelayStatistics> delay;  // per axis present, then "all"
};
// `limitMs` NaN: the results' common stored limit; results judged against
// different limits without a given one is an error saying so.
Result<LotStatistics> lotStatistics(const std::string& lot, const std::vector<CatalogResult>& shownResults,
                                    double limitMs);

// ---- Words the CLI and the GUI share (the GUI shows them through its
// translation layer, ui/core_text.h), so that both say the same.

// Who analysed a result, from its audit: "who (tool)", the tool, or
// "not recorded".
std::string analysedByText(const CatalogResult& r);

// Results as CSV (`catalog unit --csv`): a header, then one row per result
// and test point (a result without points: one row, its reason in
// `refusal`); a refused point has empty delay cells and its refusal. Text
// fields go through session::csvTextField (one starting with = + - @ is
// prefixed with a single quote, so a spreadsheet never runs it); numbers
// are written as numbers, a negative one included.
std::string resultsCsv(const std::vector<CatalogResult>& results);

// The IMU delay's least-squares slope against the mean IMU temperature over
// the vouched points of a unit's shown results, with the slope's standard
// error; NaN when fewer than three points or a single temperature.
struct TemperatureSlope {
  int n = 0;  // vouched points of shown results with a temperature
  double msPerC = kNaN, stdMsPerC = kNaN;
};
TemperatureSlope delayAgainstTemperature(const std::vector<CatalogResult>& results);

// The lot statistics' definitions (`catalog lot --json`, the GUI's tooltip).
inline constexpr const char* kPassRateDefinition = "units whose latest session's shown result is PASS, over units";
inline constexpr const char* kFirstPassYieldDefinition = "units whose first session's shown result is PASS, over units";
inline constexpr const char* kLotDelayDefinition =
    "over the vouched test points (PASS or FAIL) of shown PASS or FAIL results; INVALID and INCOMPLETE results are "
    "counted, never averaged";
inline constexpr const char* kCpkDefinition = "(limit - mean) / (3 s), one-sided: the IMU delay has an upper limit only";

}  // namespace fog::catalog
