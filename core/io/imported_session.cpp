#include "core/io/imported_session.h"

#include "core/common/version.h"
#include "core/session/session_file.h"

namespace fog::io {

Status saveImportedSession(const ImportedSession& imported, const std::string& from, const std::string& path) {
  SessionInfo info = imported.info;
  // The importer's source already says where the files were and who recorded
  // them ("import run7 (recorded by: ...)"); it is not wrapped again.
  if (info.source.empty()) info.source = "import " + from;
  if (info.softwareVersion.empty()) info.softwareVersion = std::string("unknown; imported by fogbench ") + FOG_VERSION;
  if (info.createdUtc.empty()) info.createdUtc = session::utcNow();
  FOG_ASSIGN_OR_RETURN(auto writer, session::SessionWriter::create(path, info));
  if (auto s = writer->storeRecording(imported.recording); !s.isOk()) return s;
  return writer->finish(true, "");
}

}  // namespace fog::io
