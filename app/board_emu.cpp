// fogbench-board-emu: a sampling board for testing without hardware. Plays
// the simulator's byte stream (the same plan and chain options as
// `fogbench-cli run`) onto a pseudo-terminal it creates, or onto a serial
// device, at real-time pace or a chosen speed-up, with faults on request.
// docs/serial.md describes the options and what the bench reports for each.
//
// stdout, one line each, flushed (tests read them): "pty: /dev/pts/N",
// "truth: ..." per test point, "host: ..." once the host has opened the
// port, "host command: ..." for each command the host sends (docs/protocol.md,
// "Host to board"), "stall: ...", "disconnect: ...", and a final "done: ..."
// with the counts of what was sent and damaged.

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "app/board_faults.h"
#include "app/board_host.h"
#include "app/cli_arguments.h"
#include "core/model/simulator.h"
#include "app/sim_options.h"

namespace {

using namespace fog;
using Clock = std::chrono::steady_clock;

const char* kHelp = R"(fogbench-board-emu: a sampling board on a pseudo-terminal, for tests without hardware.

usage: fogbench-board-emu [plan] [simulator options] [--speed X] [--device PATH] [--baud B] [faults]
  plan and simulator options: as fogbench-cli run (--preset, --plan, --axis/--freq-hz/--amp-deg/--duration-s,
      --seed, --gyro-delay-ms, --counter-start, ...)
  --speed X          X times real time (default 1; 0: as fast as the host reads)
  --device PATH      write to this serial device (raw, --baud) instead of a new pseudo-terminal
  --baud B           the board's baud rate (default 921600); a host set to another rate (or to
                     parity / other data bits) receives what a mismatched UART would: garbage
  --wait-open-s S    on a pty, wait this long for a host to open it (default 60)
  --linger-s S       after the plan, wait this long for the host to close the port (default 10)
  --save-raw FILE    also write every byte sent (faults included) to FILE
faults:
  --corrupt-rate R   flip one bit in each byte with probability R
  --drop-rate R      leave out each table/IMU frame with probability R
  --duplicate-rate R send each table/IMU frame twice with probability R
  --gap-at-s T --gap-s D          leave out every frame for D stream seconds from T
  --garbage-at-s T --garbage-bytes N  N random bytes at stream time T
  --wrap-after-s S   start the board counter S seconds before it wraps (2^counter-bits)
  --stall-at-s T --stall-s N      send nothing for N wall-clock seconds at stream time T
  --disconnect-at-s T             close the port (the pty vanishes for the host) at stream time T
  --fault-seed N     seed of the fault generator (default 1)
)";

void say(const std::string& line) {
  std::fputs((line + "\n").c_str(), stdout);
  std::fflush(stdout);
}

int failWith(const std::string& message) {
  std::fprintf(stderr, "fogbench-board-emu: %s\n", message.c_str());
  return 2;
}

std::string fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

struct BaudCode {
  speed_t code;
  int baud;
};
constexpr BaudCode kBauds[] = {{B50, 50},         {B1200, 1200},       {B2400, 2400},       {B4800, 4800},
                               {B9600, 9600},     {B19200, 19200},     {B38400, 38400},     {B57600, 57600},
                               {B115200, 115200}, {B230400, 230400},   {B460800, 460800},   {B500000, 500000},
                               {B576000, 576000}, {B921600, 921600},   {B1000000, 1000000}, {B1152000, 1152000},
                               {B1500000, 1500000}, {B2000000, 2000000}, {B3000000, 3000000}};

speed_t codeOf(int baud) {
  for (const auto& b : kBauds)
    if (b.baud == baud) return b.code;
  return B0;
}
int baudOf(speed_t code) {
  for (const auto& b : kBauds)
    if (b.code == code) return b.baud;
  return 0;
}

// The host side's line settings, as it configured the pty's slave.
struct HostLine {
  int baud = 0;
  int dataBits = 8;
  int parity = 0;  // 0 none, 1 even, 2 odd
};

HostLine hostLineOf(const termios& t) {
  HostLine h;
  h.baud = baudOf(cfgetospeed(&t));
  switch (t.c_cflag & CSIZE) {
    case CS5: h.dataBits = 5; break;
    case CS6: h.dataBits = 6; break;
    case CS7: h.dataBits = 7; break;
    default: h.dataBits = 8; break;
  }
  if (t.c_cflag & PARENB) h.parity = (t.c_cflag & PARODD) ? 2 : 1;
  return h;
}

