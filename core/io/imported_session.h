#pragma once
// Turning imported data into a session file, the same for the command line
// and the GUI: the imported metadata (with where it came from), the decoded
// samples, no raw stream (there is none), marked complete.

#include <string>

#include "core/common/status.h"
#include "core/io/csv_import.h"

namespace fog::io {

// `from` says where the files were ("run7/", "a.json, t.csv, g.csv"); it is
// the source only when the import left none. An empty software version or
// creation time is filled in. Refuses to
// overwrite an existing file (as SessionWriter::create).
Status saveImportedSession(const ImportedSession& imported, const std::string& from, const std::string& path);

}  // namespace fog::io
