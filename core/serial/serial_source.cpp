#include "core/serial/serial_source.h"

#include <dirent.h>
#include <fcntl.h>
#include <linux/serial.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/common/baud_rates.h"

namespace fog::serial {

namespace {

// "ttyUSB0" names /dev/ttyUSB0; a path is used as given.
std::string devicePath(const std::string& port) { return port.find('/') == std::string::npos ? "/dev/" + port : port; }

std::string firstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

tcflag_t sizeFlag(int dataBits) {
  switch (dataBits) {
    case 5: return CS5;
    case 6: return CS6;
    case 7: return CS7;
    default: return CS8;
  }
}

}  // namespace

Status SerialSettings::validate() const {
  if (port.empty()) return invalidArgument("no serial port given (--port DEVICE; fogbench-cli ports lists them)");
  if (baudRate <= 0) return invalidArgument("the baud rate must be > 0, got " + std::to_string(baudRate));
  if (baudRateCode(baudRate) == B0)
    return invalidArgument("baud rate " + std::to_string(baudRate) + " is not one a serial driver takes; use one of " +
                           acceptedBaudRates());
  if (dataBits < 5 || dataBits > 8) return invalidArgument("data bits must be 5..8, got " + std::to_string(dataBits));
  if (stopBits != 1 && stopBits != 2) return invalidArgument("stop bits must be 1 or 2, got " + std::to_string(stopBits));
  return Status::ok();
}

std::string SerialSettings::summary() const {
  const char p = parity == Parity::kEven ? 'E' : parity == Parity::kOdd ? 'O' : 'N';
  return std::to_string(baudRate) + " " + std::to_string(dataBits) + p + std::to_string(stopBits);
}

Result<Parity> parseParity(const std::string& t) {
  if (t == "none") return Parity::kNone;
  if (t == "even") return Parity::kEven;
  if (t == "odd") return Parity::kOdd;
  return invalidArgument("parity must be none, even or odd, got '" + t + "'");
}

std::vector<PortInfo> availablePorts() {
  // Every tty the kernel has a device for (/sys/class/tty/NAME/device) that
  // is a port: USB and ACM adapters, and on-board UARTs that report a UART
  // type (the 8250 driver makes ttyS0..31 whether or not a UART is there).
  std::vector<PortInfo> out;
  DIR* dir = ::opendir("/sys/class/tty");
  if (!dir) return out;
  while (const dirent* e = ::readdir(dir)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    const std::string sys = "/sys/class/tty/" + name + "/device";
    struct stat st {};
    if (::stat(sys.c_str(), &st) != 0) continue;
    const std::string path = "/dev/" + name;
    if (name.rfind("ttyS", 0) == 0) {
      const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
      if (fd < 0) continue;
      serial_struct info{};
      const bool real = ::ioctl(fd, TIOCGSERIAL, &info) == 0 && info.type != PORT_UNKNOWN;
      ::close(fd);
      if (!real) continue;
    }
    // USB adapters describe themselves on their USB device, two levels up.
    PortInfo p{name, path, firstLine(sys + "/../product"), firstLine(sys + "/../manufacturer"),
               firstLine(sys + "/../serial")};
    if (p.description.empty()) p.description = firstLine(sys + "/../../product");
    if (p.manufacturer.empty()) p.manufacturer = firstLine(sys + "/../../manufacturer");
    if (p.serialNumber.empty()) p.serialNumber = firstLine(sys + "/../../serial");
    out.push_back(std::move(p));
  }
  ::closedir(dir);
  std::sort(out.begin(), out.end(), [](const PortInfo& a, const PortInfo& b) { return a.name < b.name; });
  return out;
}

Result<std::unique_ptr<SerialSource>> SerialSource::open(const SerialSettings& settings) {
  FOG_RETURN_IF_ERROR(settings.validate());
  const std::string path = devicePath(settings.port);
  auto refused = [&](const std::string& why) { return ioError("cannot open serial port " + settings.port + ": " + why); };
  // Read-write for the optional host-to-board commands; a port the system
  // lets us only read still records.
  bool writable = true;
  int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0 && errno == EACCES) {
    writable = false;
    fd = ::open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  }
  if (fd < 0) return refused(std::strerror(errno));
  auto source = std::unique_ptr<SerialSource>(new SerialSource(fd, settings));
  source->writable_ = writable;
  // One program per port: a second one (another fogbench, a terminal
  // program that locks) is refused instead of sharing the bytes.
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
    return refused(errno == EWOULDBLOCK ? "the port is in use by another program" : std::strerror(errno));
  termios t{};
  if (::tcgetattr(fd, &t) != 0) return refused(std::string("not a serial port (") + std::strerror(errno) + ")");
  // Raw 8-bit bytes, no echo, no flow control, the receiver on; the line's
  // settings applied at once.
  ::cfmakeraw(&t);
  t.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  t.c_cflag |= CLOCAL | CREAD | sizeFlag(settings.dataBits);
  if (settings.parity != Parity::kNone) t.c_cflag |= PARENB;
  if (settings.parity == Parity::kOdd) t.c_cflag |= PARODD;
  if (settings.stopBits == 2) t.c_cflag |= CSTOPB;
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  ::cfsetspeed(&t, baudRateCode(settings.baudRate));
  if (::tcsetattr(fd, TCSANOW, &t) != 0)
    return ioError("cannot open serial port " + settings.port + " for " + settings.summary() + ": " +
                   std::strerror(errno));
  // A device may take tcsetattr and keep other settings (a pseudo-terminal
  // is always 8 bits without parity): what it kept is checked.
  termios kept{};
  const tcflag_t line = CSIZE | PARENB | PARODD | CSTOPB;
  if (::tcgetattr(fd, &kept) != 0 || (kept.c_cflag & line) != (t.c_cflag & line))
    return ioError("cannot open serial port " + settings.port + " for " + settings.summary() +
                   ": the device does not take these settings (a pseudo-terminal is always 8N1)");
  // The driver's buffer is not cleared: whatever arrives from here on is
  // what the session stores (the decoder resynchronises on stale bytes).
  return source;
}