// Writes everything, waiting while the host's buffer is full. False when the
// host has closed the port (or it failed).
bool writeAll(int fd, const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n > 0) {
      data += n;
      size -= static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) return false;
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, 1000) < 0 && errno != EINTR) return false;
    if (p.revents & (POLLHUP | POLLERR)) return false;
  }
  return true;
}

struct Options {
  double speed = 1.0;
  std::string device;
  int baud = 921600;
  double waitOpenS = 60.0, lingerS = 10.0;
  std::string saveRaw;
  app::FaultOptions faults;
  double wrapAfterS = -1.0;
  double stallAtS = -1.0, stallS = 0.0;
  double disconnectAtS = -1.0;
};

Result<Options> readOptions(app::CliArguments& args) {
  Options o;
  struct Number {
    const char* name;
    double* target;
  };
  double baud = o.baud, garbageBytes = 0.0, faultSeed = 1.0;
  Number numbers[] = {{"speed", &o.speed},
                      {"baud", &baud},
                      {"wait-open-s", &o.waitOpenS},
                      {"linger-s", &o.lingerS},
                      {"corrupt-rate", &o.faults.corruptRate},
                      {"drop-rate", &o.faults.dropRate},
                      {"duplicate-rate", &o.faults.duplicateRate},
                      {"gap-at-s", &o.faults.gapAtS},
                      {"gap-s", &o.faults.gapS},
                      {"garbage-at-s", &o.faults.garbageAtS},
                      {"garbage-bytes", &garbageBytes},
                      {"fault-seed", &faultSeed},
                      {"wrap-after-s", &o.wrapAfterS},
                      {"stall-at-s", &o.stallAtS},
                      {"stall-s", &o.stallS},
                      {"disconnect-at-s", &o.disconnectAtS}};
  for (auto& n : numbers) {
    FOG_ASSIGN_OR_RETURN(auto v, args.number(n.name, *n.target));
    *n.target = v;
  }
  for (double rate : {o.faults.corruptRate, o.faults.dropRate, o.faults.duplicateRate})
    if (rate < 0.0 || rate > 1.0) return invalidArgument("fault rates must be within 0 .. 1");
  if (o.speed < 0.0) return invalidArgument("--speed must be >= 0");
  if (codeOf(static_cast<int>(baud)) == B0 || baud != std::floor(baud))
    return invalidArgument("--baud must be a standard rate (9600 .. 3000000), got " + fmt("%g", baud));
  if (garbageBytes < 0 || garbageBytes > 1e7) return invalidArgument("--garbage-bytes must be within 0 .. 10^7");
  if (o.stallS < 0.0 || o.faults.gapS < 0.0) return invalidArgument("--stall-s and --gap-s must be >= 0");
  o.baud = static_cast<int>(baud);
  o.faults.garbageBytes = static_cast<std::size_t>(garbageBytes);
  o.faults.seed = static_cast<std::uint64_t>(std::max(faultSeed, 0.0));
  o.device = args.text("device").value_or("");
  o.saveRaw = args.text("save-raw").value_or("");
  return o;
}

// --wrap-after-s: the board counter starts that long before it wraps.
void startCounterBeforeWrap(model::SimConfig& config, double wrapAfterS) {
  if (wrapAfterS < 0.0) return;
  const double span = std::ldexp(1.0, config.samplingBoard.counterBits);
  const double ticks = std::fmod(std::round(wrapAfterS * config.samplingBoard.counterHz), span);
  config.samplingBoard.counterStart = static_cast<std::uint32_t>(std::fmod(span - ticks, span));
}

// The port the board writes to, and the line its host has set.
struct Port {
  int fd = -1;
  HostLine host;
};

// "truth: ..." a test point: what the chain really does, for tests to check.
void sayTruth(const model::Simulator& sim) {
  for (const auto& t : sim.truth())
    say("truth: point " + std::to_string(t.index + 1) + " axis " + axisName(t.axis) + " frequency_hz " +
        fmt("%.9f", t.frequencyHz) + " amplitude_deg " + fmt("%.6f", t.amplitudeDeg) + " lag_ms " +
        fmt("%.6f", t.lagS * 1e3) + " imu_delay_ms " + fmt("%.6f", t.imuDelayS * 1e3) + " gyro_delay_ms " +
        fmt("%.6f", t.gyroDelayS * 1e3));
}

