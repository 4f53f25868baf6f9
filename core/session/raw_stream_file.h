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

// The largest raw stream file read: the bytes and the decoded recording of
// 512 MiB (about 3.6 h of the bench's 39 kB/s stream) take some 1.2 GB less
// the analysis; the budget is in docs/reliability.md.
inline constexpr std::uint64_t kMaxRawStreamBytes = 512ull << 20;

struct RawStreamFile {
  std::vector<std::uint8_t> bytes;
  Recording recording;
};

// Reads the file (a regular file of at most kMaxRawStreamBytes: a FIFO or a
// device is refused, file_read.h) and decodes it. Errors name the path.
Result<RawStreamFile> readRawStreamFile(const std::string& path);

}  // namespace fog::session
