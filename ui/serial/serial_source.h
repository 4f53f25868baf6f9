#pragma once
// A real sampling board on a serial port as an acquisition::ByteSource,
// through QSerialPort (Qt Core + SerialPort only: no widgets, no event loop).
//
//   SerialSettings s; s.port = "/dev/ttyUSB0"; s.baudRate = 921600;
//   auto source = SerialSource::open(s);          // in the acquisition thread
//   acquisition::acquire(**source, options, &stop, observer);
//
// Contracts:
//  - Thread affinity: QSerialPort is a QObject. open() and every read() must
//    run in the same thread (the acquisition thread); the object may be
//    destroyed there too. read() uses the blocking API (waitForReadyRead),
//    which needs no running event loop. A QCoreApplication must exist in the
//    process (the GUI has one; ensureQtCore() makes one for the CLI).
//  - read() appends what has arrived, waiting at most `timeout` for the first
//    byte; 0 bytes means the line was quiet. A serial line never ends by
//    itself: endOfStream is never reported (the acquisition ends the run on
//    the board's "done" STATUS, a stall limit, or the operator's stop).
//  - A port that disappears (USB adapter unplugged, the board emulator's pty
//    closed) or fails returns kIoError "serial port /dev/ttyUSB0 vanished:
//    <reason>"; the source is then done and every later read() fails alike.
//  - The host-to-board direction: the port is opened read-write (read-only
//    when the system refuses writing; then queueForDevice() returns false).
//    queueForDevice() is thread-safe; the queued bytes go out in read() (and
//    flushToDevice()), in the acquisition thread. Nothing waits for a reply.
//  - Errors are fog::Status values; nothing throws.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "acquisition/byte_source.h"
#include "common/status.h"

class QSerialPort;

namespace fog::serial {

enum class Parity { kNone, kEven, kOdd };

struct SerialSettings {
  std::string port;       // "/dev/ttyUSB0", "COM3" or a name from availablePorts()
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

// The serial ports the system reports now (may be empty). Needs a
// QCoreApplication like SerialSource.
std::vector<PortInfo> availablePorts();

// Makes a QCoreApplication when the process has none (command-line use).
void ensureQtCore();

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
  void writeQueued(int timeoutMs);
  SerialSource(std::unique_ptr<QSerialPort> port, SerialSettings settings);
  Status vanished(const std::string& why);

  std::unique_ptr<QSerialPort> port_;
  SerialSettings settings_;
  Status failed_;  // set once the port has failed
  bool writable_ = false;
  std::mutex outboxMutex_;
  std::vector<std::uint8_t> outbox_;  // queued for the device, not yet handed to the port
};

}  // namespace fog::serial
