#pragma once
// A real sampling board on a serial port as an acquisition::ByteSource,
// through the POSIX terminal interface (termios, poll): Qt-free, so the
// command line records a board in every build.
//
//   SerialSettings s; s.port = "/dev/ttyUSB0"; s.baudRate = 921600;
//   auto source = SerialSource::open(s);
//   acquisition::acquire(**source, options, &stop, observer);
//
// Contracts:
//  - One thread reads (the acquisition's); queueForDevice() may be called
//    from any thread.
//  - open() applies the line settings at once and checks that the device
//    kept them (a pseudo-terminal is always 8N1: 8E1 on one is refused). The
//    baud rate is one a Linux driver takes by name (1200 .. 4000000). A port
//    another program holds (flock) is refused: one program per port.
//  - read() appends what has arrived, waiting at most `timeout` for the first
//    byte; 0 bytes means the line was quiet. A serial line never ends by
//    itself: endOfStream is never reported (the acquisition ends the run on
//    the board's "done" STATUS, a stall limit, or the operator's stop).
//  - A port that disappears (USB adapter unplugged, the board emulator's pty
//    closed: EIO or a hang-up, or the device node gone while the line is
//    quiet) returns kIoError "serial port /dev/ttyUSB0 vanished: <reason>";
//    the source is then done and every later read() fails alike.
//  - The host-to-board direction: the port is opened read-write (read-only
//    when the system refuses writing; then queueForDevice() returns false).
//    The queued bytes go out in read() (and flushToDevice()), in the
//    acquisition thread, without blocking it; nothing waits for a reply.
//  - Errors are fog::Status values; nothing throws.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/acquisition/byte_source.h"
#include "core/common/status.h"

namespace fog::serial {

enum class Parity { kNone, kEven, kOdd };

struct SerialSettings {
  std::string port;       // "/dev/ttyUSB0", or a name from availablePorts() ("ttyUSB0")
  int baudRate = 921600;  // bits per second
  Parity parity = Parity::kNone;
  int dataBits = 8;       // 5..8
  int stopBits = 1;       // 1 or 2

  // An error for a setting no serial port takes, or ok.
  Status validate() const;
  // "921600 8N1".
  std::string summary() const;
};

Result<Parity> parseParity(const std::string& text);  // none | even | odd

struct PortInfo {
  std::string name;            // "ttyUSB0"
  std::string systemLocation;  // "/dev/ttyUSB0"
  std::string description;     // from the driver, may be empty
  std::string manufacturer;
  std::string serialNumber;
};

// The serial ports the system has now (may be empty), sorted by name:
// USB/ACM adapters with what they say of themselves, on-board UARTs.
std::vector<PortInfo> availablePorts();

class SerialSource : public acquisition::ByteSource {
 public:
  // Opens and configures the port. Errors: invalid settings
  // (kInvalidArgument), a port that does not exist, is busy or may not be
  // opened (kIoError, with the system's reason).
  static Result<std::unique_ptr<SerialSource>> open(const SerialSettings& settings);
  ~SerialSource() override;

  Result<acquisition::ReadOutcome> read(std::vector<std::uint8_t>& out, std::chrono::milliseconds timeout) override;
  // "serial /dev/ttyUSB0 at 921600 8N1".
  std::string description() const override;
  bool queueForDevice(std::span<const std::uint8_t> bytes) override;
  void flushToDevice(std::chrono::milliseconds timeout) override;

 private:
  SerialSource(int fd, SerialSettings settings);
  SerialSource(const SerialSource&) = delete;
  SerialSource& operator=(const SerialSource&) = delete;
  // Writes what is queued, waiting at most `timeout` for room; what does not
  // fit stays queued, first in line.
  void writeQueued(std::chrono::milliseconds timeout);
  Status vanished(const std::string& why);

  int fd_ = -1;  // -1 once the port has failed
  SerialSettings settings_;
  Status failed_;  // set once the port has failed
  bool writable_ = false;
  std::mutex outboxMutex_;
  std::vector<std::uint8_t> outbox_;  // queued for the device, not yet handed to the port
};

}  // namespace fog::serial
