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
//
// Over TCP it serves up to kMaxTcpHosts connections at once, one protocol
// state (table, error queue, heartbeat) for all: the host's driver holds one
// and an emergency stop may arrive on a connection of its own
// (core/table/emergency_line.h), as a real controller with several
// sessions would take it.

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
  --linger-s S        once every host has gone, wait S wall seconds for another before ending (default 0;
                      a host that reconnects, as the window's table panel does, keeps it going)
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

// The command line (kHelp), as readOptions() checked it.
struct Options {
  std::string link, boardMode;
  double speed = 1.0, heartbeatS = 0.0, exitAfterS = 600.0, lingerS = 0.0;
  // Table seconds after the first swing starts; < 0: never.
  double dropAfterS = -1.0, boardVanishAfterS = -1.0;
  int tcpPort = 0;
  table::EmulatedTableParams params;
  table::ServerFaults faults;
};

Result<Options> readOptions(app::CliArguments& args) {
  Options o;
  o.link = args.text("link").value_or("tcp");
  o.boardMode = args.text("board").value_or("pty");
  struct Num {
    const char* name;
    double value;
  };
  table::EmulatedTableParams& params = o.params;
  auto& lim = params.limits.axes;
  Num nums[] = {{"speed", o.speed},
                {"tcp-port", static_cast<double>(o.tcpPort)},
                {"heartbeat-s", o.heartbeatS},
                {"max-amplitude-deg", lim[0].maxAmplitudeDeg},
                {"max-frequency-hz", lim[0].maxFrequencyHz},
                {"max-rate-deg-s", lim[0].maxRateDegPerS},
                {"max-accel-deg-s2", lim[0].maxAccelDegPerS2},
                {"servo-lag-ms", params.servoLagS * 1e3},
                {"stop-accel-deg-s2", params.stopAccelDegPerS2},
                {"exit-after-s", o.exitAfterS},
                {"drop-link-after-start-s", o.dropAfterS},
                {"interlock-after-start-s", -1.0},
                {"interlock-s", 1e9},
                {"board-vanish-after-start-s", o.boardVanishAfterS},
                {"linger-s", o.lingerS}};
  for (auto& n : nums) {
    FOG_ASSIGN_OR_RETURN(n.value, args.number(n.name, n.value));
  }
  o.speed = nums[0].value;
  o.heartbeatS = nums[2].value;
  o.exitAfterS = nums[9].value;
  o.dropAfterS = nums[10].value;
  o.boardVanishAfterS = nums[13].value;
  o.lingerS = nums[14].value;
  o.tcpPort = static_cast<int>(nums[1].value);
  for (auto& l : lim) {
    l.maxAmplitudeDeg = nums[3].value;
    l.maxFrequencyHz = nums[4].value;
    l.maxRateDegPerS = nums[5].value;
    l.maxAccelDegPerS2 = nums[6].value;
  }
  params.servoLagS = nums[7].value * 1e-3;
  params.stopAccelDegPerS2 = nums[8].value;
  o.faults.refuseHeader = args.text("refuse").value_or("");
  o.faults.interlockAfterStartS = nums[11].value;
  o.faults.interlockForS = nums[12].value;
  FOG_RETURN_IF_ERROR(args.checkAllUsed());
  if (!args.positionals().empty()) return invalidArgument("unexpected argument '" + args.positionals()[0] + "'");
  if (!(o.speed > 0.0) || o.speed > 1000.0) return invalidArgument("--speed must be in (0, 1000]");
  if (o.link != "tcp" && o.link != "pty") return invalidArgument("--link must be tcp or pty");
  if (o.boardMode != "pty" && o.boardMode != "none") return invalidArgument("--board must be pty or none");
  if (o.tcpPort < 0 || o.tcpPort > 65535) return invalidArgument("--tcp-port must be 0 .. 65535");
  if (!(params.servoLagS >= 0.0 && params.servoLagS < 0.5)) return invalidArgument("--servo-lag-ms must be 0 .. 500");
  if (!(params.stopAccelDegPerS2 > 0.0)) return invalidArgument("--stop-accel-deg-s2 must be > 0");
  if (!(o.lingerS >= 0.0)) return invalidArgument("--linger-s must be >= 0");
  return o;
}

// The board: the simulator's chain with the table's motion, no test-point
// markers (the host segments the stream from the table angle). None with
// --board none.
Result<std::unique_ptr<model::Simulator>> createBoard(const Options& o, model::SimConfig& config,
                                                      const table::EmulatedTable& emulated) {
  if (o.boardMode != "pty") return std::unique_ptr<model::Simulator>();
  config.samplingBoard.markTestPoints = false;
  TestPlan idle;
  idle.restBetweenS = 0.0;
  idle.points = {TestPoint::staticSegment(Axis::kX, kMaxPlanDurationS)};  // as long as a plan may last
  FOG_ASSIGN_OR_RETURN(std::unique_ptr<model::Simulator> sim, model::Simulator::create(config, idle));
  sim->addEffect(std::make_unique<TableMotion>(emulated));
  return sim;
}

// The emulator once its table, server and board exist: opens the
// controller's link and the board's port, then runs (every 2 ms: the link,
// the faults on request, the board's stream) until every host that came has
// gone, a signal or --exit-after-s, and says "done: ...".
class Emulator {
 public:
  Emulator(const Options& o, const table::EmulatedTable& emulated, table::TableServer& server,
           std::unique_ptr<model::Simulator> sim)
      : o_(o), emulated_(emulated), server_(server), sim_(std::move(sim)) {}

  Status openTableLink();
  Status openBoardPort(const model::SimConfig& config);
  void run();

 private:
  // One host's TCP connection (or, with fd -1 unused, the pty's lines).
  struct Host {
    int fd = -1;
    int number = 0;
    std::string inbox, outbox;
  };
  static constexpr std::size_t kMaxTcpHosts = 8;

  void closeHost(Host& host, const std::string& why);
  void acceptHosts();
  void serviceTableLink(double tableS, double wallS);
  void handleLines(Host& host, int fd, double tableS, double wallS);
  void dropLinkIfDue(double tableS);
  void vanishBoardIfDue(double tableS);
  void streamBoard(double tableS);
  bool everyHostGone(double tableS, double wallS) const;
  void finish(double wallS);

  const Options& o_;
  const table::EmulatedTable& emulated_;
  table::TableServer& server_;
  std::unique_ptr<model::Simulator> sim_;
  int listenFd_ = -1, tablePty_ = -1, boardFd_ = -1;
  std::vector<Host> hosts_;  // TCP connections open now
  Host ptyHost_;             // the pty's lines (fd unused)
  int hostsAccepted_ = 0;
  double lastHostWallS_ = 0.0;  // when a host was last connected (--linger-s counts from it)
  std::vector<std::uint8_t> boardClean_, boardBytes_, boardPending_;
  app::BoardHostControl hostControl_;
  protocol::HostCommandDecoder commandDecoder_;
  std::vector<protocol::HostCommand> commands_;
  bool dropped_ = false, hostSeen_ = false, ptyHostOpen_ = false, boardHostSeen_ = false, boardOpen_ = false;
  std::uint64_t boardSent_ = 0, linesHandled_ = 0;
};

// The controller's link.
Status Emulator::openTableLink() {
  if (o_.link == "tcp") {
    listenFd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    const int one = 1;
    ::setsockopt(listenFd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // localhost only
    sa.sin_port = htons(static_cast<std::uint16_t>(o_.tcpPort));
    socklen_t len = sizeof sa;
    if (listenFd_ < 0 || ::bind(listenFd_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0 ||
        ::listen(listenFd_, static_cast<int>(kMaxTcpHosts)) != 0 ||
        ::getsockname(listenFd_, reinterpret_cast<sockaddr*>(&sa), &len) != 0)
      return ioError(std::string("cannot listen on 127.0.0.1:") + std::to_string(o_.tcpPort) + ": " +
                     std::strerror(errno));
    say("table: tcp:127.0.0.1:" + std::to_string(ntohs(sa.sin_port)));
  } else {
    std::string name;
    tablePty_ = openPtyMaster(name);
    if (tablePty_ < 0) return ioError(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
    say("table: " + name);
  }
  return Status::ok();
}

// The board's pty and the chain's true delays, when there is a board.
Status Emulator::openBoardPort(const model::SimConfig& config) {
  if (!sim_) return Status::ok();
  std::string name;
  boardFd_ = openPtyMaster(name);
  if (boardFd_ < 0) return ioError(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
  say("board: " + name);
  char b[200];
  std::snprintf(b, sizeof b, "truth: lag_ms %.6f imu_delay_ms %.6f gyro_delay_ms %.6f", config.trueLagS() * 1e3,
                config.trueImuDelayS() * 1e3, config.trueGyroDelayS() * 1e3);
  say(b);
  return Status::ok();
}

void Emulator::run() {
  const auto start = Clock::now();
  for (;;) {
    const double wallS = std::chrono::duration<double>(Clock::now() - start).count();
    const double tableS = wallS * o_.speed;
    if (gQuit || wallS > o_.exitAfterS) break;
    serviceTableLink(tableS, wallS);
    server_.tick(tableS, wallS);
    dropLinkIfDue(tableS);
    vanishBoardIfDue(tableS);
    // The board's stream, up to now, as the host has configured it
    // (docs/protocol.md, "Host to board": commands read from the board's pty).
    if (sim_) streamBoard(tableS);
    if (everyHostGone(tableS, wallS)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  finish(std::chrono::duration<double>(Clock::now() - start).count());
}

void Emulator::closeHost(Host& host, const std::string& why) {
  if (host.fd >= 0) {
    ::close(host.fd);
    host.fd = -1;
    say("host: table link closed (connection " + std::to_string(host.number) + ", " + why + ")");
  }
}

// New TCP hosts, up to kMaxTcpHosts at once (more wait in the listen queue).
void Emulator::acceptHosts() {
  while (listenFd_ >= 0 && !dropped_ && hosts_.size() < kMaxTcpHosts) {
    const int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) break;
    hosts_.push_back(Host{fd, ++hostsAccepted_, {}, {}});
    hostSeen_ = true;
    say("host: table link connected (connection " + std::to_string(hostsAccepted_) + ", " +
        std::to_string(hosts_.size()) + " open)");
  }
}

// One host's link: what it sent handled line by line (also when it has just
// closed: what it wrote before is still read), the replies written.
void Emulator::handleLines(Host& host, int fd, double tableS, double wallS) {
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) {
      host.inbox.append(buf, static_cast<std::size_t>(n));
      continue;
    }
    if (n == 0 && fd == host.fd) closeHost(host, "by the host");
    break;
  }
  for (auto nl = host.inbox.find('\n'); nl != std::string::npos; nl = host.inbox.find('\n')) {
    const std::string line = host.inbox.substr(0, nl);
    host.inbox.erase(0, nl + 1);
    ++linesHandled_;
    if (auto reply = server_.handleLine(line, tableS, wallS)) host.outbox += *reply + "\n";
  }
  if (host.inbox.size() > 4096) {  // a host that never ends its line
    (void)server_.handleLine(std::string(300, 'X'), tableS, wallS);
    host.inbox.clear();
  }
  const bool socket = fd == host.fd;
  const int outFd = socket ? host.fd : fd;
  while (!host.outbox.empty() && outFd >= 0) {
    const ssize_t n = socket ? ::send(outFd, host.outbox.data(), host.outbox.size(), MSG_NOSIGNAL)
                             : ::write(outFd, host.outbox.data(), host.outbox.size());
    if (n <= 0) break;
    host.outbox.erase(0, static_cast<std::size_t>(n));
  }
}

// Link I/O: hosts connecting or opening the pty, their lines handled, the
// replies written.
void Emulator::serviceTableLink(double tableS, double wallS) {
  acceptHosts();
  for (auto& host : hosts_)
    if (host.fd >= 0) handleLines(host, host.fd, tableS, wallS);
  std::erase_if(hosts_, [](const Host& h) { return h.fd < 0; });
  if (!hosts_.empty()) lastHostWallS_ = wallS;
  if (tablePty_ >= 0) {
    const bool open = slaveOpen(tablePty_);
    if (open && !ptyHostOpen_) say("host: table link opened");
    if (!open && ptyHostOpen_) say("host: table link closed");
    ptyHostOpen_ = open;
    hostSeen_ = hostSeen_ || open;
    if (open) {
      lastHostWallS_ = wallS;
      handleLines(ptyHost_, tablePty_, tableS, wallS);
    }
  }
}

void Emulator::dropLinkIfDue(double tableS) {
  if (o_.dropAfterS >= 0.0 && !dropped_ && server_.firstSwingStartS() >= 0.0 &&
      tableS >= server_.firstSwingStartS() + o_.dropAfterS) {
    dropped_ = true;
    for (auto& host : hosts_) closeHost(host, "link dropped on request");
    hosts_.clear();
    if (listenFd_ >= 0) ::close(listenFd_), listenFd_ = -1;
    if (tablePty_ >= 0) ::close(tablePty_), tablePty_ = -1;
    char b[160];
    std::snprintf(b, sizeof b, "link: dropped at table time %.3f s (%.3f s after the first swing started)", tableS,
                  tableS - server_.firstSwingStartS());
    say(b);
  }
}

void Emulator::vanishBoardIfDue(double tableS) {
  if (sim_ && o_.boardVanishAfterS >= 0.0 && server_.firstSwingStartS() >= 0.0 &&
      tableS >= server_.firstSwingStartS() + o_.boardVanishAfterS) {
    ::close(boardFd_);
    boardFd_ = -1;
    sim_.reset();
    char b[160];
    std::snprintf(b, sizeof b, "board: vanished at table time %.3f s (%.3f s after the first swing started)", tableS,
                  tableS - server_.firstSwingStartS());
    say(b);
  }
}

void Emulator::streamBoard(double tableS) {
  boardClean_.clear();
  sim_->advance(tableS, boardClean_);
  const bool open = slaveOpen(boardFd_);
  {  // also once the host has closed: what it wrote just before is still there
    std::uint8_t in[512];
    for (ssize_t n; (n = ::read(boardFd_, in, sizeof in)) > 0;) {
      commands_.clear();
      commandDecoder_.push(std::span<const std::uint8_t>(in, static_cast<std::size_t>(n)), commands_);
      for (const auto& c : commands_) {
        char at[64];
        std::snprintf(at, sizeof at, " at table time %.3f s", tableS);
        say("host command: " + hostControl_.apply(c) + at);
      }
    }
  }
  boardBytes_.clear();
  hostControl_.process(boardClean_, boardBytes_);
  if (open && !boardOpen_) say("host: board port opened");
  if (!open && boardOpen_) say("host: board port closed");
  boardOpen_ = open;
  boardHostSeen_ = boardHostSeen_ || open;
  if (open) {
    boardPending_.insert(boardPending_.end(), boardBytes_.begin(), boardBytes_.end());
    while (!boardPending_.empty()) {
      const ssize_t n = ::write(boardFd_, boardPending_.data(), boardPending_.size());
      if (n <= 0) break;
      boardPending_.erase(boardPending_.begin(), boardPending_.begin() + n);
      boardSent_ += static_cast<std::uint64_t>(n);
    }
    if (boardPending_.size() > (8u << 20)) boardPending_.clear();  // a host that stopped reading
  } else {
    boardPending_.clear();  // a board streams whether or not anyone listens
  }
}

// Done: every host that came has gone.
bool Emulator::everyHostGone(double tableS, double wallS) const {
  const bool tableGone = hostSeen_ && hosts_.empty() && !ptyHostOpen_;
  const bool boardGone = !sim_ || (boardHostSeen_ && !boardOpen_);  // vanished on request counts as gone
  if (!(tableGone && boardGone) || wallS - lastHostWallS_ < o_.lingerS) return false;
  bool rest = true;
  for (int a = 0; a < kAxisCount; ++a) rest = rest && emulated_.mode(static_cast<Axis>(a), tableS) != table::AxisMode::kSwinging;
  return rest || wallS > o_.exitAfterS;  // a swinging table waits for its heartbeat
}

void Emulator::finish(double wallS) {
  char b[200];
  std::snprintf(b, sizeof b, "done: %.3f table s, %llu lines handled, %llu board bytes, %d swings started",
                wallS * o_.speed, static_cast<unsigned long long>(linesHandled_),
                static_cast<unsigned long long>(boardSent_), server_.swingsStarted());
  say(b);
  for (auto& host : hosts_) ::close(host.fd);
  if (listenFd_ >= 0) ::close(listenFd_);
  if (tablePty_ >= 0) ::close(tablePty_);
  if (boardFd_ >= 0) ::close(boardFd_);
}

}  // namespace

int main(int argc, char** argv) {
  auto started = app::startEmulator(argc, argv, kHelp);
  if (!started) return failWith(started.status().message());
  if (!*started) return 0;  // --help
  model::SimConfig& config = (*started)->config;
  const auto options = readOptions((*started)->args);
  if (!options) return failWith(options.status().message());

  table::EmulatedTable emulated(options->params);
  table::TableServer server(emulated, options->faults);
  server.setEventSink(say);
  if (options->heartbeatS > 0.0)
    (void)server.handleLine("SYST:HEART:TIM " + std::to_string(options->heartbeatS), 0.0, 0.0);
  auto board = createBoard(*options, config, emulated);
  if (!board) return failWith(board.status().message());

  Emulator emulator(*options, emulated, server, std::move(*board));
  if (auto s = emulator.openTableLink(); !s.isOk()) return failWith(s.message());
  if (auto s = emulator.openBoardPort(config); !s.isOk()) return failWith(s.message());
  std::signal(SIGINT, onQuit);
  std::signal(SIGTERM, onQuit);
  std::signal(SIGPIPE, SIG_IGN);
  emulator.run();
  return 0;
}
