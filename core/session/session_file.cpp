#include "core/session/session_file.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <bit>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <utility>

#include "core/common/file_read.h"
#include "core/common/sha256.h"
#include "core/common/text.h"
#include "core/common/version.h"
#include "core/protocol/recording_builder.h"

namespace fog::session {

namespace {

namespace fs = std::filesystem;

// Schema 1. docs/sessions.md documents every column; keep the two in step.
// Changing anything here means a new kSchemaVersion and a migration below.
constexpr const char* kSchemaV1 = R"sql(
CREATE TABLE session (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  operator TEXT NOT NULL,
  imu_model TEXT NOT NULL,
  imu_serial TEXT NOT NULL,
  source TEXT NOT NULL,
  software_version TEXT NOT NULL,
  created_utc TEXT NOT NULL,
  notes TEXT NOT NULL,
  table_read_delay_ms REAL NOT NULL,
  table_read_delay_std_ms REAL NOT NULL,
  board_delay_ms REAL NOT NULL,
  board_delay_std_ms REAL NOT NULL,
  latitude_deg REAL NOT NULL,
  pulse_equivalent_deg REAL NOT NULL,
  counter_hz REAL NOT NULL,
  counter_bits INTEGER NOT NULL,
  test_plan_json TEXT NOT NULL,
  state TEXT NOT NULL,
  incomplete_reason TEXT NOT NULL DEFAULT '',
  finished_utc TEXT NOT NULL DEFAULT ''
);
CREATE TABLE raw_chunk (
  seq INTEGER PRIMARY KEY,
  byte_offset INTEGER NOT NULL,
  data BLOB NOT NULL,
  data_fnv1a INTEGER NOT NULL,
  committed_utc TEXT NOT NULL
);
CREATE TABLE decoded (
  id INTEGER PRIMARY KEY CHECK (id = 1),
  raw_bytes INTEGER NOT NULL,
  counter_hz REAL NOT NULL,
  counter_bits INTEGER NOT NULL,
  pulse_equivalent_deg REAL NOT NULL,
  table_frames INTEGER NOT NULL,
  imu_frames INTEGER NOT NULL,
  status_frames INTEGER NOT NULL,
  checksum_failures INTEGER NOT NULL,
  bytes_skipped INTEGER NOT NULL,
  lost_frames INTEGER NOT NULL,
  duplicate_frames INTEGER NOT NULL,
  out_of_order_frames INTEGER NOT NULL,
  counter_wraps INTEGER NOT NULL
);
CREATE TABLE test_point (
  position INTEGER PRIMARY KEY,
  point_index INTEGER NOT NULL,
  axis TEXT NOT NULL,
  nominal_frequency_hz REAL NOT NULL,
  nominal_amplitude_deg REAL NOT NULL,
  table_samples INTEGER NOT NULL,
  imu_samples INTEGER NOT NULL
);
CREATE TABLE table_block (
  test_point INTEGER NOT NULL,
  block INTEGER NOT NULL,
  samples INTEGER NOT NULL,
  data BLOB NOT NULL,
  data_fnv1a INTEGER NOT NULL,
  PRIMARY KEY (test_point, block)
);
CREATE TABLE imu_block (
  test_point INTEGER NOT NULL,
  block INTEGER NOT NULL,
  samples INTEGER NOT NULL,
  data BLOB NOT NULL,
  data_fnv1a INTEGER NOT NULL,
  PRIMARY KEY (test_point, block)
);
CREATE TABLE result (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  created_utc TEXT NOT NULL,
  settings_json TEXT NOT NULL,
  report_json TEXT NOT NULL
);
)sql";

// Schema 2: checksums of the metadata row and of each stored result (SQLite
// checks its pages, not the values in them: one flipped bit in a bench
// constant would otherwise change every later analysis silently). NULL = not
// checked (a file migrated from schema 1 keeps its metadata unchecked).
constexpr const char* kSchemaV2Step = R"sql(
ALTER TABLE session ADD COLUMN metadata_fnv1a INTEGER;
ALTER TABLE result ADD COLUMN fnv1a INTEGER;
)sql";

// Schema 3: the table log of a table-driven run (commands to the table
// controller, its replies, its status changes, the plan runner's steps).
constexpr const char* kSchemaV3Step = R"sql(
CREATE TABLE table_log (
  seq INTEGER PRIMARY KEY,
  elapsed_s REAL NOT NULL,
  logged_utc TEXT NOT NULL,
  kind TEXT NOT NULL,
  text TEXT NOT NULL
);
)sql";

// Schema 4: the gyro signs of the bench constants (+1, or -1 for a gyro axis
// mounted the other way round; files of older schemas read +1: what every
// analysis of them used), and what an import applied to make the recording
// (the gyro rate convention and frame period, the swing windows cut) as
// JSON, '' for a recorded session (docs/sessions.md).
constexpr const char* kSchemaV4Step = R"sql(
ALTER TABLE session ADD COLUMN gyro_sign_x INTEGER NOT NULL DEFAULT 1;
ALTER TABLE session ADD COLUMN gyro_sign_y INTEGER NOT NULL DEFAULT 1;
ALTER TABLE session ADD COLUMN gyro_sign_z INTEGER NOT NULL DEFAULT 1;
ALTER TABLE session ADD COLUMN import_json TEXT NOT NULL DEFAULT '';
)sql";

// Schema 5: the IMU's frame at zero table angles as the bench constants
// state it (core/common/imu_frame.h text: "NED", "RFU:30"; '' = not stated,
// what files of older schemas read).
constexpr const char* kSchemaV5Step = R"sql(
ALTER TABLE session ADD COLUMN imu_frame TEXT NOT NULL DEFAULT '';
)sql";

// Schema 6: the unit's identity beyond its serial: the production lot it
// belongs to and the bench (station) that recorded it, what the catalog
// groups results by ('' = not stated, what files of older schemas read).
constexpr const char* kSchemaV6Step = R"sql(
ALTER TABLE session ADD COLUMN lot TEXT NOT NULL DEFAULT '';
ALTER TABLE session ADD COLUMN bench_id TEXT NOT NULL DEFAULT '';
)sql";

// Sample blocks: small enough to stay far below SQLite's 1 GB value limit
// whatever the test point's length, large enough that a block costs little.
constexpr std::size_t kSamplesPerBlock = 65536;
// Text fields: what a recorder accepts and what a reader loads (a longer
// value written by something else is cut, and says so).
constexpr std::size_t kMaxNotesBytes = 1 << 20;
constexpr std::size_t kMaxFieldBytes = 4096;
// Test point indices are 16-bit on the wire; 0xFFFF means "none".
constexpr std::int64_t kMaxTestPointIndex = 0xFFFF;
constexpr std::size_t kTableRecordBytes = 4 * 8;      // time_s, x, y, z (deg), float64 LE
constexpr std::size_t kImuRecordBytes = 5 * 8 + 4;    // time_s, dx, dy, dz (deg), temperature_c, lost_before u32
// A raw chunk is committed early once this large, so memory stays bounded
// when bytes arrive faster than real time (replay, benchmarks).
constexpr std::size_t kMaxPendingRaw = 1 << 20;
// Every connection waits for a lock rather than failing at once. Readers never
// block a WAL writer; the only other writer is addResult(), whose transaction
// is one small INSERT (milliseconds), so the recorder waits at most that long.
// The recorder's own timeout is generous: losing a recording to a lock is
// never acceptable.
constexpr int kRecorderBusyTimeoutMs = 30000;
constexpr int kReaderBusyTimeoutMs = 5000;
constexpr int kAddResultBusyTimeoutMs = 5000;
// finish() tries this long to make the file self-contained again; a reader
// that keeps the file open only leaves the -wal beside it a while longer.
constexpr int kFinishBusyTimeoutMs = 1000;

// --- little helpers -------------------------------------------------------

class Stmt {
 public:
  Stmt(sqlite3* db, const char* sql) { rc_ = sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr); }
  ~Stmt() { sqlite3_finalize(stmt_); }
  Stmt(const Stmt&) = delete;
  Stmt& operator=(const Stmt&) = delete;
  bool ok() const { return rc_ == SQLITE_OK && stmt_ != nullptr; }
  sqlite3_stmt* get() const { return stmt_; }
  void bind(int i, double v) { sqlite3_bind_double(stmt_, i, v); }
  void bind(int i, std::int64_t v) { sqlite3_bind_int64(stmt_, i, v); }
  void bind(int i, const std::string& v) {
    sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
  }
  void bindBlob(int i, const void* data, std::size_t size) {
    // A zero-length blob must still be a blob, not NULL (NOT NULL columns).
    sqlite3_bind_blob64(stmt_, i, size ? data : "", static_cast<sqlite3_uint64>(size), SQLITE_STATIC);
  }
  int step() { return sqlite3_step(stmt_); }
  std::string text(int i) const {
    const auto* p = sqlite3_column_text(stmt_, i);
    return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(sqlite3_column_bytes(stmt_, i)))
             : std::string();
  }
  double real(int i) const { return sqlite3_column_double(stmt_, i); }
  std::int64_t integer(int i) const { return sqlite3_column_int64(stmt_, i); }
  std::span<const std::uint8_t> blob(int i) const {
    const void* p = sqlite3_column_blob(stmt_, i);
    const int n = sqlite3_column_bytes(stmt_, i);
    if (!p || n <= 0) return {};
    return {static_cast<const std::uint8_t*>(p), static_cast<std::size_t>(n)};
  }

 private:
  sqlite3_stmt* stmt_ = nullptr;
  int rc_ = SQLITE_ERROR;
};

