#pragma once
// A table controller on a localhost TCP port for the desk tests of the table
// panel (tests/ui/table_panel_test.cpp) and the emergency line: it
// serves the remote protocol with the emulator's own code (EmulatedTable +
// TableServer, as fogbench-table-emu does) until told to hang, and records
// every line that arrives, on every connection, with the steady_clock time
// it arrived. A hung controller still accepts connections and reads (so the
// time an emergency stop's bytes arrive is measured), but answers nothing —
// what a controller whose firmware is stuck does.
//
// Its own thread runs the sockets (poll with a 2-ms tick), so the time of
// arrival does not depend on the GUI thread under test. Thread-safe: the
// test thread reads lines() and sets hang() while it runs.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/table/emulated_table.h"

namespace fogtest {

class FakeTableController {
 public:
  using Clock = std::chrono::steady_clock;
  struct Line {
    int connection = 0;  // 1 for the first connection accepted, 2 for the next, ...
    std::string text;
    Clock::time_point at;
  };

  // hangFromStart: accept, read and record, never answer (a controller that
  // takes the connection and then says nothing).
  explicit FakeTableController(bool hangFromStart = false) : server_(table_), hung_(hangFromStart) {
    listen_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof sa;
    if (listen_ < 0 || ::bind(listen_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0 ||
        ::listen(listen_, 16) != 0 || ::getsockname(listen_, reinterpret_cast<sockaddr*>(&sa), &len) != 0)
      return;
    port_ = ntohs(sa.sin_port);
    thread_ = std::thread([this] { run(); });
  }
  ~FakeTableController() {
    quit_ = true;
    if (thread_.joinable()) thread_.join();
    for (auto& c : clients_) ::close(c.fd);
    if (listen_ >= 0) ::close(listen_);
  }
  FakeTableController(const FakeTableController&) = delete;
  FakeTableController& operator=(const FakeTableController&) = delete;

  bool listening() const { return port_ != 0; }
  std::string address() const { return "tcp:127.0.0.1:" + std::to_string(port_); }
  // From now on nothing is answered (lines are still read and recorded).
  void hang() { hung_ = true; }
  // From now on no new connection is taken (they are refused); those open
  // stay. Returns once the listening socket is closed.
  void stopListening() {
    stopListening_ = true;
    for (int i = 0; i < 500 && !listenerClosed_; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::vector<Line> lines() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return lines_;
  }
  int connections() const { return accepted_; }
  // The first line `text` (case as sent) that arrived at or after `since`; none: Clock::time_point{}.
  Line firstLine(const std::string& text, Clock::time_point since = {}) const {
    for (const auto& l : lines())
      if (l.text == text && l.at >= since) return l;
    return Line{};
  }

 private:
  struct Client {
    int fd = -1;
    int number = 0;
    std::string inbox, outbox;
  };

  double wallS() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  void run() {
    while (!quit_) {
      if (stopListening_ && listen_ >= 0) {
        ::close(listen_);
        listen_ = -1;
        listenerClosed_ = true;
      }
      std::vector<pollfd> fds;
      if (listen_ >= 0) fds.push_back({listen_, POLLIN, 0});
      for (const auto& c : clients_) fds.push_back({c.fd, POLLIN, 0});
      ::poll(fds.data(), fds.size(), 2);
      for (int fd; listen_ >= 0 && (fd = ::accept4(listen_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC)) >= 0;)
        clients_.push_back(Client{fd, ++accepted_, {}, {}});
      server_.tick(wallS(), wallS());
      for (auto& c : clients_) serve(c);
      // A connection the host closed is closed here too (it would wake poll() at once, for ever).
      for (auto it = clients_.begin(); it != clients_.end();)
        if (it->fd < 0) it = clients_.erase(it);
        else ++it;
    }
  }

  void serve(Client& c) {
    char buf[4096];
    ssize_t n = 0;
    while ((n = ::read(c.fd, buf, sizeof buf)) > 0) c.inbox.append(buf, static_cast<std::size_t>(n));
    const bool closed = n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR);
    const auto now = Clock::now();
    for (auto nl = c.inbox.find('\n'); nl != std::string::npos; nl = c.inbox.find('\n')) {
      std::string line = c.inbox.substr(0, nl);
      c.inbox.erase(0, nl + 1);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        lines_.push_back(Line{c.number, line, now});
      }
      if (hung_) continue;
      if (auto reply = server_.handleLine(line, wallS(), wallS())) c.outbox += *reply + "\n";
    }
    if (!c.outbox.empty() && !closed) {
      const ssize_t sent = ::send(c.fd, c.outbox.data(), c.outbox.size(), MSG_NOSIGNAL);
      if (sent > 0) c.outbox.erase(0, static_cast<std::size_t>(sent));
    }
    if (closed) {
      ::close(c.fd);
      c.fd = -1;
    }
  }

  fog::table::EmulatedTable table_;
  fog::table::TableServer server_;
  std::atomic<bool> hung_;
  std::atomic<bool> quit_{false};
  std::atomic<bool> stopListening_{false};
  std::atomic<bool> listenerClosed_{false};
  std::atomic<int> accepted_{0};
  int listen_ = -1;
  int port_ = 0;
  std::vector<Client> clients_;  // the server's thread only
  mutable std::mutex mutex_;     // guards lines_
  std::vector<Line> lines_;
  Clock::time_point start_ = Clock::now();
  std::thread thread_;
};

}  // namespace fogtest
