#pragma once
// fogbench-cli catalog index|units|unit|lot|push|refused (docs/catalog.md),
// and the catalog's update after a command stores a result.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_arguments.h"
#include "core/catalog/catalog.h"
#include "core/common/status.h"

namespace fog::app {

int catalogCommand(CliArguments& args);

// What a command's results went into (docs/catalog.md, "Where a catalog
// lives", "A bench offline").
struct CatalogUpdate {
  bool none = false;     // no catalog named and `folder` has none: nothing done
  std::string catalog;   // describe() of the catalog indexed into
  catalog::IndexReport index;
  // --db postgresql://…: the bench's own catalog (its folder's
  // fogbench-catalog.sqlite) is indexed, then its pending rows pushed.
  std::optional<catalog::SyncReport> shared;
  std::string note;      // the bench's own catalog could not be written: indexed straight into the server, why
};

// Indexes `paths` into the catalog `db` names (as --db: a SQLite file, a
// folder, or a postgresql:// URI, then through `folder`'s own catalog), or,
// when `db` is empty, into `folder`'s catalog: made when `create`, else only
// when it exists (`none` otherwise). The one path index, batch and every
// command that stores a result take.
Result<CatalogUpdate> updateCatalog(const std::string& db, const std::string& folder,
                                    const std::vector<std::string>& paths, bool create,
                                    const std::function<void(int, int)>& progress = {});

// "pushed 3 results to the PostgreSQL catalog …; none pending" or "the
// shared catalog … was not updated (why); 3 results pending in the SQLite
// catalog …: the next catalog index, batch or catalog push sends them".
std::string sharedCatalogText(const catalog::SyncReport& shared, const std::string& local);

// After a batch re-analysis: `files` re-indexed into the catalog (as
// updateCatalog, never creating one). Prints what it did in one line; an
// error (the shared catalog not reached included) leaves the sessions' new
// results stored.
Status updateCatalogAfterBatch(const std::string& db, const std::string& folder, const std::vector<std::string>& files);

// After analyze, run --out or a board/table run stored a result in
// `sessionPath`: that file re-indexed into the catalog `db` names, else into
// its folder's catalog when it has one. Never fails the analysis: a catalog
// that cannot be reached is said on stderr with how to catch up (`catalog
// index DIR`). Says "Catalog updated: …" on stdout unless `quiet` (--json).
void updateCatalogAfterAnalysis(const std::string& db, const std::string& sessionPath, bool quiet);

}  // namespace fog::app