bool exec(sqlite3* db, const char* sql) { return sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK; }

std::string sqliteMessage(sqlite3* db) { return db ? sqlite3_errmsg(db) : "out of memory"; }

Result<std::int64_t> pragmaInt(sqlite3* db, const char* sql) {
  Stmt s(db, sql);
  if (!s.ok() || s.step() != SQLITE_ROW) return ioError(sqliteMessage(db));
  return s.integer(0);
}

void putDouble(std::uint8_t* at, double v) {
  auto bits = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) at[i] = static_cast<std::uint8_t>(bits >> (8 * i));
}
double getDouble(const std::uint8_t* at) {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(at[i]) << (8 * i);
  return std::bit_cast<double>(bits);
}
void putU32(std::uint8_t* at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint32_t getU32(const std::uint8_t* at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(at[i]) << (8 * i);
  return v;
}
// FNV-1a 64 of every stored blob: SQLite checks its page structure but not
// the bytes inside a blob, and a damaged raw stream must never pass as data.
std::int64_t fnv1a(std::span<const std::uint8_t> data) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::uint8_t b : data) h = (h ^ b) * 0x100000001b3ULL;
  return std::bit_cast<std::int64_t>(h);
}
std::int64_t fnv1a(const std::vector<std::uint8_t>& data) { return fnv1a(std::span<const std::uint8_t>(data)); }

// FNV-1a 64 continued over more bytes.
void fnv1aAdd(std::uint64_t& h, const void* data, std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
}

// Every metadata column in a fixed order, as SQLite stores it (type and
// bytes): what metadata_fnv1a covers.
constexpr const char* kMetadataColumns =
    "operator, imu_model, imu_serial, source, software_version, created_utc, notes, table_read_delay_ms,"
    " table_read_delay_std_ms, board_delay_ms, board_delay_std_ms, latitude_deg, pulse_equivalent_deg, counter_hz,"
    " counter_bits, test_plan_json, state, incomplete_reason, finished_utc";
constexpr const char* kSchemaV4MetadataColumns = ", gyro_sign_x, gyro_sign_y, gyro_sign_z, import_json";
constexpr const char* kSchemaV5MetadataColumns = ", imu_frame";
constexpr const char* kSchemaV6MetadataColumns = ", lot, bench_id";

// Over the metadata columns the file's schema has.
Result<std::int64_t> metadataChecksum(sqlite3* db, int schemaVersion = kSchemaVersion) {
  const std::string columns = std::string(kMetadataColumns) + (schemaVersion >= 4 ? kSchemaV4MetadataColumns : "") +
                              (schemaVersion >= 5 ? kSchemaV5MetadataColumns : "") +
                              (schemaVersion >= 6 ? kSchemaV6MetadataColumns : "");
  Stmt s(db, ("SELECT " + columns + " FROM session WHERE id = 1").c_str());
  if (!s.ok() || s.step() != SQLITE_ROW) return ioError(sqliteMessage(db));
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const int n = sqlite3_column_count(s.get());
  for (int i = 0; i < n; ++i) {
    const auto type = static_cast<std::uint8_t>(sqlite3_column_type(s.get(), i));
    fnv1aAdd(h, &type, 1);
    std::uint8_t v[8];
    if (type == SQLITE_INTEGER) {
      putDouble(v, std::bit_cast<double>(s.integer(i)));
      fnv1aAdd(h, v, 8);
    } else if (type == SQLITE_FLOAT) {
      putDouble(v, s.real(i));
      fnv1aAdd(h, v, 8);
    } else if (type != SQLITE_NULL) {
      const std::string t = s.text(i);
      putDouble(v, std::bit_cast<double>(static_cast<std::uint64_t>(t.size())));
      fnv1aAdd(h, v, 8);
      fnv1aAdd(h, t.data(), t.size());
    }
  }
  return std::bit_cast<std::int64_t>(h);
}

// Stores the metadata row's checksum (inside the caller's transaction).
bool updateMetadataChecksum(sqlite3* db, int schemaVersion = kSchemaVersion) {
  auto sum = metadataChecksum(db, schemaVersion);
  if (!sum) return false;
  Stmt s(db, "UPDATE session SET metadata_fnv1a = ?1 WHERE id = 1");
  if (!s.ok()) return false;
  s.bind(1, *sum);
  return s.step() == SQLITE_DONE;
}

std::int64_t resultChecksum(const std::string& createdUtc, const std::string& settings, const std::string& report) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const std::string* t : {&createdUtc, &settings, &report}) {
    fnv1aAdd(h, t->data(), t->size());
    fnv1aAdd(h, "", 1);  // separator: the NUL byte
  }
  return std::bit_cast<std::int64_t>(h);
}

std::uint32_t bigEndian32(const std::uint8_t* at) {
  return (std::uint32_t{at[0]} << 24) | (std::uint32_t{at[1]} << 16) | (std::uint32_t{at[2]} << 8) | at[3];
}

// What the first 100 bytes (the SQLite header) say, read before SQLite sees
// the file so that each kind of wrong file gets its own clear message.
struct HeaderInfo {
  std::uint32_t applicationId = 0;
  int userVersion = 0;
  std::string truncated;  // non-empty: why the file is shorter than its header says
  // The file is shorter than its header says, but a -wal lies beside it: a
  // crash or a full disk during a checkpoint leaves exactly this, with every
  // missing page still in the -wal. SQLite decides (checkWalCoversTruncation).
  bool truncatedWithWal = false;
};

// A session whose SQLite header (first 100 bytes) is damaged still holds its
// schema as text in page 1 (sqlite_master); one whose whole first page is
// lost (zeroed: 4 KiB) still holds its session row, with the plan's JSON, in
// the pages after it. Such a file must never be taken for a raw
// sampling-board stream: a stream never holds this text, and decoding the
// database pages as a stream reads the stream's chunks in page order with
// the pages' own bytes between them (192 checksum failures and 1.1 MB
// skipped in a 20-s session; the delay came out right by luck of the order).
enum class SessionDamage { kNone, kHeader, kFirstPage };
constexpr std::size_t kSchemaSearchBytes = 64 * 1024;
SessionDamage sessionDamage(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(kSchemaSearchBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.find("CREATE TABLE raw_chunk") != std::string::npos &&
      head.find("CREATE TABLE session") != std::string::npos)
    return SessionDamage::kHeader;
  // Without the schema: a file of whole pages whose second page (at the
  // smallest page size a session uses, 4 KiB) is a table b-tree page, and
  // the session row's plan text. A plan file or a CSV is not made of pages.
  constexpr std::size_t kPage = 4096;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const bool pages = !ec && size >= 2 * kPage && size % kPage == 0 && head.size() > kPage &&
                     (head[kPage] == 0x0d || head[kPage] == 0x05);
  if (pages && head.find("\"rest_between_s\"") != std::string::npos &&
      head.find("\"points\"") != std::string::npos)
    return SessionDamage::kFirstPage;
  return SessionDamage::kNone;
}

std::string damagedSessionMessage(const std::string& path, SessionDamage damage) {
  if (damage == SessionDamage::kFirstPage)
    return "'" + path + "' is a fogbench session whose first page (the SQLite header and the list of its tables, "
           "4 KiB) is damaged; it is not analysed as a raw stream (the stream inside is cut into database pages). "
           "Restore it from a backup";
  return "'" + path + "' is a fogbench session whose SQLite header (its first 100 bytes) is damaged; it is not "
         "analysed as a raw stream. Restore it from a backup, or repair a copy: printf 'SQLite format 3\\0' | "
         "dd of=COPY.fbs conv=notrunc (when only the header's first bytes were hit, the copy opens again)";
}

