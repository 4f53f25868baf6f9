#include "core/session/raw_stream_file.h"

#include "core/common/file_read.h"
#include "core/protocol/recording_builder.h"

namespace fog::session {

Result<RawStreamFile> readRawStreamFile(const std::string& path, double benchPulseEquivalentDeg) {
  RawStreamFile out;
  FOG_ASSIGN_OR_RETURN(out.bytes, readRegularFile(path, kMaxRawStreamBytes, "a raw sampling-board stream"));
  auto recording = protocol::decodeRecording(out.bytes, benchPulseEquivalentDeg);
  if (!recording) return Status(recording.status().code(), path + ": " + recording.status().message());
  out.recording = std::move(*recording);
  return out;
}

}  // namespace fog::session
