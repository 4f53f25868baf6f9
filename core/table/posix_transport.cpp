// POSIX byte transport: TCP (connect with a timeout) and serial / pty
// devices (termios raw).
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/baud_rates.h"
#include "core/table/transport.h"

namespace fog::table {

namespace {

using Clock = std::chrono::steady_clock;

class FdTransport : public ByteTransport {
 public:
  FdTransport(int fd, std::string description, bool socket, std::chrono::milliseconds writeTimeout)
      : fd_(fd), description_(std::move(description)), socket_(socket), writeTimeout_(writeTimeout) {}
  ~FdTransport() override {
    if (fd_ >= 0) ::close(fd_);
  }
  std::string description() const override { return description_; }

  Status write(std::string_view bytes) override {
    if (!broken_.isOk()) return broken_;
    const auto giveUp = Clock::now() + writeTimeout_;
    while (!bytes.empty()) {
      const ssize_t n = socket_ ? ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL)
                                : ::write(fd_, bytes.data(), bytes.size());
      if (n > 0) {
        bytes.remove_prefix(static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno != EAGAIN && errno != EINTR) return lost(failed(errno));
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(giveUp - Clock::now());
      if (left.count() <= 0) return lost("no room to write for " + std::to_string(writeTimeout_.count()) + " ms");
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) < 0 && errno != EINTR) return lost(std::strerror(errno));
      if (p.revents & (POLLERR | POLLNVAL)) return lost("the link failed");
    }
    return Status::ok();
  }

  Result<std::size_t> read(std::string& out, std::chrono::milliseconds timeout) override {
    if (!broken_.isOk()) return broken_;
    pollfd p{fd_, POLLIN, 0};
    const int rc = ::poll(&p, 1, static_cast<int>(std::max<long long>(0, timeout.count())));
    if (rc < 0) {
      if (errno == EINTR) return std::size_t{0};
      return lost(std::strerror(errno));
    }
    if (rc == 0) return std::size_t{0};
    char buf[4096];
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n > 0) {
      out.append(buf, static_cast<std::size_t>(n));
      return static_cast<std::size_t>(n);
    }
    if (n == 0) return lost(socket_ ? "connection closed by the controller" : "the device closed");
    if (errno == EAGAIN || errno == EINTR) return std::size_t{0};
    if (socket_ && (errno == ECONNRESET || errno == EPIPE)) return lost(failed(errno));
    return lost(std::string("vanished: ") + std::strerror(errno));
  }

 private:
  // A controller that closes its end shows as EOF on a read, or as EPIPE /
  // ECONNRESET on whichever call comes next when a line was in flight: one
  // reason either way.
  std::string failed(int err) const {
    if (socket_ && (err == EPIPE || err == ECONNRESET))
      return std::string("connection closed by the controller (") + std::strerror(err) + ")";
    return std::strerror(err);
  }
  Status lost(const std::string& why) {
    broken_ = ioError("table link " + description_ + " lost: " + why);
    return broken_;
  }

  int fd_;
  std::string description_;
  bool socket_;
  std::chrono::milliseconds writeTimeout_;
  Status broken_;
};

Result<std::unique_ptr<ByteTransport>> openTcp(const std::string& address, std::chrono::milliseconds connectTimeout,
                                               std::chrono::milliseconds writeTimeout) {
  const std::string rest = address.substr(4);
  const auto colon = rest.rfind(':');
  if (colon == std::string::npos) return invalidArgument("table address '" + address + "' is not tcp:HOST:PORT");
  std::string host = rest.substr(0, colon);
  const std::string portText = rest.substr(colon + 1);
  char* end = nullptr;
  const long port = std::strtol(portText.c_str(), &end, 10);
  if (portText.empty() || *end != '\0' || port < 1 || port > 65535)
    return invalidArgument("table address '" + address + "': port must be 1 .. 65535");
  if (host == "localhost") host = "127.0.0.1";
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, host.c_str(), &sa.sin_addr) != 1)
    return invalidArgument("table address '" + address + "': HOST must be a numeric IPv4 address or localhost");
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return ioError(std::string("cannot make a socket: ") + std::strerror(errno));
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&sa), sizeof sa) != 0) {
    if (errno != EINPROGRESS) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      return ioError("cannot connect to the table controller at " + address + ": " + why);
    }
    pollfd p{fd, POLLOUT, 0};
    const int rc = ::poll(&p, 1, static_cast<int>(connectTimeout.count()));
    int err = 0;
    socklen_t len = sizeof err;
    if (rc <= 0 || ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) != 0 || err != 0) {
      const std::string why = rc == 0 ? "no answer within " + std::to_string(connectTimeout.count()) + " ms"
                                      : std::strerror(err ? err : errno);
      ::close(fd);
      return ioError("cannot connect to the table controller at " + address + ": " + why);
    }
  }
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return std::unique_ptr<ByteTransport>(std::make_unique<FdTransport>(fd, "tcp:" + host + ":" + std::to_string(port), true, writeTimeout));
}

}  // namespace

Result<std::unique_ptr<ByteTransport>> openTransport(const std::string& address, int baud,
                                                     std::chrono::milliseconds connectTimeout,
                                                     std::chrono::milliseconds writeTimeout) {
  if (address.rfind("tcp:", 0) == 0) return openTcp(address, connectTimeout, writeTimeout);
  if (address.empty()) return invalidArgument("no table address given (tcp:HOST:PORT or a device path)");
  const speed_t code = baudRateCode(baud);
  if (code == B0)
    return invalidArgument("table link baud rate " + std::to_string(baud) + " is not supported; use one of " +
                           acceptedBaudRates());
  const int fd = ::open(address.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return ioError("cannot open the table controller's port " + address + ": " + std::strerror(errno));
  termios t{};
  if (::tcgetattr(fd, &t) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return ioError(address + " is not a serial device: " + why);
  }
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  cfsetspeed(&t, code);
  if (::tcsetattr(fd, TCSANOW, &t) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return ioError("cannot set " + address + " to " + std::to_string(baud) + " 8N1: " + why);
  }
  return std::unique_ptr<ByteTransport>(std::make_unique<FdTransport>(
      fd, "serial " + address + " at " + std::to_string(baud) + " 8N1", false, writeTimeout));
}

}  // namespace fog::table