// Errors only for a file that is missing, unreadable, empty or not SQLite.
Result<HeaderInfo> readHeader(const std::string& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status))
    return ioError("cannot open session '" + path + "': no such file; check the path");
  if (fs::is_directory(status)) return ioError("'" + path + "' is a folder, not a fogbench session file");
  // A FIFO would block the read below and a device never ends: only a
  // regular file can be a session (file_read.h words the refusal).
  if (!fs::is_regular_file(status)) return checkRegularFile(path, 0, "a fogbench session file");
  const auto size = fs::file_size(path, ec);
  if (ec) return ioError("cannot read '" + path + "': " + ec.message());
  if (size == 0)
    return corruptData("'" + path + "' is empty (0 bytes), not a fogbench session; it was never written");
  std::ifstream in(path, std::ios::binary);
  std::array<std::uint8_t, 100> h{};
  in.read(reinterpret_cast<char*>(h.data()), h.size());
  if (!in && in.gcount() == 0) return ioError("cannot read '" + path + "'; check its permissions");
  static constexpr char kMagic[] = "SQLite format 3";  // 16 bytes with the NUL
  if (size < h.size() || std::memcmp(h.data(), kMagic, sizeof kMagic) != 0) {
    if (const auto damage = sessionDamage(path); damage != SessionDamage::kNone)
      return corruptData(damagedSessionMessage(path, damage));
    return corruptData("'" + path + "' is not a fogbench session (not an SQLite database)");
  }
  HeaderInfo info;
  info.applicationId = bigEndian32(h.data() + 68);
  info.userVersion = static_cast<int>(bigEndian32(h.data() + 60));
  // Truncation: the header's page count is trustworthy when its "version
  // valid for" matches the change counter (SQLite file format, section 1.3.7).
  std::uint64_t pageSize = (std::uint64_t{h[16]} << 8) | h[17];
  if (pageSize == 1) pageSize = 65536;
  const std::uint64_t pages = bigEndian32(h.data() + 28);
  if (pages != 0 && bigEndian32(h.data() + 24) == bigEndian32(h.data() + 92) && size < pages * pageSize) {
    info.truncated = "'" + path + "' is truncated: it holds " + std::to_string(size) + " of its " +
                     std::to_string(pages * pageSize) + " bytes; copy it again from the original or restore a backup";
    // A WAL holds at least its 32-byte header and one frame.
    const auto walSize = fs::file_size(path + "-wal", ec);
    info.truncatedWithWal = !ec && walSize > 32 + 24;
  }
  return info;
}

// A session file this build may open: fogbench's id, not truncated.
Result<HeaderInfo> checkHeader(const std::string& path) {
  auto info = readHeader(path);
  if (!info) return info;
  if (info->applicationId != static_cast<std::uint32_t>(kApplicationId)) {
    char id[16];
    std::snprintf(id, sizeof id, "0x%08X", info->applicationId);
    return corruptData("'" + path + "' is an SQLite database but not a fogbench session (application_id " + id +
                       ")");
  }
  // A live recording's main file lags its -wal, and a checkpoint in progress
  // can show a header ahead of the file: SQLite's view through the -wal
  // decides then (checkWalCoversTruncation), never the size alone (1 open in
  // 3 463 of a session being recorded was refused as truncated).
  if (!info->truncated.empty() && !info->truncatedWithWal && isBeingRecorded(path)) info->truncatedWithWal = true;
  if (!info->truncated.empty() && !info->truncatedWithWal) return corruptData(info->truncated);
  return info;
}

// For a file that is shorter than its header says but has a -wal: the
// connection sees the pages of the -wal over the main file; if the whole
// database checks out through it, nothing is missing (the -wal is
// checkpointed into the main file by the next connection that writes).
Status checkWalCoversTruncation(sqlite3* db, const HeaderInfo& header) {
  if (!header.truncatedWithWal) return Status::ok();
  Stmt s(db, "PRAGMA quick_check(1)");
  if (s.ok() && s.step() == SQLITE_ROW && s.text(0) == "ok") return Status::ok();
  return corruptData(header.truncated + " (its -wal does not hold the missing pages)");
}

std::string newerSchemaMessage(const std::string& path, std::int64_t version) {
  return "'" + path + "' was written by a newer fogbench (schema " + std::to_string(version) +
         "; this one reads up to " + std::to_string(kSchemaVersion) + "): update fogbench";
}

// Authoritative identity and version check through SQLite (the header read
// above may predate changes still in the WAL).
Result<int> checkIdentity(sqlite3* db, const std::string& path) {
  auto app = pragmaInt(db, "PRAGMA application_id");
  if (!app)
    return corruptData("cannot read session '" + path + "': " + app.status().message() +
                       "; the file is damaged, restore it from a backup");
  if (*app != kApplicationId) return corruptData("'" + path + "' is not a fogbench session");
  auto version = pragmaInt(db, "PRAGMA user_version");
  if (!version) return corruptData("cannot read session '" + path + "': " + version.status().message());
  if (*version > kSchemaVersion) return invalidArgument(newerSchemaMessage(path, *version));
  if (*version < 1)
    return corruptData("'" + path + "' has no session schema (user_version " + std::to_string(*version) +
                       "); it was not written completely");
  return static_cast<int>(*version);
}

// Migrations from older schemas, applied inside the caller's write
// transaction before anything is written. Schema 1 is the first: none yet.
// A new version adds a step here ("if (from < 2) { ALTER TABLE ...; }") and
// SessionReader learns to read every older layout without migrating it.
Status migrate(sqlite3* db, int from) {
  if (from == kSchemaVersion) return Status::ok();
  if (from < 1 || from > kSchemaVersion)
    return Status(StatusCode::kInternal, "no migration from schema " + std::to_string(from));
  if (from < 2) {
    // 1 -> 2: checksum columns. The metadata of a migrated file stays
    // unchecked (NULL): a checksum now would bless whatever it holds.
    if (!exec(db, kSchemaV2Step) || !exec(db, "PRAGMA user_version = 2"))
      return ioError("migrating from schema 1 to 2 failed: " + sqliteMessage(db));
  }
  if (from < 3) {
    // 2 -> 3: an empty table log.
    if (!exec(db, kSchemaV3Step) || !exec(db, "PRAGMA user_version = 3"))
      return ioError("migrating from schema 2 to 3 failed: " + sqliteMessage(db));
  }
  // 3 -> 4: gyro signs, +1 (what the file was analysed with), and no
  // import settings; 4 -> 5: no stated IMU frame; 5 -> 6: no lot, no bench. A checked metadata row
  // stays checked over the new columns only if it still matches its
  // checksum: a damaged row is never blessed.
  auto addMetadataColumns = [&](int to, const char* step) -> Status {
    const std::string what = "migrating from schema " + std::to_string(to - 1) + " to " + std::to_string(to);
    std::optional<std::int64_t> stored;
    {
      Stmt c(db, "SELECT metadata_fnv1a FROM session WHERE id = 1");
      if (c.ok() && c.step() == SQLITE_ROW && sqlite3_column_type(c.get(), 0) != SQLITE_NULL) stored = c.integer(0);
    }
    const auto before = metadataChecksum(db, to - 1);
    if (!exec(db, step) || !exec(db, ("PRAGMA user_version = " + std::to_string(to)).c_str()))
      return ioError(what + " failed: " + sqliteMessage(db));
    if (stored && before && *before == *stored && !updateMetadataChecksum(db, to))
      return ioError(what + " failed: " + sqliteMessage(db));
    return Status::ok();
  };
  if (from < 4) FOG_RETURN_IF_ERROR(addMetadataColumns(4, kSchemaV4Step));
  if (from < 5) FOG_RETURN_IF_ERROR(addMetadataColumns(5, kSchemaV5Step));
  if (from < 6) FOG_RETURN_IF_ERROR(addMetadataColumns(6, kSchemaV6Step));
  return Status::ok();
}

}  // namespace
std::string utcNow();
namespace {
Status insertTableLog(sqlite3* db, const std::vector<TableLogEntry>& entries) {
  Stmt s(db, "INSERT INTO table_log (elapsed_s, logged_utc, kind, text) VALUES (?1, ?2, ?3, ?4)");
  if (!s.ok()) return ioError(sqliteMessage(db));
  const std::string now = utcNow();
  for (const auto& e : entries) {
    sqlite3_reset(s.get());
    s.bind(1, e.elapsedS);
    s.bind(2, now);
    s.bind(3, toValidUtf8(e.kind.substr(0, kMaxFieldBytes)));
    s.bind(4, toValidUtf8(e.text.substr(0, kMaxFieldBytes)));
    if (s.step() != SQLITE_DONE) return ioError(sqliteMessage(db));
  }
  return Status::ok();
}

}  // namespace

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

bool looksLikeSession(const std::string& path) {
  auto h = readHeader(path);
  if (h.isOk()) return h->applicationId == static_cast<std::uint32_t>(kApplicationId);
  // kCorruptData: a regular file that was read (a FIFO is never opened).
  return h.status().code() == StatusCode::kCorruptData && sessionDamage(path) != SessionDamage::kNone;
}

bool isSqliteFile(const std::string& path) {
  auto h = readHeader(path);
  return h.isOk() || (h.status().code() == StatusCode::kCorruptData && sessionDamage(path) != SessionDamage::kNone);
}

