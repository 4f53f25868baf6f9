#include "core/common/file_read.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace fog {

namespace fs = std::filesystem;

std::string byteCount(std::uint64_t bytes) {
  if (bytes >= (1ull << 20) && bytes % (1ull << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (1ull << 10) && bytes % (1ull << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

Status checkRegularFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  std::error_code ec;
  const auto status = fs::status(path, ec);  // follows symbolic links
  if (ec || !fs::exists(status)) return ioError(path + " does not exist (cannot read it); check the path");
  if (fs::is_directory(status)) return ioError(path + " is a folder, not " + what);
  if (!fs::is_regular_file(status)) {
    const char* kind = fs::is_fifo(status)                                     ? "a FIFO (named pipe)"
                       : fs::is_character_file(status) || fs::is_block_file(status) ? "a device"
                       : fs::is_socket(status)                                 ? "a socket"
                                                                               : "not a regular file";
    std::string link;
    if (fs::is_symlink(fs::symlink_status(path, ec)))
      link = " (a link to " + fs::read_symlink(path, ec).string() + ")";
    return invalidArgument(path + link + " is " + std::string(kind) + ", not " + what +
                           ": only regular files are read (a pipe or a device may never end); copy the data into a "
                           "file first");
  }
  const auto size = fs::file_size(path, ec);
  if (ec) return ioError("cannot read " + path + ": " + ec.message());
  if (size > maxBytes)
    return invalidArgument(path + " holds " + std::to_string(size) + " bytes, more than the " + byteCount(maxBytes) +
                           " that " + what + " may hold (docs/reliability.md): split the recording");
  return Status::ok();
}

namespace {

template <typename Bytes>
Result<Bytes> readBounded(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  FOG_RETURN_IF_ERROR(checkRegularFile(path, maxBytes, what));
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return ioError("cannot open " + path + " for reading; check its permissions");
  Bytes out;
  // The size was checked: the whole file in one allocation (growing by
  // doubling would hold up to twice the bound for a moment).
  std::error_code ec;
  out.reserve(static_cast<std::size_t>(fs::file_size(path, ec)));
  char buf[1 << 16];
  std::size_t n;
  bool tooLong = false;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    if (out.size() + n > maxBytes) {
      tooLong = true;
      break;
    }
    out.insert(out.end(), buf, buf + n);
  }
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return ioError("error while reading " + path);
  if (tooLong)
    return invalidArgument(path + " grew beyond the " + byteCount(maxBytes) + " that " + what +
                           " may hold while it was read; read it when it is complete");
  return out;
}

}  // namespace

Result<std::vector<std::uint8_t>> readRegularFile(const std::string& path, std::uint64_t maxBytes,
                                                  const std::string& what) {
  return readBounded<std::vector<std::uint8_t>>(path, maxBytes, what);
}

Result<std::string> readRegularTextFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  return readBounded<std::string>(path, maxBytes, what);
}

}  // namespace fog
