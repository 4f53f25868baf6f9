// fogbench-table-emu: a three-axis turntable controller for testing without
// hardware. Speaks the remote protocol of docs/table-control.md on a
// localhost TCP port or a pseudo-terminal, moves a simulated table (rate and
// acceleration limits, servo lag), enforces the heartbeat, injects faults on
// request, and — in the same process, on a second pseudo-terminal — plays the
// sampling board's stream (docs/protocol.md) with the table angle of that
// simulated motion, so the whole hardware path runs without hardware:
//   fogbench-cli run --table remote:ADDR --source serial --port BOARD_PTY
// One process hosts both endpoints so that the board's stamps and the
// table's motion share one clock exactly (docs/table-control.md, "The
// emulator").
//
// stdout, one flushed line each (tests read them): "table: ADDRESS",
// "board: /dev/pts/N", "truth: ...", then events as they happen ("host: ...",
// "swing: ...", "heartbeat: ...", "interlock: ...", "link: ...",
// "refused: ...") and "done: ..." at the end.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "app/board_host.h"
#include "app/cli_arguments.h"
#include "core/model/effect.h"
#include "core/model/simulator.h"
#include "app/sim_options.h"
#include "core/table/emulated_table.h"

namespace {

using namespace fog;
using Clock = std::chrono::steady_clock;

const char* kHelp = R"(fogbench-table-emu: a turntable controller (and its sampling board) for tests without hardware.

usage: fogbench-table-emu [--link tcp|pty] [--tcp-port N] [--board pty|none] [--speed X] [options] [faults]
  --link tcp|pty      the controller's link: TCP on 127.0.0.1 (default; --tcp-port N, 0 = any free port)
                      or a new pseudo-terminal
  --board pty|none    also play the sampling board's stream, with this table's motion, on a new
                      pseudo-terminal (default pty)
  --speed X           X times real time (default 1): table and board share this clock
  --heartbeat-s S     heartbeat timeout before any host sets one (default 0: off until SYST:HEART:TIM)
  --max-amplitude-deg A --max-frequency-hz F --max-rate-deg-s R --max-accel-deg-s2 C
                      the limits the controller reports and enforces (defaults 45, 20, 400, 3000)
  --servo-lag-ms L    actual angle behind the commanded one (default 2)
  --stop-accel-deg-s2 A  deceleration of a stop (default 100)
  --exit-after-s S    give up after S wall seconds (default 600)
  simulator options for the board: --seed, --gyro-delay-ms, ... as fogbench-cli run
faults:
  --refuse HEADER     refuse the first command with this header (e.g. AXIS:Y:START): error 204
  --drop-link-after-start-s T  close the controller's link T table seconds after the first swing starts,
                      and accept no new connection (the heartbeat then stops the table)
  --interlock-after-start-s T [--interlock-s D]  trip the interlock T table seconds after the first swing
                      starts (every axis stopped, motion refused), closed again after D seconds
  --board-vanish-after-start-s T  close the board's pty T table seconds after the first swing starts
                      (for the host the board's port vanishes; the table goes on until told otherwise)
)";

void say(const std::string& line) {
  std::fputs((line + "\n").c_str(), stdout);
  std::fflush(stdout);
}

int failWith(const std::string& m) {
  std::fprintf(stderr, "fogbench-table-emu: %s\n", m.c_str());
  return 2;
}

std::atomic<bool> gQuit{false};
extern "C" void onQuit(int) { gQuit = true; }

// The board's table angle is the emulated table's.
class TableMotion : public model::Effect {
 public:
  explicit TableMotion(const table::EmulatedTable& t) : table_(t) {}
  std::string name() const override { return "emulated table motion"; }
  void onTableMotion(double timeS, std::array<double, kAxisCount>& angleDeg) const override {
    for (int a = 0; a < kAxisCount; ++a) angleDeg[static_cast<std::size_t>(a)] = table_.angleDeg(static_cast<Axis>(a), timeS);
  }