bool isBeingRecorded(const std::string& path) {
  // Called before the caller opens its own SQLite connection to the file:
  // closing this descriptor drops every fcntl() lock the process holds on it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool live = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return live;
}

// --- SessionWriter ---------------------------------------------------------

Result<std::unique_ptr<SessionWriter>> SessionWriter::create(const std::string& path, const SessionInfo& infoIn) {
  std::error_code ec;
  const std::string exists =
      "'" + path + "' already exists; a session file is never overwritten: choose another name";
  if (fs::exists(path, ec)) return ioError(exists);
  SessionInfo info = infoIn;
  // Stored text is UTF-8 (JSON output, other tools): convert what is not.
  for (std::string* text : {&info.operatorName, &info.imuModel, &info.imuSerial, &info.lot, &info.benchId,
                            &info.source, &info.softwareVersion, &info.createdUtc, &info.notes})
    *text = toValidUtf8(*text);
  // A frame whose text does not read back (a heading beyond +-360) would
  // make the file unreadable once recorded: refused before anything is written.
  const std::string frameText = imuFrameToText(info.bench.imuFrame);
  auto readsBack = [&](const ImuFrame& f) {
    const auto& given = info.bench.imuFrame.forwardHeadingDeg;
    return f.convention == info.bench.imuFrame.convention && f.forwardHeadingDeg.has_value() == given.has_value() &&
           (!given || std::abs(*f.forwardHeadingDeg - *given) <= 1e-6);
  };
  if (auto frame = imuFrameFromText(frameText); !frame || !readsBack(*frame)) {
    const std::string why = frame ? "it does not read back" : frame.status().message();
    return invalidArgument("cannot create session '" + path + "': the bench constants' IMU frame \"" + frameText +
                           "\" cannot be stored (" + why + "); correct it in the bench constants");
  }
  if (info.createdUtc.empty()) info.createdUtc = utcNow();
  if (info.softwareVersion.empty()) info.softwareVersion = FOG_VERSION;
  // Bounded text: every reader holds it in memory and prints it.
  if (info.notes.size() > kMaxNotesBytes)
    return invalidArgument("the notes are " + std::to_string(info.notes.size()) + " bytes; at most " +
                           std::to_string(kMaxNotesBytes) + " (attach long documents beside the session)");
  for (const auto& [name, text] : {std::pair<const char*, const std::string*>{"operator", &info.operatorName},
                                   {"IMU model", &info.imuModel}, {"IMU serial", &info.imuSerial},
                                   {"lot", &info.lot}, {"bench id", &info.benchId},
                                   {"source", &info.source}, {"software version", &info.softwareVersion},
                                   {"creation time", &info.createdUtc}})
    if (text->size() > kMaxFieldBytes)
      return invalidArgument(std::string("the ") + name + " is " + std::to_string(text->size()) +
                             " bytes; at most " + std::to_string(kMaxFieldBytes));

  // The file is created exclusively (O_EXCL): of two programs creating the
  // same name, exactly one wins, and the other never touches the winner's
  // file. The winner keeps this descriptor open with an exclusive flock()
  // until it has finished: isBeingRecorded() tells a live recording from an
  // interrupted one by it. (flock() locks are independent of SQLite's fcntl()
  // locks, and the descriptor is closed only after SQLite's connection.)
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    if (errno == EEXIST) return ioError(exists);
    return ioError("cannot create session '" + path + "': " + std::strerror(errno) +
                   "; check the folder exists and is writable");
  }
  ::flock(fd, LOCK_EX);  // ours alone: at most a reader's momentary probe delays it
  std::unique_ptr<SessionWriter> w(new SessionWriter());
  w->path_ = path;
  w->lockFd_ = fd;
  // A stale -wal or -journal beside the new name would be replayed into the
  // new file by SQLite. Such side files are not ours: never remove them.
  for (const char* suffix : {"-wal", "-journal", "-shm"}) {
    if (fs::exists(path + suffix, ec)) {
      fs::remove(path, ec);  // the empty file this call made
      ::close(fd);
      return ioError("a leftover '" + path + suffix + "' from an earlier file of the same name exists; move it "
                     "away or delete it, or choose another name");
    }
  }
  const int rc = sqlite3_open_v2(path.c_str(), &w->db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  auto abandon = [&](const std::string& what) -> Status {
    std::string msg = "cannot create session '" + path + "': " + what + " (" + sqliteMessage(w->db_) + ")";
    sqlite3_close(w->db_);
    w->db_ = nullptr;
    // Only what this call created: the file it made exclusively (it holds no
    // data yet) and the side files its own connection made.
    fs::remove(path, ec);
    for (const char* suffix : {"-journal", "-wal", "-shm"}) fs::remove(path + suffix, ec);
    ::close(w->lockFd_);
    w->lockFd_ = -1;
    return ioError(msg + "; check the folder exists and is writable");
  };
  if (rc != SQLITE_OK) return abandon("open failed");
  sqlite3_extended_result_codes(w->db_, 1);
  sqlite3_busy_timeout(w->db_, kRecorderBusyTimeoutMs);
  // Everything that identifies the file goes in one rollback-journal
  // transaction, written to the main file before WAL mode is switched on:
  // a file is either a complete empty session or not a session at all.
  const std::string ids = "PRAGMA application_id = " + std::to_string(kApplicationId) +
                          "; PRAGMA user_version = " + std::to_string(kSchemaVersion) + ";";
  if (!exec(w->db_, "BEGIN") || !exec(w->db_, ids.c_str()) || !exec(w->db_, kSchemaV1) ||
      !exec(w->db_, kSchemaV2Step) || !exec(w->db_, kSchemaV3Step) || !exec(w->db_, kSchemaV4Step) || !exec(w->db_, kSchemaV5Step) ||
      !exec(w->db_, kSchemaV6Step))
    return abandon("schema");
  {
    Stmt s(w->db_,
           "INSERT INTO session (id, operator, imu_model, imu_serial, source, software_version, created_utc, notes,"
           " table_read_delay_ms, table_read_delay_std_ms, board_delay_ms, board_delay_std_ms, latitude_deg,"
           " pulse_equivalent_deg, counter_hz, counter_bits, test_plan_json, state, gyro_sign_x, gyro_sign_y,"
           " gyro_sign_z, import_json, imu_frame, lot, bench_id)"
           " VALUES (1, ?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, 'recording', ?17, ?18,"
           " ?19, ?20, ?21, ?22, ?23)");
    if (!s.ok()) return abandon("metadata");
    s.bind(1, info.operatorName);
    s.bind(2, info.imuModel);
    s.bind(3, info.imuSerial);
    s.bind(4, info.source);
    s.bind(5, info.softwareVersion);
    s.bind(6, info.createdUtc);
    s.bind(7, info.notes);
    s.bind(8, info.bench.tableReadDelayMs);
    s.bind(9, info.bench.tableReadDelayStdMs);
    s.bind(10, info.bench.boardDelayMs);
    s.bind(11, info.bench.boardDelayStdMs);
    s.bind(12, info.bench.latitudeDeg);
    s.bind(13, info.bench.pulseEquivalentDeg);
    s.bind(14, info.bench.counterHz);
    s.bind(15, std::int64_t{info.bench.counterBits});
    s.bind(16, testPlanToJson(info.plan));
    for (int a = 0; a < kAxisCount; ++a)
      s.bind(17 + a, std::int64_t{info.bench.gyroSign[static_cast<std::size_t>(a)] < 0 ? -1 : 1});
    s.bind(20, importSettingsToJson(info.imported));
    s.bind(21, frameText);
    s.bind(22, info.lot);
    s.bind(23, info.benchId);
    if (s.step() != SQLITE_DONE) return abandon("metadata");
  }
  if (!updateMetadataChecksum(w->db_)) return abandon("metadata checksum");
  if (!exec(w->db_, "COMMIT")) return abandon("commit");
  // WAL: a commit appends to the -wal file and a crash never leaves a torn
  // database; synchronous=FULL syncs every commit, so even a power cut keeps
  // all committed chunks (a handful of syncs per second costs nothing).
  auto mode = [&]() -> std::string {
    Stmt s(w->db_, "PRAGMA journal_mode = WAL");
    return s.ok() && s.step() == SQLITE_ROW ? s.text(0) : std::string();
  }();
  if (mode != "wal" || !exec(w->db_, "PRAGMA synchronous = FULL")) return abandon("WAL journal");
  return w;
}

SessionWriter::~SessionWriter() {
  if (db_) {
    // Not finished: keep what was given (state stays "recording", which the
    // reader reports as interrupted), exactly as after a crash.
    if (broken_.isOk()) (void)commitPending();
    sqlite3_close(db_);
  }
  if (lockFd_ >= 0) ::close(lockFd_);  // after SQLite's connection: releases the recording lock
}

