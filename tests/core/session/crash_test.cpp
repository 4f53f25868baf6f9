// Crash safety, proven on a real process: the record helper records a
// real-time paced simulated stream into a session; after ~1.5 s the test
// kills it with SIGKILL (no destructor, no flush), reopens the file and checks
// that it holds an exact prefix of the stream covering everything produced
// before the kill except at most the last 250 ms (+ 100 ms scheduling slack
// for a loaded 2-core machine: the helper may be descheduled between
// producing bytes and its next commit check).

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/protocol/decoder.h"
#include "record_helper_stream.h"
#include "core/session/session_file.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

struct HelperLine {
  std::uint64_t appended = 0, committed = 0, commits = 0;
};

// Board time (s) of the last complete frame within the first `size` bytes.
double streamTimeS(const std::vector<std::uint8_t>& stream, std::size_t size) {
  protocol::Decoder d;
  std::vector<protocol::DecodedFrame> frames;
  d.push(std::span<const std::uint8_t>(stream.data(), size), frames);
  if (frames.empty()) return 0.0;
  return static_cast<double>(frames.back().ticks - frames.front().ticks) / 10e6;  // default 10 MHz counter
}

TEST(SessionCrash, KillDashNineLosesAtMostTheLast250Ms) {
  fog::test::ScratchDir dir;
  const std::string path = dir.file("killed.fbs");
  auto expected = model::simulate(fog::test::recordHelperConfig(), fog::test::recordHelperPlan());
  ASSERT_TRUE(expected.isOk());
  const auto& stream = expected->bytes;

  int pipeFd[2];
  ASSERT_EQ(::pipe(pipeFd), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::dup2(pipeFd[1], STDOUT_FILENO);
    ::close(pipeFd[0]);
    ::close(pipeFd[1]);
    ::execl(FOG_RECORD_HELPER, FOG_RECORD_HELPER, path.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(pipeFd[1]);

  // Read its progress lines for ~1.5 s, then kill it mid-recording.
  std::string text;
  char buf[4096];
  const auto start = std::chrono::steady_clock::now();
  const auto killAt = start + std::chrono::milliseconds(1500);
  bool eof = false;
  while (!eof && std::chrono::steady_clock::now() < killAt) {
    pollfd p{pipeFd[0], POLLIN, 0};
    if (::poll(&p, 1, 20) > 0) {
      const auto n = ::read(pipeFd[0], buf, sizeof buf);
      if (n <= 0) eof = true;
      else text.append(buf, static_cast<std::size_t>(n));
    }
  }
  ASSERT_FALSE(eof) << "the helper stopped before it was killed:\n" << text;
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "helper was not killed";
  // Lines written before the kill are still in the pipe.
  for (ssize_t n; (n = ::read(pipeFd[0], buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  ::close(pipeFd[0]);

  HelperLine last;
  std::size_t lines = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    HelperLine h;
    unsigned long long a = 0, c = 0, k = 0;
    if (std::sscanf(line.c_str(), "appended %llu committed %llu commits %llu", &a, &c, &k) == 3) {
      last = {a, c, k};
      ++lines;
    }
  }
  ASSERT_GT(lines, 50u) << text;
  ASSERT_GT(last.commits, 3u) << "the helper should have committed several times in 1.5 s";

  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_FALSE((*r)->complete());
  EXPECT_NE((*r)->incompleteReason().find("interrupted"), std::string::npos);
  EXPECT_EQ((*r)->info().operatorName, "kill test");
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();

  // An exact prefix of the stream ...
  ASSERT_LE(raw->size(), stream.size());
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin())) << "stored bytes are not the stream's prefix";
  // ... holding at least everything the helper had seen committed ...
  EXPECT_GE(raw->size(), last.committed);
  // ... and all but the last 250 ms (+ slack) of what it had produced.
  const double producedS = streamTimeS(stream, static_cast<std::size_t>(last.appended));
  const double storedS = streamTimeS(stream, raw->size());
  const double lostMs = (producedS - storedS) * 1e3;
  std::printf("[ kill -9 ] produced %llu bytes (%.3f s of stream) before the kill, stored %zu bytes (%.3f s), "
              "lost %.1f ms, %llu commits\n",
              static_cast<unsigned long long>(last.appended), producedS, raw->size(), storedS, lostMs,
              static_cast<unsigned long long>(last.commits));
  ::testing::Test::RecordProperty("lost_ms", std::to_string(lostMs));
  EXPECT_GT(producedS, 0.8) << "the helper should have produced about 1.5 s of stream";
  EXPECT_LE(lostMs, static_cast<double>(kPromisedMaxLoss.count()) + 100.0);

  // The interrupted session still analyses: its samples come from the raw stream.
  EXPECT_FALSE((*r)->hasStoredRecording());
  auto rec = (*r)->recording();
  ASSERT_TRUE(rec.isOk()) << rec.status().message();
  EXPECT_GT(rec->testPoints.at(0).table.size(), 100u);
}

}  // namespace
}  // namespace fog::session
