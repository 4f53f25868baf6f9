#pragma once
// A child process for the command-line tests over pseudo-terminals and
// localhost TCP (serial_test.cpp, table_test.cpp): argv run with stdout and
// stderr on pipes, read without sleeping; every wait has a limit.

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <string>
#include <vector>

namespace fog::test {

using Clock = std::chrono::steady_clock;

// A child process with its stdout and stderr on pipes.
class Child {
 public:
  explicit Child(const std::vector<std::string>& argv) {
    int outPipe[2], errPipe[2];
    if (::pipe(outPipe) != 0 || ::pipe(errPipe) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(outPipe[1], 1);
      ::dup2(errPipe[1], 2);
      ::close(outPipe[0]);
      ::close(errPipe[0]);
      ::close(outPipe[1]);
      ::close(errPipe[1]);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      ::execv(args[0], args.data());
      std::perror("execv");
      ::_exit(127);
    }
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    outFd_ = outPipe[0];
    errFd_ = errPipe[0];
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  pid_t pid() const { return pid_; }
  ~Child() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
    if (outFd_ >= 0) ::close(outFd_);
    if (errFd_ >= 0) ::close(errFd_);
  }

  // Reads until stdout holds a line matching `pattern` (or the process
  // ends, or the limit passes); returns the first capture group or "".
  std::string waitForLine(const std::string& pattern, double limitS = 60.0) {
    const std::regex re(pattern);
    const auto giveUp = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limitS));
    for (;;) {
      std::smatch m;
      if (std::regex_search(out, m, re)) return m.size() > 1 ? m[1].str() : m[0].str();
      if (!pump(giveUp)) return "";
    }
  }

  // Reads everything until the process exits; its exit code, or -1 when it
  // had to be killed at the limit.
  int finish(double limitS = 120.0) {
    const auto giveUp = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limitS));
    while (pump(giveUp)) {
    }
    if (Clock::now() >= giveUp) ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exited_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // Reads what arrives within `seconds`; false once both pipes are closed.
  bool pumpFor(double seconds) {
    return pump(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)));
  }

  std::string out, err;

 private:
  // One round of reading; false once both pipes are closed or time is up.
  bool pump(Clock::time_point giveUp) {
    if (outFd_ < 0 && errFd_ < 0) return false;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(giveUp - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p[2] = {{outFd_, POLLIN, 0}, {errFd_, POLLIN, 0}};
    if (::poll(p, 2, static_cast<int>(std::min<long long>(left, 1000))) < 0) return false;
    for (int i = 0; i < 2; ++i) {
      if (!(p[i].revents & (POLLIN | POLLHUP))) continue;
      char buf[4096];
      const ssize_t n = ::read(p[i].fd, buf, sizeof buf);
      int& fd = i == 0 ? outFd_ : errFd_;
      if (n <= 0) {
        ::close(fd);
        fd = -1;
      } else {
        (i == 0 ? out : err).append(buf, static_cast<std::size_t>(n));
      }
    }
    return true;
  }

  pid_t pid_ = -1;
  int outFd_ = -1, errFd_ = -1;
  bool exited_ = false;
};

}  // namespace fog::test
