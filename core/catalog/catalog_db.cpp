#include "core/catalog/catalog_db.h"

#include <libpq-fe.h>
#include <sqlite3.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fog::catalog {

namespace {

namespace fs = std::filesystem;

// 'F' 'O' 'G' 'C' at offset 68 of the SQLite header: a fogbench catalog (a
// session file is 'FOGB'), so a catalog command never writes into a session
// or another program's database named by mistake.
constexpr int kCatalogApplicationId = 0x464F4743;

class SqliteDb final : public CatalogDb {
 public:
  ~SqliteDb() override {
    if (db_) sqlite3_close(db_);
  }
  static Result<std::unique_ptr<CatalogDb>> open(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
      return invalidArgument("catalog '" + path + "' is a folder; name a catalog file (e.g. " +
                             (fs::path(path) / "fogbench-catalog.sqlite").string() + ")");
    const bool existed = fs::exists(path, ec) && fs::file_size(path, ec) > 0;
    auto db = std::unique_ptr<SqliteDb>(new SqliteDb);
    db->path_ = path;
    if (sqlite3_open_v2(path.c_str(), &db->db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK)
      return ioError("cannot open the catalog '" + path + "': " + (db->db_ ? sqlite3_errmsg(db->db_) : "out of memory") +
                     "; check the folder exists and is writable");
    sqlite3_busy_timeout(db->db_, 10000);
    auto id = db->query("PRAGMA application_id", {});
    if (!id) return ioError("catalog '" + path + "' is not a readable SQLite database (" + id.status().message() + ")");
    const long long appId = id->empty() ? 0 : integerOf((*id)[0][0]);
    if (appId != kCatalogApplicationId) {
      auto tables = db->query("SELECT count(*) FROM sqlite_master", {});
      const bool empty = tables && !tables->empty() && integerOf((*tables)[0][0]) == 0;
      if (existed && !empty) {
        const std::string what = appId == 0x464F4742 ? "a fogbench session file, not a catalog"
                                                     : "another SQLite database, not a fogbench catalog";
        return invalidArgument("'" + path + "' is " + what + "; nothing was written. Name a catalog file with --db");
      }
      FOG_RETURN_IF_ERROR(db->exec("PRAGMA application_id = " + std::to_string(kCatalogApplicationId), {}));
    }
    // The catalog is derived from the session files (an index run rebuilds
    // any row): WAL with synchronous=NORMAL spares an fsync per commit, and
    // readers (the GUI) never wait for an indexing writer.
    FOG_RETURN_IF_ERROR(db->exec("PRAGMA journal_mode = WAL", {}));
    FOG_RETURN_IF_ERROR(db->exec("PRAGMA synchronous = NORMAL", {}));
    return std::unique_ptr<CatalogDb>(std::move(db));
  }

  Kind kind() const override { return Kind::kSqlite; }
  std::string describe() const override { return "SQLite catalog " + path_; }

  Status exec(const std::string& sql, const std::vector<Value>& params) override {
    auto r = run(sql, params, nullptr);
    return r;
  }
  Result<std::vector<Row>> query(const std::string& sql, const std::vector<Value>& params) override {
    std::vector<Row> rows;
    FOG_RETURN_IF_ERROR(run(sql, params, &rows));
    return rows;
  }

 private:
  SqliteDb() = default;
  Status run(const std::string& sql, const std::vector<Value>& params, std::vector<Row>* rows) {
    const char* tail = sql.c_str();
    const char* end = sql.c_str() + sql.size();
    // Several statements without parameters (the schema) run in turn.
    while (tail < end) {
      sqlite3_stmt* st = nullptr;
      if (sqlite3_prepare_v2(db_, tail, static_cast<int>(end - tail), &st, &tail) != SQLITE_OK)
        return error("preparing a statement");
      if (!st) break;  // only whitespace or a comment left
      for (std::size_t i = 0; i < params.size() && static_cast<int>(i) < sqlite3_bind_parameter_count(st); ++i) {
        const int rc = params[i] ? sqlite3_bind_text(st, static_cast<int>(i + 1), params[i]->data(),
                                                     static_cast<int>(params[i]->size()), SQLITE_TRANSIENT)
                                 : sqlite3_bind_null(st, static_cast<int>(i + 1));
        if (rc != SQLITE_OK) {
          sqlite3_finalize(st);
          return error("binding a value");
        }
      }
      int rc;
      while ((rc = sqlite3_step(st)) == SQLITE_ROW) {
        if (!rows) continue;
        Row row;
        for (int c = 0; c < sqlite3_column_count(st); ++c) {
          if (sqlite3_column_type(st, c) == SQLITE_NULL) {
            row.emplace_back(std::nullopt);
          } else if (sqlite3_column_type(st, c) == SQLITE_FLOAT) {
            row.emplace_back(*numberValue(sqlite3_column_double(st, c)));
          } else {
            const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(st, c));
            row.emplace_back(std::string(t ? t : "", static_cast<std::size_t>(sqlite3_column_bytes(st, c))));
          }
        }
        rows->push_back(std::move(row));
      }
      sqlite3_finalize(st);
      if (rc != SQLITE_DONE) return error("running a statement");
    }
    return Status::ok();
  }
  Status error(const std::string& what) const {
    const int code = sqlite3_errcode(db_);
    std::string msg = "catalog '" + path_ + "': " + what + " failed: " + sqlite3_errmsg(db_);
    if (code == SQLITE_FULL) msg += " (disk full?)";
    if (code == SQLITE_BUSY) msg += " (another program holds the catalog; try again when it is done)";
    if (code == SQLITE_READONLY) msg += " (the catalog file or its folder is read-only)";
    return ioError(msg);
  }

