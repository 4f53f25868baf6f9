#pragma once
// fogbench-cli catalog index|units|unit|lot|push|refused (docs/catalog.md).

#include <string>
#include <vector>

#include "app/cli_arguments.h"
#include "core/common/status.h"

namespace fog::app {

int catalogCommand(CliArguments& args);

// After a batch re-analysis: indexes `files` into the catalog `db` names
// (as --db: a file, a folder or a PostgreSQL address), or, when `db` is
// empty, into `folder`'s catalog when it has one. Prints what it did in one
// line; an error leaves the sessions' new results stored.
Status updateCatalogAfterBatch(const std::string& db, const std::string& folder, const std::vector<std::string>& files);

}  // namespace fog::app