Status SessionWriter::fail(const std::string& what) {
  const int code = db_ ? (sqlite3_extended_errcode(db_) & 0xff) : SQLITE_NOMEM;
  const char* advice = code == SQLITE_FULL                          ? "; the disk is full: free some space"
                       : code == SQLITE_BUSY || code == SQLITE_LOCKED ? "; another program holds the file locked"
                                                                      : "; check free disk space and the device";
  broken_ = ioError("writing session '" + path_ + "' failed while " + what + ": " + sqliteMessage(db_) +
                    "; the data committed so far is kept" + advice);
  exec(db_, "ROLLBACK");
  return broken_;
}

Status SessionWriter::commitPending() {
  if (pending_.empty()) return Status::ok();
  Stmt s(db_, "INSERT INTO raw_chunk (seq, byte_offset, data, data_fnv1a, committed_utc) VALUES (?1, ?2, ?3, ?4, ?5)");
  if (!s.ok()) return fail("storing raw bytes");
  s.bind(1, nextChunk_);
  s.bind(2, static_cast<std::int64_t>(committed_));
  s.bindBlob(3, pending_.data(), pending_.size());
  s.bind(4, fnv1a(pending_));
  s.bind(5, utcNow());
  // Autocommit: one statement, one transaction, one WAL sync.
  if (s.step() != SQLITE_DONE) return fail("storing raw bytes");
  ++nextChunk_;
  ++commits_;
  committed_ += pending_.size();
  pending_.clear();
  return Status::ok();
}

Status SessionWriter::appendRaw(const std::uint8_t* data, std::size_t size) {
  if (!broken_.isOk()) return broken_;
  if (finished_) return invalidArgument("session '" + path_ + "' is finished; it accepts no more data");
  const auto now = std::chrono::steady_clock::now();
  if (size > 0) {
    if (pending_.empty()) oldestPending_ = now;
    pending_.insert(pending_.end(), data, data + size);
    appended_ += size;
  }
  if (!pending_.empty() && (now - oldestPending_ >= kCommitInterval || pending_.size() >= kMaxPendingRaw))
    return commitPending();
  return Status::ok();
}

Status SessionWriter::appendTableLog(const std::vector<TableLogEntry>& entries) {
  if (!broken_.isOk()) return broken_;
  if (finished_) return invalidArgument("session '" + path_ + "' is finished; it accepts no more data");
  if (entries.empty()) return Status::ok();
  if (auto s = commitPending(); !s.isOk()) return s;
  if (!exec(db_, "BEGIN IMMEDIATE")) return fail("storing the table log");
  if (!insertTableLog(db_, entries).isOk()) return fail("storing the table log");
  if (!exec(db_, "COMMIT")) return fail("storing the table log");
  return Status::ok();
}

Status SessionWriter::flush() {
  if (!broken_.isOk()) return broken_;
  if (finished_) return Status::ok();
  return commitPending();
}