// A new pseudo-terminal, once a host has opened its slave and set its line.
Result<Port> openPtyForHost(const Options& o, termios board, const model::Simulator& sim) {
  int fd = -1, slave = -1;
  char name[256] = {};
  // A sentinel rate on the slave tells when the host has configured it.
  cfsetspeed(&board, B50);
  if (::openpty(&fd, &slave, name, &board, nullptr) != 0)
    return ioError(std::string("cannot create a pseudo-terminal: ") + std::strerror(errno));
  ::close(slave);
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  ::fcntl(fd, F_SETFD, FD_CLOEXEC);
  say(std::string("pty: ") + name);
  sayTruth(sim);
  // Wait for the host: the master reports a hang-up while no slave is open.
  const auto giveUp = Clock::now() + std::chrono::duration<double>(o.waitOpenS);
  for (;;) {
    pollfd p{fd, POLLOUT, 0};
    ::poll(&p, 1, 0);
    if (!(p.revents & POLLHUP)) break;
    if (Clock::now() > giveUp)
      return ioError("no host opened " + std::string(name) + " within " + fmt("%g", o.waitOpenS) + " s");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // ... and for it to set its line (the serial source does so while opening). On
  // Linux a pty master's tcgetattr reports the slave's settings.
  termios t{};
  const auto configured = Clock::now() + std::chrono::seconds(2);
  while (::tcgetattr(fd, &t) == 0 && cfgetospeed(&t) == B50 && Clock::now() < configured)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  HostLine host{o.baud, 8, 0};
  if (cfgetospeed(&t) != B50) host = hostLineOf(t);
  say("host: opened at " + std::to_string(host.baud) + " " + std::to_string(host.dataBits) +
      (host.parity == 0 ? "N" : host.parity == 1 ? "E" : "O") + "1 (board " + std::to_string(o.baud) + " 8N1)");
  return Port{fd, host};
}

// --device: the serial device, set to the board's line.
Result<Port> openDevice(const Options& o, termios board) {
  const int fd = ::open(o.device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return ioError("cannot open " + o.device + ": " + std::strerror(errno));
  cfsetspeed(&board, codeOf(o.baud));
  if (::tcsetattr(fd, TCSANOW, &board) != 0)
    return ioError("cannot set " + o.device + " to " + std::to_string(o.baud) + " 8N1: " + std::strerror(errno));
  say("device: " + o.device + " at " + std::to_string(o.baud) + " 8N1");
  return Port{fd, {o.baud, 8, 0}};
}

// The port: a new pseudo-terminal (the host opens its slave) or a device.
Result<Port> openPort(const Options& o, const model::Simulator& sim) {
  termios board{};
  cfmakeraw(&board);
  board.c_cflag |= CLOCAL | CREAD;
  return o.device.empty() ? openPtyForHost(o, board, sim) : openDevice(o, board);
}

// The board on its port: streams the plan with the faults asked for, says
// "done: ..." and, on a pty, lingers until the host lets go.
class Board {
 public:
  Board(const Options& o, model::Simulator& sim, Port port, std::ofstream raw)
      : o_(o), sim_(sim), fd_(port.fd), host_(port.host), raw_(std::move(raw)), faults_(o.faults) {}

  void run() {
    stream();
    raw_.flush();
    report();
    if (fd_ >= 0 && o_.device.empty()) linger();
    if (fd_ >= 0) ::close(fd_);
  }

 private:
  void stream();
  bool send();
  void readHostCommands();
  void report() const;
  void linger();

  const Options& o_;
  model::Simulator& sim_;
  int fd_;
  HostLine host_;
  std::ofstream raw_;
  app::BoardFaults faults_;
  // The host-to-board direction (docs/protocol.md): commands read from the
  // port, applied to the clean stream before the faults.
  app::BoardHostControl hostControl_;
  protocol::HostCommandDecoder commandDecoder_;
  std::vector<protocol::HostCommand> commands_;
  std::vector<std::uint8_t> clean_, configured_, damaged_;
  std::uint64_t sent_ = 0;
  bool hostGone_ = false;
};

// Until the plan ends, the host closes the port or --disconnect-at-s.
void Board::stream() {
  const auto start = Clock::now();
  Clock::duration paused{};
  bool stalled = false, more = true;
  constexpr double kStepS = 0.005;
  while (more) {
    // Stream time released so far; the next event (stall, disconnect) caps it.
    const double wallS = std::chrono::duration<double>(Clock::now() - start - paused).count();
    double until = o_.speed > 0.0 ? wallS * o_.speed : sim_.timeS() + 0.05;
    const bool stallDue = !stalled && o_.stallAtS >= 0.0 && until >= o_.stallAtS;
    const bool disconnectDue = o_.disconnectAtS >= 0.0 && until >= o_.disconnectAtS;
    if (stallDue) until = o_.stallAtS;
    if (disconnectDue) until = std::min(until, o_.disconnectAtS);
    // What the host sent (a board that only streams would ignore it).
    readHostCommands();
    clean_.clear();
    configured_.clear();
    damaged_.clear();
    more = sim_.advance(until, clean_);
    hostControl_.process(clean_, configured_);
    faults_.apply(configured_, sim_.timeS(), damaged_);
    if (!damaged_.empty() && !send()) {
      hostGone_ = true;
      break;
    }
    if (disconnectDue) {
      raw_.flush();
      ::close(fd_);
      fd_ = -1;
      say("disconnect: closed the port at stream time " + fmt("%.3f", o_.disconnectAtS) + " s after " +
          std::to_string(sent_) + " bytes");
      break;
    }
    if (stallDue) {
      stalled = true;
      raw_.flush();
      say("stall: nothing sent for " + fmt("%.1f", o_.stallS) + " s from stream time " + fmt("%.3f", o_.stallAtS) +
          " s");
      const auto pauseStart = Clock::now();
      std::this_thread::sleep_for(std::chrono::duration<double>(o_.stallS));
      paused += Clock::now() - pauseStart;
      say("stall: sending again");
      continue;
    }
    if (o_.speed > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(kStepS / std::max(o_.speed, 1.0)));
  }
}

// The damaged bytes as the host's line receives them; false when the host
// has closed the port (or it failed).
bool Board::send() {
  // The line as the host has it set now (it may change it at any time).
  if (termios t{}; o_.device.empty() && ::tcgetattr(fd_, &t) == 0 && cfgetospeed(&t) != B50) host_ = hostLineOf(t);
  const auto line = app::uartReceive(damaged_, o_.baud, host_.baud, host_.dataBits, host_.parity);
  if (raw_.is_open())
    raw_.write(reinterpret_cast<const char*>(damaged_.data()), static_cast<std::streamsize>(damaged_.size()));
  if (!writeAll(fd_, line.data(), line.size())) return false;
  sent_ += damaged_.size();
  return true;
}

void Board::readHostCommands() {
  std::uint8_t in[512];
  for (ssize_t n; (n = ::read(fd_, in, sizeof in)) > 0;) {
    commands_.clear();
    commandDecoder_.push(std::span<const std::uint8_t>(in, static_cast<std::size_t>(n)), commands_);
    for (const auto& c : commands_)
      say("host command: " + hostControl_.apply(c) + " at stream time " + fmt("%.3f", sim_.timeS()) + " s");
  }
}

void Board::report() const {
  const auto& c = faults_.counts();
  say("done: " + std::to_string(sent_) + " bytes, " + std::to_string(c.frames) + " frames of " +
      fmt("%.3f", sim_.timeS()) + " s; faults: " + std::to_string(c.corruptedBytes) + " corrupted bytes, " +
      std::to_string(c.droppedFrames) + " dropped frames, " + std::to_string(c.gapFrames) + " gap frames, " +
      std::to_string(c.duplicatedFrames) + " duplicated frames, " + std::to_string(c.garbageBytes) +
      " garbage bytes" + (hostGone_ ? "; the host closed the port" : ""));
}

// Like a board after its plan: the port stays until the host lets go.
void Board::linger() {
  const auto giveUp = Clock::now() + std::chrono::duration<double>(o_.lingerS);
  for (;;) {
    pollfd p{fd_, POLLOUT, 0};
    ::poll(&p, 1, 0);
    // Commands still count (a host stops the stream when its run is over),
    // read after the poll so that what a host wrote before closing is seen.
    readHostCommands();
    if ((p.revents & POLLHUP) || Clock::now() > giveUp) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto started = app::startEmulator(argc, argv, kHelp);
  if (!started) return failWith(started.status().message());
  if (!*started) return 0;  // --help
  auto& args = (*started)->args;
  model::SimConfig& config = (*started)->config;
  auto plan = app::readPlan(args);
  if (!plan) return failWith(plan.status().message());
  auto options = readOptions(args);
  if (!options) return failWith(options.status().message());
  if (auto s = args.checkAllUsed(); !s.isOk()) return failWith(s.message());
  if (!args.positionals().empty()) return failWith("unexpected argument '" + args.positionals()[0] + "'");
  const Options& o = *options;
  startCounterBeforeWrap(config, o.wrapAfterS);
  auto sim = model::Simulator::create(config, *plan);
  if (!sim) return failWith(sim.status().message());

  std::ofstream raw;
  if (!o.saveRaw.empty()) {
    raw.open(o.saveRaw, std::ios::binary | std::ios::trunc);
    if (!raw) return failWith("cannot write '" + o.saveRaw + "'");
  }
  auto port = openPort(o, **sim);
  if (!port) return failWith(port.status().message());
  Board(o, **sim, *port, std::move(raw)).run();
  return 0;
}