  sqlite3* db_ = nullptr;
  std::string path_;
};

// libpq's message on one line: "…failed: Connection refused\n\tIs the
// server running…\n" -> "…failed: Connection refused; Is the server running…".
std::string oneLine(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') {
      out += "; ";
    } else if (c != '\t' && c != '\r') {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

class PostgresDb final : public CatalogDb {
 public:
  ~PostgresDb() override {
    if (conn_) PQfinish(conn_);
  }
  static Result<std::unique_ptr<CatalogDb>> open(const std::string& target) {
    auto db = std::unique_ptr<PostgresDb>(new PostgresDb);
    // A server that does not answer is said within 10 s (a bench offline
    // must not hang an analysis on TCP's retries); the URI's own
    // connect_timeout, expanded from `dbname` after it, wins.
    const char* keys[] = {"connect_timeout", "dbname", nullptr};
    const char* values[] = {"10", target.c_str(), nullptr};
    db->conn_ = PQconnectdbParams(keys, values, /*expand_dbname=*/1);
    if (!db->conn_) return ioError("cannot reach the PostgreSQL catalog: out of memory");
    if (PQstatus(db->conn_) != CONNECTION_OK) {
      std::string msg = oneLine(PQerrorMessage(db->conn_));
      return ioError("cannot reach the PostgreSQL catalog " + describeTarget(target) + " (" + msg +
                     "); check the server is up and the address");
    }
    // CREATE TABLE IF NOT EXISTS says NOTICE for every table: not for users.
    PQsetNoticeProcessor(db->conn_, [](void*, const char*) {}, nullptr);
    const char* host = PQhost(db->conn_);
    db->where_ = std::string(PQdb(db->conn_)) + " on " + (host ? host : "?") + ":" + PQport(db->conn_);
    return std::unique_ptr<CatalogDb>(std::move(db));
  }

  Kind kind() const override { return Kind::kPostgres; }
  std::string describe() const override { return "PostgreSQL catalog " + where_; }

  Status exec(const std::string& sql, const std::vector<Value>& params) override { return run(sql, params, nullptr); }
  Result<std::vector<Row>> query(const std::string& sql, const std::vector<Value>& params) override {
    std::vector<Row> rows;
    FOG_RETURN_IF_ERROR(run(sql, params, &rows));
    return rows;
  }

 private:
  PostgresDb() = default;
  // `?` -> `$1`, `$2`, ... outside quoted text.
  static std::string numbered(const std::string& sql) {
    std::string out;
    int n = 0;
    bool quoted = false;
    for (char c : sql) {
      if (c == '\'') quoted = !quoted;
      if (c == '?' && !quoted) {
        out += '$' + std::to_string(++n);
      } else {
        out += c;
      }
    }
    return out;
  }
  Status run(const std::string& sql, const std::vector<Value>& params, std::vector<Row>* rows) {
    std::vector<const char*> values;
    for (const auto& p : params) values.push_back(p ? p->c_str() : nullptr);
    PGresult* res = params.empty()
                        ? PQexec(conn_, sql.c_str())
                        : PQexecParams(conn_, numbered(sql).c_str(), static_cast<int>(values.size()), nullptr,
                                       values.data(), nullptr, nullptr, 0);
    const auto status = PQresultStatus(res);
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
      std::string msg = oneLine(res ? PQresultErrorMessage(res) : PQerrorMessage(conn_));
      PQclear(res);
      if (PQstatus(conn_) != CONNECTION_OK)
        return ioError("the PostgreSQL catalog " + where_ + " went away (" + msg + "); nothing half-written is kept");
      return ioError("PostgreSQL catalog " + where_ + ": " + msg);
    }
    if (rows) {
      const int nr = PQntuples(res), nc = PQnfields(res);
      for (int r = 0; r < nr; ++r) {
        Row row;
        for (int c = 0; c < nc; ++c)
          row.emplace_back(PQgetisnull(res, r, c) ? Value{} : Value{std::string(PQgetvalue(res, r, c),
                                                                       static_cast<std::size_t>(PQgetlength(res, r, c)))});
        rows->push_back(std::move(row));
      }
    }
    PQclear(res);
    return Status::ok();
  }

  PGconn* conn_ = nullptr;
  std::string where_;
};

}  // namespace