Status SessionWriter::storeRecording(const Recording& rec) {
  if (!broken_.isOk()) return broken_;
  if (finished_) return invalidArgument("session '" + path_ + "' is finished; it accepts no more data");
  if (auto s = commitPending(); !s.isOk()) return s;
  if (!exec(db_, "BEGIN IMMEDIATE")) return fail("storing decoded samples");
  if (!exec(db_, "DELETE FROM decoded; DELETE FROM test_point; DELETE FROM table_block; DELETE FROM imu_block;"))
    return fail("storing decoded samples");
  {
    Stmt s(db_,
           "INSERT INTO decoded VALUES (1, ?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)");
    if (!s.ok()) return fail("storing decoded samples");
    const auto& h = rec.health;
    s.bind(1, static_cast<std::int64_t>(committed_));
    s.bind(2, rec.counterHz);
    s.bind(3, std::int64_t{rec.counterBits});
    s.bind(4, rec.pulseEquivalentDeg);
    const std::uint64_t counters[] = {h.tableFrames,     h.imuFrames,       h.statusFrames,
                                      h.checksumFailures, h.bytesSkipped,   h.lostFrames,
                                      h.duplicateFrames,  h.outOfOrderFrames, h.counterWraps};
    for (int i = 0; i < 9; ++i) s.bind(5 + i, static_cast<std::int64_t>(counters[i]));
    if (s.step() != SQLITE_DONE) return fail("storing decoded samples");
  }
  Stmt point(db_, "INSERT INTO test_point VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  Stmt tableBlock(db_, "INSERT INTO table_block VALUES (?1, ?2, ?3, ?4, ?5)");
  Stmt imuBlock(db_, "INSERT INTO imu_block VALUES (?1, ?2, ?3, ?4, ?5)");
  if (!point.ok() || !tableBlock.ok() || !imuBlock.ok()) return fail("storing decoded samples");
  // The samples of one test point in blocks of kSamplesPerBlock records,
  // each with its checksum; encode(k, at) writes sample k's record.
  std::vector<std::uint8_t> buf;
  auto writeBlocks = [&](Stmt& blocks, std::int64_t testPoint, std::size_t count, std::size_t recordBytes,
                         const auto& encode) {
    for (std::size_t first = 0, block = 0; first < count; first += kSamplesPerBlock, ++block) {
      const std::size_t n = std::min(kSamplesPerBlock, count - first);
      buf.resize(n * recordBytes);
      for (std::size_t i = 0; i < n; ++i) encode(first + i, buf.data() + i * recordBytes);
      blocks.bind(1, testPoint);
      blocks.bind(2, static_cast<std::int64_t>(block));
      blocks.bind(3, static_cast<std::int64_t>(n));
      blocks.bindBlob(4, buf.data(), buf.size());
      blocks.bind(5, fnv1a(buf));
      if (blocks.step() != SQLITE_DONE) return false;
      sqlite3_reset(blocks.get());
    }
    return true;
  };
  for (std::size_t p = 0; p < rec.testPoints.size(); ++p) {
    const auto& tp = rec.testPoints[p];
    const auto pos = static_cast<std::int64_t>(p);
    point.bind(1, pos);
    point.bind(2, std::int64_t{tp.index});
    point.bind(3, std::string(axisName(tp.axis)));
    point.bind(4, tp.nominalFrequencyHz);
    point.bind(5, tp.nominalAmplitudeDeg);
    point.bind(6, static_cast<std::int64_t>(tp.table.size()));
    point.bind(7, static_cast<std::int64_t>(tp.imu.size()));
    if (point.step() != SQLITE_DONE) return fail("storing decoded samples");
    sqlite3_reset(point.get());
    if (!writeBlocks(tableBlock, pos, tp.table.size(), kTableRecordBytes, [&](std::size_t k, std::uint8_t* at) {
          const auto& t = tp.table[k];
          putDouble(at, t.timeS);
          for (int a = 0; a < kAxisCount; ++a) putDouble(at + 8 * (a + 1), t.angleDeg[static_cast<std::size_t>(a)]);
        }))
      return fail("storing decoded samples");
    if (!writeBlocks(imuBlock, pos, tp.imu.size(), kImuRecordBytes, [&](std::size_t k, std::uint8_t* at) {
          const auto& m = tp.imu[k];
          putDouble(at, m.timeS);
          for (int a = 0; a < kAxisCount; ++a) putDouble(at + 8 * (a + 1), m.incrementDeg[static_cast<std::size_t>(a)]);
          putDouble(at + 32, m.temperatureC);
          putU32(at + 40, m.lostBefore);
        }))
      return fail("storing decoded samples");
  }
  if (!exec(db_, "COMMIT")) return fail("storing decoded samples");
  return Status::ok();
}

Status SessionWriter::finish(bool complete, const std::string& reason) {
  if (!broken_.isOk()) return broken_;
  if (finished_) return Status::ok();
  if (auto s = commitPending(); !s.isOk()) return s;
  if (!exec(db_, "BEGIN IMMEDIATE")) return fail("marking the session finished");
  {
    Stmt s(db_, "UPDATE session SET state = ?1, incomplete_reason = ?2, finished_utc = ?3 WHERE id = 1");
    if (!s.ok()) return fail("marking the session finished");
    s.bind(1, std::string(complete ? "complete" : "incomplete"));
    s.bind(2, complete ? std::string() : (reason.empty() ? std::string("stopped before the end") : toValidUtf8(reason)));
    s.bind(3, utcNow());
    if (s.step() != SQLITE_DONE) return fail("marking the session finished");
  }
  if (!updateMetadataChecksum(db_) || !exec(db_, "COMMIT")) return fail("marking the session finished");
  finished_ = true;
  // Back to a single self-contained file: checkpoint the WAL into the main
  // file and drop it. Everything is committed already, so a failure here
  // loses nothing (the -wal file simply stays beside the session, e.g. while
  // a reader has it open, and the next connection to close checkpoints it).
  sqlite3_busy_timeout(db_, kFinishBusyTimeoutMs);
  exec(db_, "PRAGMA wal_checkpoint(TRUNCATE)");
  exec(db_, "PRAGMA journal_mode = DELETE");
  if (sqlite3_close(db_) != SQLITE_OK) return fail("closing the file");
  db_ = nullptr;
  ::close(lockFd_);
  lockFd_ = -1;
  return Status::ok();
}

Status SessionWriter::finishAfterFailure(const std::string& reason) {
  if (finished_ || !db_) return broken_;
  finished_ = true;
  pending_.clear();
  Status marked = Status::ok();
  exec(db_, "ROLLBACK");  // whatever the failed write left open
  bool ok = exec(db_, "BEGIN IMMEDIATE");
  {
    Stmt s(db_, "UPDATE session SET state = 'incomplete', incomplete_reason = ?1, finished_utc = ?2 WHERE id = 1");
    if (s.ok()) {
      s.bind(1, toValidUtf8(reason));
      s.bind(2, utcNow());
    }
    ok = ok && s.ok() && s.step() == SQLITE_DONE;
  }
  ok = ok && updateMetadataChecksum(db_) && exec(db_, "COMMIT");
  if (!ok) {
    marked = ioError("session '" + path_ + "' could not be marked incomplete: " + sqliteMessage(db_));
    exec(db_, "ROLLBACK");
  }
  sqlite3_busy_timeout(db_, kFinishBusyTimeoutMs);
  if (marked.isOk()) {
    exec(db_, "PRAGMA wal_checkpoint(TRUNCATE)");
    exec(db_, "PRAGMA journal_mode = DELETE");
  }
  sqlite3_close(db_);
  db_ = nullptr;
  ::close(lockFd_);
  lockFd_ = -1;
  return marked;
}

// --- SessionReader ---------------------------------------------------------

Result<std::unique_ptr<SessionReader>> SessionReader::open(const std::string& path) {
  FOG_ASSIGN_OR_RETURN(auto header, checkHeader(path));
  if (header.userVersion > kSchemaVersion) return invalidArgument(newerSchemaMessage(path, header.userVersion));

  std::unique_ptr<SessionReader> r(new SessionReader());
  r->path_ = path;
  r->live_ = isBeingRecorded(path);
  if (sqlite3_open_v2(path.c_str(), &r->db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
    return ioError("cannot open session '" + path + "': " + sqliteMessage(r->db_) + "; check its permissions");
  // A recorder may be checkpointing or another program running WAL recovery.
  sqlite3_busy_timeout(r->db_, kReaderBusyTimeoutMs);
  FOG_RETURN_IF_ERROR(checkWalCoversTruncation(r->db_, header));
  FOG_ASSIGN_OR_RETURN(auto version, checkIdentity(r->db_, path));
  r->schemaVersion_ = version;

  if (r->schemaVersion_ >= 2) {
    Stmt c(r->db_, "SELECT metadata_fnv1a FROM session WHERE id = 1");
    if (!c.ok() || c.step() != SQLITE_ROW) return r->readError("reading its metadata");
    if (sqlite3_column_type(c.get(), 0) != SQLITE_NULL) {
      auto sum = metadataChecksum(r->db_, r->schemaVersion_);
      if (!sum) return r->readError("reading its metadata");
      if (*sum != c.integer(0))
        return corruptData("session '" + path + "': its metadata (who, bench constants, plan, state) fails its "
                           "checksum; the file is damaged, restore it from a backup");
    }
  }
  // Text is read at most kMax...Bytes long (a crafted file may hold 200 MB
  // of notes); length() tells whether it was cut.
  const std::string field = std::to_string(kMaxFieldBytes), notes = std::to_string(kMaxNotesBytes);
  auto cut = [](const char* column, const std::string& n) {
    return std::string("CAST(substr(CAST(") + column + " AS BLOB), 1, " + n + ") AS TEXT)";
  };
  const std::string sql =
      "SELECT " + cut("operator", field) + ", " + cut("imu_model", field) + ", " + cut("imu_serial", field) + ", " +
      cut("source", field) + ", " + cut("software_version", field) + ", " + cut("created_utc", field) + ", " +
      cut("notes", notes) +
      ", table_read_delay_ms, table_read_delay_std_ms, board_delay_ms, board_delay_std_ms, latitude_deg,"
      " pulse_equivalent_deg, counter_hz, counter_bits, test_plan_json, state, " +
      cut("incomplete_reason", field) + ", length(CAST(notes AS BLOB))" +
      (r->schemaVersion_ >= 4 ? ", gyro_sign_x, gyro_sign_y, gyro_sign_z, " + cut("import_json", notes) : "") +
      (r->schemaVersion_ >= 5 ? ", " + cut("imu_frame", field) : "") +
      (r->schemaVersion_ >= 6 ? ", " + cut("lot", field) + ", " + cut("bench_id", field) : "") +
      " FROM session WHERE id = 1";
  Stmt s(r->db_, sql.c_str());
  if (!s.ok()) return r->readError("reading its metadata");
  const int rc = s.step();
  if (rc != SQLITE_ROW) {
    if (rc == SQLITE_DONE) return corruptData("session '" + path + "' has no metadata row; the file is damaged");
    return r->readError("reading its metadata");
  }
  auto& info = r->info_;
  // A file written by another tool may hold text that is not UTF-8.
  info.operatorName = toValidUtf8(s.text(0));
  info.imuModel = toValidUtf8(s.text(1));
  info.imuSerial = toValidUtf8(s.text(2));
  info.source = toValidUtf8(s.text(3));
  info.softwareVersion = toValidUtf8(s.text(4));
  info.createdUtc = toValidUtf8(s.text(5));
  info.notes = toValidUtf8(s.text(6));
  if (const auto stored = s.integer(18); stored > static_cast<std::int64_t>(kMaxNotesBytes))
    info.notes += " [... notes cut: the file holds " + std::to_string(stored) + " bytes]";
  info.bench.tableReadDelayMs = s.real(7);
  info.bench.tableReadDelayStdMs = s.real(8);
  info.bench.boardDelayMs = s.real(9);
  info.bench.boardDelayStdMs = s.real(10);
  info.bench.latitudeDeg = s.real(11);
  info.bench.pulseEquivalentDeg = s.real(12);
  info.bench.counterHz = s.real(13);
  info.bench.counterBits = static_cast<int>(s.integer(14));
  // Older schemas have no signs: +1, what their analyses used.
  if (r->schemaVersion_ >= 4)
    for (int a = 0; a < kAxisCount; ++a)
      info.bench.gyroSign[static_cast<std::size_t>(a)] = s.integer(19 + a) < 0 ? -1 : 1;
  auto plan = testPlanFromJson(s.text(15));
  if (!plan)
    return corruptData("session '" + path + "': its stored test plan is unreadable (" + plan.status().message() +
                       ")");
  info.plan = std::move(*plan);
  if (r->schemaVersion_ >= 4) {  // older schemas have no import settings
    auto imported = importSettingsFromJson(s.text(22));
    if (!imported)
      return corruptData("session '" + path + "': its import settings are unreadable (" +
                         imported.status().message() + ")");
    info.imported = std::move(*imported);
  }
  if (r->schemaVersion_ >= 5) {  // older schemas state no frame
    auto frame = imuFrameFromText(s.text(23));
    if (!frame)
      return corruptData("session '" + path + "': its stored IMU frame is unreadable (" + frame.status().message() +
                         ")");
    info.bench.imuFrame = *frame;
  }
  if (r->schemaVersion_ >= 6) {  // older schemas state neither: ''
    info.lot = toValidUtf8(s.text(24));
    info.benchId = toValidUtf8(s.text(25));
  }
  r->state_ = s.text(16);
  r->reason_ = toValidUtf8(s.text(17));
  return r;
}

SessionReader::~SessionReader() { sqlite3_close(db_); }

Status SessionReader::readError(const std::string& what) const {
  return corruptData("cannot read session '" + path_ + "' (" + what + "): " + sqliteMessage(db_) +
                     "; the file is damaged, restore it from a backup");
}

std::string SessionReader::incompleteReason() const {
  if (state_ == "complete") return {};
  if (state_ == "incomplete") return reason_;
  if (live_) return "being recorded now: the session is not finished yet";
  return "recording was interrupted: the recording program stopped without finishing the session "
         "(crash, kill, power cut or a full disk); everything committed until then is kept";
}

bool SessionReader::isReadOnly() const { return sqlite3_db_readonly(db_, "main") == 1; }

std::uint64_t SessionReader::rawByteCount() const {
  Stmt s(db_, "SELECT coalesce(sum(length(data)), 0) FROM raw_chunk");
  return s.ok() && s.step() == SQLITE_ROW ? static_cast<std::uint64_t>(s.integer(0)) : 0;
}

Result<std::vector<std::uint8_t>> SessionReader::rawBytes() const {
  std::vector<std::uint8_t> out;
  out.reserve(rawByteCount());
  Stmt s(db_, "SELECT seq, byte_offset, data, data_fnv1a FROM raw_chunk ORDER BY seq");
  if (!s.ok()) return readError("reading the raw stream");
  int rc;
  std::int64_t expectSeq = 0;
  while ((rc = s.step()) == SQLITE_ROW) {
    if (s.integer(0) != expectSeq || s.integer(1) != static_cast<std::int64_t>(out.size()))
      return corruptData("session '" + path_ + "': the raw stream has a gap at byte " + std::to_string(out.size()) +
                         " (chunk " + std::to_string(expectSeq) + "); the file is damaged");
    auto data = s.blob(2);
    if (fnv1a(data) != s.integer(3))
      return corruptData("session '" + path_ + "': raw stream chunk " + std::to_string(expectSeq) + " (bytes " +
                         std::to_string(out.size()) + ".." + std::to_string(out.size() + data.size()) +
                         ") fails its checksum; the file is damaged, restore it from a backup");
    out.insert(out.end(), data.begin(), data.end());
    ++expectSeq;
  }
  if (rc != SQLITE_DONE) return readError("reading the raw stream");
  return out;
}

Status SessionReader::checkRawStream() const { return walkRawStream({}); }

Result<std::string> SessionReader::rawSha256() const {
  Sha256 h;
  FOG_RETURN_IF_ERROR(walkRawStream([&h](const std::uint8_t* p, std::size_t n) { h.update(p, n); }));
  return h.hex();
}

Status SessionReader::walkRawStream(const std::function<void(const std::uint8_t*, std::size_t)>& each) const {
  Stmt s(db_, "SELECT seq, byte_offset, data, data_fnv1a FROM raw_chunk ORDER BY seq");
  if (!s.ok()) return readError("reading the raw stream");
  int rc;
  std::int64_t expectSeq = 0, at = 0;
  while ((rc = s.step()) == SQLITE_ROW) {
    if (s.integer(0) != expectSeq || s.integer(1) != at)
      return corruptData("session '" + path_ + "': the raw stream has a gap at byte " + std::to_string(at) +
                         " (chunk " + std::to_string(expectSeq) + "); the file is damaged");
    auto data = s.blob(2);
    if (fnv1a(data) != s.integer(3))
      return corruptData("session '" + path_ + "': raw stream chunk " + std::to_string(expectSeq) + " (bytes " +
                         std::to_string(at) + ".." + std::to_string(at + static_cast<std::int64_t>(data.size())) +
                         ") fails its checksum; the file is damaged, restore it from a backup");
    if (each) each(data.data(), data.size());
    at += static_cast<std::int64_t>(data.size());
    ++expectSeq;
  }
  if (rc != SQLITE_DONE) return readError("reading the raw stream");
  return Status::ok();
}

bool SessionReader::hasStoredRecording() const {
  Stmt s(db_, "SELECT count(*) FROM decoded");
  return s.ok() && s.step() == SQLITE_ROW && s.integer(0) > 0;
}

Result<Recording> SessionReader::recording(double pulseEquivalentDeg) const {
  const double bench = pulseEquivalentDeg > 0.0 ? pulseEquivalentDeg : info_.bench.pulseEquivalentDeg;
  if (!hasStoredRecording()) {
    FOG_ASSIGN_OR_RETURN(auto raw, rawBytes());
    auto rec = protocol::decodeRecording(raw, bench);
    if (!rec) return Status(rec.status().code(), "session '" + path_ + "': " + rec.status().message());
    return rec;
  }
  Recording rec;
  {
    Stmt s(db_, "SELECT counter_hz, counter_bits, pulse_equivalent_deg, table_frames, imu_frames, status_frames,"
                " checksum_failures, bytes_skipped, lost_frames, duplicate_frames, out_of_order_frames, counter_wraps"
                " FROM decoded WHERE id = 1");
    if (!s.ok() || s.step() != SQLITE_ROW) return readError("reading the decoded samples");
    // Stored counts and constants are checked before they size or scale
    // anything: a crafted file (valid checksums) must not crash a reader.
    const double hz = s.real(0), pulse = s.real(2);
    const std::int64_t bits = s.integer(1);
    if (!std::isfinite(hz) || hz < 0 || bits < 0 || bits > 64 || !std::isfinite(pulse))
      return corruptData("session '" + path_ + "': decoded samples are damaged (counter " + std::to_string(hz) +
                         " Hz, " + std::to_string(bits) + " bits); analyse the raw stream instead");
    rec.counterHz = hz;
    rec.counterBits = static_cast<int>(bits);
    rec.pulseEquivalentDeg = pulse;
    std::uint64_t* counters[] = {&rec.health.tableFrames,      &rec.health.imuFrames,
                                 &rec.health.statusFrames,     &rec.health.checksumFailures,
                                 &rec.health.bytesSkipped,     &rec.health.lostFrames,
                                 &rec.health.duplicateFrames,  &rec.health.outOfOrderFrames,
                                 &rec.health.counterWraps};
    for (int i = 0; i < 9; ++i) *counters[i] = static_cast<std::uint64_t>(s.integer(3 + i));
  }
  Stmt points(db_, "SELECT position, point_index, axis, nominal_frequency_hz, nominal_amplitude_deg, table_samples,"
                   " imu_samples FROM test_point ORDER BY position");
  Stmt tableBlocks(db_, "SELECT samples, data, data_fnv1a FROM table_block WHERE test_point = ?1 ORDER BY block");
  Stmt imuBlocks(db_, "SELECT samples, data, data_fnv1a FROM imu_block WHERE test_point = ?1 ORDER BY block");
  if (!points.ok() || !tableBlocks.ok() || !imuBlocks.ok()) return readError("reading the decoded samples");
  auto damaged = [&](const std::string& what) {
    return corruptData("session '" + path_ + "': decoded samples are damaged (" + what +
                       "); analyse the raw stream instead");
  };
  // Every block of one test point, checked against its size and checksum;
  // decode gets each record.
  auto readBlocks = [&](Stmt& blocks, std::int64_t testPoint, std::int64_t expected, std::size_t recordBytes,
                        const std::string& what, const auto& decode) -> Status {
    blocks.bind(1, testPoint);
    int brc;
    std::int64_t total = 0;
    while ((brc = blocks.step()) == SQLITE_ROW) {
      // At most kSamplesPerBlock: n * recordBytes cannot wrap, and the blob
      // must hold exactly that many records.
      const std::int64_t stored = blocks.integer(0);
      if (stored < 0 || static_cast<std::uint64_t>(stored) > kSamplesPerBlock)
        return damaged(what + " block claims " + std::to_string(stored) + " samples (at most " +
                       std::to_string(kSamplesPerBlock) + " per block)");
      const auto n = static_cast<std::size_t>(stored);
      auto data = blocks.blob(1);
      if (data.size() != n * recordBytes || fnv1a(data) != blocks.integer(2))
        return damaged(what + " block fails its size or checksum check");
      total += stored;
      if (total > expected) break;  // more than the test point says: refused below, before decoding it all
      for (std::size_t i = 0; i < n; ++i) decode(data.data() + i * recordBytes);
    }
    sqlite3_reset(blocks.get());
    if (brc != SQLITE_DONE && brc != SQLITE_ROW) return readError("reading the decoded samples");
    if (total != expected)
      return damaged("sample count of test point " + std::to_string(testPoint) + ": it says " +
                     std::to_string(expected) + " " + what.substr(what.find(' ') + 1) + " samples, its blocks hold " +
                     (total > expected ? "more" : std::to_string(total)));
    return Status::ok();
  };
  int rc;
  while ((rc = points.step()) == SQLITE_ROW) {
    TestPointData tp;
    const std::int64_t pos = points.integer(0);
    // The board numbers test points with 16 bits (protocol::StatusPayload).
    const std::int64_t index = points.integer(1);
    if (index < 0 || index >= kMaxTestPointIndex)
      return damaged("test point index " + std::to_string(index) + " outside 0.." +
                     std::to_string(kMaxTestPointIndex - 1));
    tp.index = static_cast<int>(index);
    auto axis = parseAxis(points.text(2));
    if (!axis) return damaged("axis '" + points.text(2) + "'");
    tp.axis = *axis;
    tp.nominalFrequencyHz = points.real(3);
    tp.nominalAmplitudeDeg = points.real(4);
    if (!std::isfinite(tp.nominalFrequencyHz) || !std::isfinite(tp.nominalAmplitudeDeg))
      return damaged("nominal frequency or amplitude of test point " + std::to_string(pos) + " is not a number");
    // The test_point table has no kind column (schema 1 is unchanged): the
    // session's stored plan says which points are static segments.
    if (tp.index >= 0 && static_cast<std::size_t>(tp.index) < info_.plan.points.size())
      tp.kind = info_.plan.points[static_cast<std::size_t>(tp.index)].kind;
    const auto tableCount = points.integer(5), imuCount = points.integer(6);
    if (tableCount < 0 || imuCount < 0) return damaged("negative sample count");
    // Reserved only up to what the blocks can hold: a crafted count must not
    // allocate gigabytes before the blocks disagree with it.
    constexpr std::int64_t kReserveLimit = 1 << 22;
    tp.table.reserve(static_cast<std::size_t>(std::min(tableCount, kReserveLimit)));
    tp.imu.reserve(static_cast<std::size_t>(std::min(imuCount, kReserveLimit)));
    FOG_RETURN_IF_ERROR(readBlocks(tableBlocks, pos, tableCount, kTableRecordBytes, "a table", [&](const std::uint8_t* at) {
      TableSample t;
      t.timeS = getDouble(at);
      for (int a = 0; a < kAxisCount; ++a) t.angleDeg[static_cast<std::size_t>(a)] = getDouble(at + 8 * (a + 1));
      tp.table.push_back(t);
    }));
    FOG_RETURN_IF_ERROR(readBlocks(imuBlocks, pos, imuCount, kImuRecordBytes, "an IMU", [&](const std::uint8_t* at) {
      ImuSample m;
      m.timeS = getDouble(at);
      for (int a = 0; a < kAxisCount; ++a) m.incrementDeg[static_cast<std::size_t>(a)] = getDouble(at + 8 * (a + 1));
      m.temperatureC = getDouble(at + 32);
      m.lostBefore = getU32(at + 40);
      tp.imu.push_back(m);
    }));
    rec.testPoints.push_back(std::move(tp));
  }
  if (rc != SQLITE_DONE) return readError("reading the decoded samples");
  // Sessions stored before the builder had to resolve the pulse equivalent
  // kept raw pulse counts (pulse_equivalent_deg 0) when the stream did not
  // state it; they were analysed with the session's bench constant, which
  // turns them into degrees here as the builder does now.
  const bool anyImu = std::any_of(rec.testPoints.begin(), rec.testPoints.end(),
                                  [](const TestPointData& tp) { return !tp.imu.empty(); });
  if (anyImu && !(rec.pulseEquivalentDeg > 0.0)) {
    if (!(std::isfinite(bench) && bench > 0.0))
      return invalidArgument("session '" + path_ + "': the stream does not state its gyro pulse equivalent (degrees "
                             "per pulse): give --pulse-equivalent-deg or set it in the bench constants");
    rec.pulseEquivalentDeg = bench;
    for (auto& tp : rec.testPoints)
      for (auto& m : tp.imu)
        for (double& v : m.incrementDeg) v *= bench;
  }
  return rec;
}

Result<std::vector<StoredResult>> SessionReader::results() const {
  std::vector<StoredResult> out;
  Stmt s(db_, schemaVersion_ >= 2 ? "SELECT id, created_utc, settings_json, report_json, fnv1a FROM result ORDER BY id"
                                   : "SELECT id, created_utc, settings_json, report_json, NULL FROM result ORDER BY id");
  if (!s.ok()) return readError("reading the results");
  int rc;
  while ((rc = s.step()) == SQLITE_ROW) {
    StoredResult r{s.integer(0), s.text(1), s.text(2), s.text(3)};
    if (sqlite3_column_type(s.get(), 4) != SQLITE_NULL)
      r.intact = resultChecksum(r.createdUtc, r.settingsJson, r.reportJson) == s.integer(4);
    for (std::string* t : {&r.createdUtc, &r.settingsJson, &r.reportJson}) *t = toValidUtf8(*t);
    out.push_back(std::move(r));
  }
  if (rc != SQLITE_DONE) return readError("reading the results");
  return out;
}

Result<std::vector<TableLogEntry>> SessionReader::tableLog() const {
  std::vector<TableLogEntry> out;
  if (schemaVersion_ < 3) return out;
  const std::string n = std::to_string(kMaxFieldBytes);
  Stmt s(db_, ("SELECT elapsed_s, CAST(substr(CAST(kind AS BLOB), 1, " + n + ") AS TEXT), CAST(substr(CAST(text AS BLOB), 1, " +
               n + ") AS TEXT) FROM table_log ORDER BY seq").c_str());
  if (!s.ok()) return readError("reading the table log");
  int rc;
  while ((rc = s.step()) == SQLITE_ROW) out.push_back(TableLogEntry{s.real(0), toValidUtf8(s.text(1)), toValidUtf8(s.text(2))});
  if (rc != SQLITE_DONE) return readError("reading the table log");
  return out;
}

// --- addResult -------------------------------------------------------------

Status addResult(const std::string& path, const std::string& settingsJson, const std::string& reportJson) {
  FOG_ASSIGN_OR_RETURN(auto header, checkHeader(path));
  if (header.userVersion > kSchemaVersion) return invalidArgument(newerSchemaMessage(path, header.userVersion));
  // A result of a recording in progress is of a part of it, and taking the
  // write lock would compete with the recorder: never while it records.
  if (isBeingRecorded(path))
    return ioError("the result was not stored: session '" + path +
                   "' is being recorded right now; analyse it again when the recording has finished");
  sqlite3* db = nullptr;
  struct Closer {
    sqlite3*& db;
    ~Closer() { sqlite3_close(db); }
  } closer{db};
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK)
    return ioError("the result was not stored: cannot open session '" + path + "' for writing: " +
                   sqliteMessage(db) + "; check the file is writable");
  // A recorder or another analysis may hold the write lock briefly; a
  // recorder storing its decoded samples may hold it longer: then the result
  // is not stored (and the recorder is not disturbed).
  sqlite3_busy_timeout(db, kAddResultBusyTimeoutMs);
  if (auto s = checkWalCoversTruncation(db, header); !s.isOk())
    return Status(s.code(), "the result was not stored: " + s.message());
  auto failed = [&](const char* what) {
    const int code = sqlite3_errcode(db);
    Status s = code == SQLITE_BUSY || code == SQLITE_LOCKED
                   ? ioError("the result was not stored in session '" + path +
                             "': the file stayed locked by its recorder or another program for " +
                             std::to_string(kAddResultBusyTimeoutMs / 1000) +
                             " s; the session is unchanged; analyse it again when the recording has finished")
                   : ioError("the result was not stored in session '" + path + "' (" + what + "): " +
                             sqliteMessage(db) + "; the session is unchanged; check the file is writable");
    exec(db, "ROLLBACK");
    return s;
  };
  if (!exec(db, "BEGIN IMMEDIATE")) return failed("locking");
  auto version = checkIdentity(db, path);
  if (!version) {
    exec(db, "ROLLBACK");
    return version.status();
  }
  if (auto s = migrate(db, *version); !s.isOk()) {
    exec(db, "ROLLBACK");
    return s;
  }
  Stmt s(db, "INSERT INTO result (created_utc, settings_json, report_json, fnv1a) VALUES (?1, ?2, ?3, ?4)");
  if (!s.ok()) return failed("inserting");
  const std::string created = utcNow(), settings = toValidUtf8(settingsJson), report = toValidUtf8(reportJson);
  s.bind(1, created);
  s.bind(2, settings);
  s.bind(3, report);
  s.bind(4, resultChecksum(created, settings, report));
  if (s.step() != SQLITE_DONE) return failed("inserting");
  if (!exec(db, "COMMIT")) return failed("committing");
  return Status::ok();
}

Status appendTableLog(const std::string& path, const std::vector<TableLogEntry>& entries) {
  if (entries.empty()) return Status::ok();
  FOG_ASSIGN_OR_RETURN(auto header, checkHeader(path));
  if (header.userVersion > kSchemaVersion) return invalidArgument(newerSchemaMessage(path, header.userVersion));
  if (isBeingRecorded(path))
    return ioError("the table log was not stored: session '" + path + "' is being recorded right now");
  sqlite3* db = nullptr;
  struct Closer {
    sqlite3*& db;
    ~Closer() { sqlite3_close(db); }
  } closer{db};
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK)
    return ioError("the table log was not stored: cannot open session '" + path + "' for writing: " + sqliteMessage(db));
  sqlite3_busy_timeout(db, kAddResultBusyTimeoutMs);
  if (!exec(db, "BEGIN IMMEDIATE"))
    return ioError("the table log was not stored in session '" + path + "': " + sqliteMessage(db));
  auto version = checkIdentity(db, path);
  if (!version) {
    exec(db, "ROLLBACK");
    return version.status();
  }
  if (auto s = migrate(db, *version); !s.isOk()) {
    exec(db, "ROLLBACK");
    return s;
  }
  if (auto s = insertTableLog(db, entries); !s.isOk() || !exec(db, "COMMIT")) {
    exec(db, "ROLLBACK");
    return ioError("the table log was not stored in session '" + path + "': " + sqliteMessage(db));
  }
  return Status::ok();
}

}  // namespace fog::session
