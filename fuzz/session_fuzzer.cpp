// libFuzzer entry for the session reader: arbitrary bytes as a .fbs file.
//
// The input is written to a private file and opened with
// SessionReader::open; when it opens, everything is read (metadata, state,
// the raw stream, the decoded samples or a decode of the raw stream, every
// result). Each call must return a value or a Status with a message, never
// crash, hang or leak; a file that is not a session must be refused by open.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/session/session_file.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

const std::string& scratchPath() {
  static const std::string path = "/tmp/fog_fuzz_session_" + std::to_string(::getpid()) + ".fbs";
  return path;
}

void removeAll(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) ::unlink((path + suffix).c_str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchPath();
  removeAll(path);
  {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const bool looks = fog::session::looksLikeSession(path);
  auto reader = fog::session::SessionReader::open(path);
  if (!reader) {
    check(!reader.status().message().empty());
  } else {
    // Only a fogbench session opens.
    check(looks);
    const auto& r = **reader;
    check(r.isReadOnly());
    (void)r.info();
    (void)r.schemaVersion();
    if (!r.complete()) (void)r.incompleteReason();
    auto raw = r.rawBytes();
    if (raw) check(raw->size() == r.rawByteCount());
    else check(!raw.status().message().empty());
    (void)r.hasStoredRecording();
    auto rec = r.recording();
    if (!rec) check(!rec.status().message().empty());
    auto results = r.results();
    if (!results) check(!results.status().message().empty());
  }
  removeAll(path);
  return 0;
}