bool isPostgresTarget(const std::string& t) {
  // Only libpq's URI form: a file or folder whose name holds "host=" or
  // "dbname=" (a folder named after a setting, an export) is a SQLite
  // catalog, never a server to connect to.
  return t.rfind("postgresql://", 0) == 0 || t.rfind("postgres://", 0) == 0;
}

Result<std::unique_ptr<CatalogDb>> CatalogDb::open(const std::string& target) {
  if (target.empty()) return invalidArgument("no catalog named: give --db FILE or --db postgresql://…");
  if (isPostgresTarget(target)) return PostgresDb::open(target);
  return SqliteDb::open(target);
}

std::string describeTarget(const std::string& target) {
  if (!isPostgresTarget(target)) return target;
  std::string t = target;
  const std::size_t scheme = t.find("://") + 3;
  const std::size_t at = t.find('@', scheme), slash = t.find('/', scheme);
  if (at != std::string::npos && (slash == std::string::npos || at < slash)) {
    const std::size_t colon = t.find(':', scheme);
    if (colon != std::string::npos && colon < at) t.replace(colon + 1, at - colon - 1, "***");
  }
  for (std::size_t p = t.find("password="); p != std::string::npos; p = t.find("password=", p + 1)) {
    const std::size_t end = t.find('&', p);
    t.replace(p + 9, (end == std::string::npos ? t.size() : end) - p - 9, "***");
  }
  return t;
}

Value numberValue(double v) {
  if (!std::isfinite(v)) return std::nullopt;
  // The shortest text that reads back as the same double (0.06, not
  // 0.059999999999999998), and never the locale's decimal comma: the GUI
  // runs under the user's locale, and the same catalog is read by the CLI
  // and PostgreSQL.
  char b[40];
  const auto r = std::to_chars(b, b + sizeof b, v);
  return std::string(b, r.ptr);
}
Value integerValue(long long v) { return std::to_string(v); }

double numberOf(const Value& v) {
  if (!v || v->empty()) return std::nan("");
  double d = 0.0;
  const char* end = v->data() + v->size();
  const auto r = std::from_chars(v->data(), end, d);
  return r.ec == std::errc() && r.ptr == end ? d : std::nan("");
}
long long integerOf(const Value& v, long long fallback) {
  if (!v || v->empty()) return fallback;
  long long n = 0;
  const char* end = v->data() + v->size();
  const auto r = std::from_chars(v->data(), end, n);
  return r.ec == std::errc() && r.ptr == end ? n : fallback;
}
std::string textOf(const Value& v) { return v ? *v : std::string(); }

}  // namespace fog::catalog
