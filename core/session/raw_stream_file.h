#pragma once
// A raw sampling-board stream saved to a file (`run --save-raw`, a capture of
// the board's serial line): what analyze, diagnose, noise and report read
// when their FILE is not a session (session::isSqliteFile() decides first, so
// a damaged session is never decoded as a stream).

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/common/status.h"

namespace fog::session {

// The largest raw stream file read: 160 MiB, some 70 min of the bench's
// 39 kB/s stream (a plan is at most 1 h). Reading, decoding and analysing a
// 148 MiB stream peaks at 704 MB (analyze; diagnose 741 MB), within the 1 GB
// budget of docs/reliability.md.
inline constexpr std::uint64_t kMaxRawStreamBytes = 160ull << 20;

struct RawStreamFile {
  std::vector<std::uint8_t> bytes;
  Recording recording;
};

// Reads the file (a regular file of at most kMaxRawStreamBytes: a FIFO or a
// device is refused, file_read.h) and decodes it. Errors name the path.
// benchPulseEquivalentDeg: for a stream that does not state its pulse
// equivalent (protocol::decodeRecording).
Result<RawStreamFile> readRawStreamFile(const std::string& path, double benchPulseEquivalentDeg = 0.0);

}  // namespace fog::session