 private:
  const table::EmulatedTable& table_;
};

int openPtyMaster(std::string& name) {
  int master = -1, slave = -1;
  char path[256] = {};
  termios raw{};
  cfmakeraw(&raw);
  raw.c_cflag |= CLOCAL | CREAD;
  if (::openpty(&master, &slave, path, &raw, nullptr) != 0) return -1;
  ::close(slave);
  ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
  ::fcntl(master, F_SETFD, FD_CLOEXEC);
  name = path;
  return master;
}

bool slaveOpen(int master) {
  pollfd p{master, POLLOUT, 0};
  ::poll(&p, 1, 0);
  return !(p.revents & POLLHUP);
}

}  // namespace

int main(int argc, char** argv) {
  auto started = app::startEmulator(argc, argv, kHelp);
  if (!started) return failWith(started.status().message());
  if (!*started) return 0;  // --help
  auto& args = (*started)->args;
  auto* config = &(*started)->config;
  const std::string link = args.text("link").value_or("tcp");
  const std::string boardMode = args.text("board").value_or("pty");
  struct Num {
    const char* name;
    double value;
  };
  table::EmulatedTableParams params;
  auto& lim = params.limits.axes;
  Num nums[] = {{"speed", 1.0},
                {"tcp-port", 0.0},
                {"heartbeat-s", 0.0},
                {"max-amplitude-deg", lim[0].maxAmplitudeDeg},
                {"max-frequency-hz", lim[0].maxFrequencyHz},
                {"max-rate-deg-s", lim[0].maxRateDegPerS},
                {"max-accel-deg-s2", lim[0].maxAccelDegPerS2},
                {"servo-lag-ms", params.servoLagS * 1e3},
                {"stop-accel-deg-s2", params.stopAccelDegPerS2},
                {"exit-after-s", 600.0},
                {"drop-link-after-start-s", -1.0},
                {"interlock-after-start-s", -1.0},
                {"interlock-s", 1e9},
                {"board-vanish-after-start-s", -1.0}};
  for (auto& n : nums) {
    auto v = args.number(n.name, n.value);
    if (!v) return failWith(v.status().message());
    n.value = *v;
  }
  const double speed = nums[0].value, heartbeatS = nums[2].value, exitAfterS = nums[9].value;
  const double dropAfterS = nums[10].value, boardVanishAfterS = nums[13].value;
  const int tcpPort = static_cast<int>(nums[1].value);
  for (auto& l : lim) {
    l.maxAmplitudeDeg = nums[3].value;
    l.maxFrequencyHz = nums[4].value;
    l.maxRateDegPerS = nums[5].value;
    l.maxAccelDegPerS2 = nums[6].value;
  }
  params.servoLagS = nums[7].value * 1e-3;
  params.stopAccelDegPerS2 = nums[8].value;
  table::ServerFaults faults;
  faults.refuseHeader = args.text("refuse").value_or("");
  faults.interlockAfterStartS = nums[11].value;
  faults.interlockForS = nums[12].value;
  if (auto s = args.checkAllUsed(); !s.isOk()) return failWith(s.message());
  if (!args.positionals().empty()) return failWith("unexpected argument '" + args.positionals()[0] + "'");
  if (!(speed > 0.0) || speed > 1000.0) return failWith("--speed must be in (0, 1000]");
  if (link != "tcp" && link != "pty") return failWith("--link must be tcp or pty");
  if (boardMode != "pty" && boardMode != "none") return failWith("--board must be pty or none");
  if (tcpPort < 0 || tcpPort > 65535) return failWith("--tcp-port must be 0 .. 65535");
  if (!(params.servoLagS >= 0.0 && params.servoLagS < 0.5)) return failWith("--servo-lag-ms must be 0 .. 500");
  if (!(params.stopAccelDegPerS2 > 0.0)) return failWith("--stop-accel-deg-s2 must be > 0");

  table::EmulatedTable emulated(params);
  table::TableServer server(emulated, faults);
  server.setEventSink(say);
  if (heartbeatS > 0.0) (void)server.handleLine("SYST:HEART:TIM " + std::to_string(heartbeatS), 0.0, 0.0);

  // The board: the simulator's chain with the table's motion, no test-point
  // markers (the host segments the stream from the table angle).
  std::unique_ptr<model::Simulator> sim;
  int boardFd = -1;
  if (boardMode == "pty") {
    config->samplingBoard.markTestPoints = false;
    TestPlan idle;
    idle.restBetweenS = 0.0;
    idle.points = {TestPoint::staticSegment(Axis::kX, kMaxPlanDurationS)};  // as long as a plan may last
    auto created = model::Simulator::create(*config, idle);
    if (!created) return failWith(created.status().message());
    sim = std::move(*created);
    sim->addEffect(std::make_unique<TableMotion>(emulated));
  }

  // The controller's link.
  int listenFd = -1, clientFd = -1, tablePty = -1;
  if (link == "tcp") {
    listenFd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    const int one = 1;
    ::setsockopt(listenFd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // localhost only
    sa.sin_port = htons(static_cast<std::uint16_t>(tcpPort));
    socklen_t len = sizeof sa;
    if (listenFd < 0 || ::bind(listenFd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0 ||
        ::listen(listenFd, 1) != 0 || ::getsockname(listenFd, reinterpret_cast<sockaddr*>(&sa), &len) != 0)
      return failWith(std::string("cannot listen on 127.0.0.1:") + std::to_string(tcpPort) + ": " + std::strerror(errno));
    say("table: tcp:127.0.0.1:" + std::to_string(ntohs(sa.sin_port)));
  } else {
    std::string name;
    tablePty = openPtyMaster(name);
    if (tablePty < 0) return failWith(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
    say("table: " + name);
  }
  if (sim) {
    std::string name;
    boardFd = openPtyMaster(name);
    if (boardFd < 0) return failWith(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
    say("board: " + name);
    char b[200];
    std::snprintf(b, sizeof b, "truth: lag_ms %.6f imu_delay_ms %.6f gyro_delay_ms %.6f", config->trueLagS() * 1e3,
                  config->trueImuDelayS() * 1e3, config->trueGyroDelayS() * 1e3);
    say(b);
  }
  std::signal(SIGINT, onQuit);
  std::signal(SIGTERM, onQuit);
  std::signal(SIGPIPE, SIG_IGN);

  const auto start = Clock::now();
  std::string inbox, outbox;
  std::vector<std::uint8_t> boardClean, boardBytes, boardPending;
  app::BoardHostControl hostControl;
  protocol::HostCommandDecoder commandDecoder;
  std::vector<protocol::HostCommand> commands;
  bool dropped = false, hostSeen = false, ptyHostOpen = false, boardHostSeen = false, boardOpen = false;
  std::uint64_t boardSent = 0, linesHandled = 0;
  auto closeClient = [&](const std::string& why) {
    if (clientFd >= 0) {
      ::close(clientFd);
      clientFd = -1;
      say("host: table link closed (" + why + ")");
    }
  };
  for (;;) {
    const double wallS = std::chrono::duration<double>(Clock::now() - start).count();
    const double tableS = wallS * speed;
    if (gQuit || wallS > exitAfterS) break;
    // Link I/O.
    if (listenFd >= 0 && clientFd < 0 && !dropped) {
      const int fd = ::accept4(listenFd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd >= 0) {
        clientFd = fd;
        hostSeen = true;
        inbox.clear();
        say("host: table link connected");
      }
    }
    int ioFd = clientFd >= 0 ? clientFd : -1;
    if (tablePty >= 0) {
      const bool open = slaveOpen(tablePty);
      if (open && !ptyHostOpen) say("host: table link opened");
      if (!open && ptyHostOpen) say("host: table link closed");
      ptyHostOpen = open;
      hostSeen = hostSeen || open;
      ioFd = open ? tablePty : -1;
    }
    if (ioFd >= 0) {
      char buf[4096];
      for (;;) {
        const ssize_t n = ::read(ioFd, buf, sizeof buf);
        if (n > 0) {
          inbox.append(buf, static_cast<std::size_t>(n));
          continue;
        }
        if (n == 0 && ioFd == clientFd) closeClient("by the host");
        break;
      }
      for (auto nl = inbox.find('\n'); nl != std::string::npos; nl = inbox.find('\n')) {
        const std::string line = inbox.substr(0, nl);
        inbox.erase(0, nl + 1);
        ++linesHandled;
        if (auto reply = server.handleLine(line, tableS, wallS)) outbox += *reply + "\n";
      }
      if (inbox.size() > 4096) {  // a host that never ends its line
        (void)server.handleLine(std::string(300, 'X'), tableS, wallS);
        inbox.clear();
      }
      const int outFd = clientFd >= 0 ? clientFd : (ptyHostOpen ? tablePty : -1);
      while (!outbox.empty() && outFd >= 0) {
        const ssize_t n = outFd == clientFd ? ::send(outFd, outbox.data(), outbox.size(), MSG_NOSIGNAL)
                                            : ::write(outFd, outbox.data(), outbox.size());
        if (n <= 0) break;
        outbox.erase(0, static_cast<std::size_t>(n));
      }
    }
    server.tick(tableS, wallS);
    if (dropAfterS >= 0.0 && !dropped && server.firstSwingStartS() >= 0.0 &&
        tableS >= server.firstSwingStartS() + dropAfterS) {
      dropped = true;
      closeClient("link dropped on request");
      if (listenFd >= 0) ::close(listenFd), listenFd = -1;
      if (tablePty >= 0) ::close(tablePty), tablePty = -1;
      char b[160];
      std::snprintf(b, sizeof b, "link: dropped at table time %.3f s (%.3f s after the first swing started)", tableS,
                    tableS - server.firstSwingStartS());
      say(b);
    }
    if (sim && boardVanishAfterS >= 0.0 && server.firstSwingStartS() >= 0.0 &&
        tableS >= server.firstSwingStartS() + boardVanishAfterS) {
      ::close(boardFd);
      boardFd = -1;
      sim.reset();
      char b[160];
      std::snprintf(b, sizeof b, "board: vanished at table time %.3f s (%.3f s after the first swing started)", tableS,
                    tableS - server.firstSwingStartS());
      say(b);
    }
    // The board's stream, up to now, as the host has configured it
    // (docs/protocol.md, "Host to board": commands read from the board's pty).
    if (sim) {
      boardClean.clear();
      sim->advance(tableS, boardClean);
      const bool open = slaveOpen(boardFd);
      {  // also once the host has closed: what it wrote just before is still there
        std::uint8_t in[512];
        for (ssize_t n; (n = ::read(boardFd, in, sizeof in)) > 0;) {
          commands.clear();
          commandDecoder.push(std::span<const std::uint8_t>(in, static_cast<std::size_t>(n)), commands);
          for (const auto& c : commands) {
            char at[64];
            std::snprintf(at, sizeof at, " at table time %.3f s", tableS);
            say("host command: " + hostControl.apply(c) + at);
          }
        }
      }
      boardBytes.clear();
      hostControl.process(boardClean, boardBytes);
      if (open && !boardOpen) say("host: board port opened");
      if (!open && boardOpen) say("host: board port closed");
      boardOpen = open;
      boardHostSeen = boardHostSeen || open;
      if (open) {
        boardPending.insert(boardPending.end(), boardBytes.begin(), boardBytes.end());
        while (!boardPending.empty()) {
          const ssize_t n = ::write(boardFd, boardPending.data(), boardPending.size());
          if (n <= 0) break;
          boardPending.erase(boardPending.begin(), boardPending.begin() + n);
          boardSent += static_cast<std::uint64_t>(n);
        }
        if (boardPending.size() > (8u << 20)) boardPending.clear();  // a host that stopped reading
      } else {
        boardPending.clear();  // a board streams whether or not anyone listens
      }
    }
    // Done: every host that came has gone.
    const bool tableGone = hostSeen && clientFd < 0 && !ptyHostOpen;
    const bool boardGone = !sim || (boardHostSeen && !boardOpen);  // vanished on request counts as gone
    if (tableGone && boardGone) {
      bool rest = true;
      for (int a = 0; a < kAxisCount; ++a) rest = rest && emulated.mode(static_cast<Axis>(a), tableS) != table::AxisMode::kSwinging;
      if (rest || wallS > exitAfterS) break;  // a swinging table waits for its heartbeat
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const double wallS = std::chrono::duration<double>(Clock::now() - start).count();
  char b[200];
  std::snprintf(b, sizeof b, "done: %.3f table s, %llu lines handled, %llu board bytes, %d swings started", wallS * speed,
                static_cast<unsigned long long>(linesHandled), static_cast<unsigned long long>(boardSent),
                server.swingsStarted());
  say(b);
  if (clientFd >= 0) ::close(clientFd);
  if (listenFd >= 0) ::close(listenFd);
  if (tablePty >= 0) ::close(tablePty);
  if (boardFd >= 0) ::close(boardFd);
  return 0;
}
