#pragma once
// The catalog's database, behind one small interface so that the same schema,
// statements and tests serve both back ends (docs/catalog.md):
//  - SQLite: a file (embedded; the default, one per sessions folder);
//  - PostgreSQL: a shared server, named only by a libpq URI
//    (`postgresql://…` or `postgres://…`), through libpq. Anything else,
//    "host=… dbname=…" included, names a SQLite file.
// Statements use `?` placeholders; every value is bound as text (NULL for an
// empty optional) and read back as text, so both back ends see the same SQL
// and the same values. Numbers are written with the fewest significant
// digits that read back as the same double (at most 17).
// Qt-free; errors are Status values; nothing throws.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace fog::catalog {

using Value = std::optional<std::string>;  // nullopt: SQL NULL
using Row = std::vector<Value>;

class CatalogDb {
 public:
  enum class Kind { kSqlite, kPostgres };

  // Opens (and for SQLite creates) the database named by `target`. A
  // PostgreSQL server that does not answer is a kIoError naming the server
  // (never its password) and saying what to do.
  static Result<std::unique_ptr<CatalogDb>> open(const std::string& target);
  virtual ~CatalogDb() = default;

  virtual Kind kind() const = 0;
  // "SQLite catalog /data/sessions/fogbench-catalog.sqlite",
  // "PostgreSQL catalog fogbench on /run/postgresql:5432" (no password).
  virtual std::string describe() const = 0;
  virtual Status exec(const std::string& sql, const std::vector<Value>& params = {}) = 0;
  virtual Result<std::vector<Row>> query(const std::string& sql, const std::vector<Value>& params = {}) = 0;
};

// Whether `target` names a PostgreSQL server rather than a SQLite file: it
// starts with postgresql:// or postgres://.
bool isPostgresTarget(const std::string& target);

// `target` as it may be shown: a URI's password (user:PASSWORD@,
// password=…) replaced by "***".
std::string describeTarget(const std::string& target);

// Text of a number as bound (round-trip exact); NULL for NaN/inf.
Value numberValue(double v);
Value integerValue(long long v);
// A NULL or unparsable value reads as NaN / `fallback`.
double numberOf(const Value& v);
long long integerOf(const Value& v, long long fallback = 0);
std::string textOf(const Value& v);

}  // namespace fog::catalog
