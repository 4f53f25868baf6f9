#pragma once
// A byte link to a table controller: a serial line (a USB adapter, a
// pseudo-terminal) or a TCP connection. Abstract so that the remote driver
// can be tested over anything; the POSIX implementation below serves both
// kinds of link. Core may use POSIX, never Qt.
//
// Contracts: write() sends everything or fails; read() appends what arrives,
// waiting at most `timeout` for the first byte (0 bytes appended: nothing
// came); a link that is closed or failed gives kIoError ("connection closed
// by the controller", "... vanished: Input/output error") on that call and
// every later one. Bounded: no call waits longer than its timeout (write:
// writeTimeout). Not thread-safe: one thread uses a transport.

#include <chrono>
#include <memory>
#include <string>
#include <string_view>

#include "core/common/status.h"

namespace fog::table {

class ByteTransport {
 public:
  virtual ~ByteTransport() = default;
  virtual std::string description() const = 0;  // "tcp:127.0.0.1:5025", "serial /dev/ttyUSB1 at 115200 8N1"
  virtual Status write(std::string_view bytes) = 0;
  virtual Result<std::size_t> read(std::string& out, std::chrono::milliseconds timeout) = 0;
};

// "tcp:HOST:PORT" (HOST a numeric IPv4 address or "localhost") or the path
// of a serial device / pseudo-terminal (raw 8N1 at `baud`). kIoError with the
// system's reason when it cannot be opened or connected within connectTimeout.
Result<std::unique_ptr<ByteTransport>> openTransport(const std::string& address, int baud = 115200,
                                                     std::chrono::milliseconds connectTimeout = std::chrono::seconds(5),
                                                     std::chrono::milliseconds writeTimeout = std::chrono::seconds(2));

}  // namespace fog::table