SerialSource::SerialSource(int fd, SerialSettings settings) : fd_(fd), settings_(std::move(settings)) {}

SerialSource::~SerialSource() {
  if (fd_ >= 0) ::close(fd_);
}

Status SerialSource::vanished(const std::string& why) {
  failed_ = ioError("serial port " + settings_.port + " vanished: " + why);
  ::close(fd_);
  fd_ = -1;
  return failed_;
}

bool SerialSource::queueForDevice(std::span<const std::uint8_t> bytes) {
  if (!writable_) return false;
  std::lock_guard lock(outboxMutex_);
  // A board that never reads cannot make this grow without bound: commands
  // are a few dozen bytes per test point.
  outbox_.insert(outbox_.end(), bytes.begin(), bytes.end());
  return true;
}

void SerialSource::writeQueued(std::chrono::milliseconds timeout) {
  std::vector<std::uint8_t> bytes;
  {
    std::lock_guard lock(outboxMutex_);
    bytes.swap(outbox_);
  }
  std::size_t sent = 0;
  const auto giveUp = std::chrono::steady_clock::now() + timeout;
  while (fd_ >= 0 && sent < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + sent, bytes.size() - sent);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) break;  // the read that follows says what happened
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(giveUp - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd_, POLLOUT, 0};
    ::poll(&p, 1, static_cast<int>(left.count()));
  }
  if (sent < bytes.size()) {
    // The rest goes out first next time.
    std::lock_guard lock(outboxMutex_);
    outbox_.insert(outbox_.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(sent), bytes.end());
  }
}

void SerialSource::flushToDevice(std::chrono::milliseconds timeout) {
  if (failed_.isOk() && writable_) writeQueued(timeout);
}

Result<acquisition::ReadOutcome> SerialSource::read(std::vector<std::uint8_t>& out,
                                                    std::chrono::milliseconds timeout) {
  if (!failed_.isOk()) return failed_;
  if (writable_) writeQueued(std::chrono::milliseconds(0));
  pollfd p{fd_, POLLIN, 0};
  const int rc = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, timeout.count())));
  if (rc < 0) {
    if (errno == EINTR) return acquisition::ReadOutcome{0, false};
    return vanished(std::strerror(errno));
  }
  if (rc == 0) {
    // A quiet line, unless the device node itself has gone (some drivers
    // report an unplugged adapter only as silence).
    struct stat st {};
    if (::stat(devicePath(settings_.port).c_str(), &st) != 0) return vanished("the device no longer exists");
    return acquisition::ReadOutcome{0, false};
  }
  std::uint8_t buffer[8192];
  const ssize_t n = ::read(fd_, buffer, sizeof buffer);
  if (n > 0) {
    out.insert(out.end(), buffer, buffer + n);
    return acquisition::ReadOutcome{static_cast<std::size_t>(n), false};
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return acquisition::ReadOutcome{0, false};
  // 0 bytes from a readable tty is a hang-up; an error (EIO) is a device
  // that has gone (a pulled adapter, the emulator's pty closed).
  return vanished(n == 0 ? "the line hung up" : std::strerror(errno));
}

std::string SerialSource::description() const { return "serial " + settings_.port + " at " + settings_.summary(); }

}  // namespace fog::serial
