#pragma once
// Reading a whole input file in bounded time and memory.
//
// Only a regular file (a symbolic link is followed to one) is read: a FIFO
// would block the reader forever, and a device such as /dev/zero or
// /dev/urandom never ends (reading one whole once exhausted 2 GB). The size
// is checked before a byte is read, and reading stops one byte past the
// bound, so a file that grows while it is read (a recorder still writing)
// cannot take more than the bound either.

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace fog {

// Refuses (kIoError / kInvalidArgument, with what to do) a path that does
// not exist, is a folder, is not a regular file, or holds more than maxBytes.
// `what` names the file in messages ("the table file", "a raw stream").
Status checkRegularFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// The file's bytes, after checkRegularFile().
Result<std::vector<std::uint8_t>> readRegularFile(const std::string& path, std::uint64_t maxBytes,
                                                  const std::string& what);
Result<std::string> readRegularTextFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// "512 MiB", "64 KiB", "100 bytes": a bound as the messages write it.
std::string byteCount(std::uint64_t bytes);

}  // namespace fog
