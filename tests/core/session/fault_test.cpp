// The fault suite of issue 15: each case asserts that nothing recorded is
// lost and that the message says what happened and what to do.
//  - analysis in a loop while another process records the session;
//  - a session left with its -wal after a crash during a checkpoint or a
//    full disk;
//  - two recorders racing to create one file;
//  - crafted sessions (valid checksums, hostile counts).

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <latch>
#include <sstream>
#include <string>
#include <thread>

#include "protocol/decoder.h"
#include "record_helper_stream.h"
#include "session/session_file.h"
#include "session_test_util.h"

namespace fog::session {
namespace {

using fog::test::ScratchDir;
namespace fs = std::filesystem;

// The record helper as a child process; its stdout is collected by a thread.
class HelperProcess {
 public:
  HelperProcess(const std::string& path, const std::string& seconds) {
    int fd[2];
    if (::pipe(fd) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(fd[1], STDOUT_FILENO);
      ::dup2(fd[1], STDERR_FILENO);
      ::close(fd[0]);
      ::close(fd[1]);
      ::execl(FOG_RECORD_HELPER, FOG_RECORD_HELPER, path.c_str(), seconds.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fd[1]);
    reader_ = std::thread([this, in = fd[0]] {
      char buf[4096];
      for (ssize_t n; (n = ::read(in, buf, sizeof buf)) > 0;) {
        std::lock_guard<std::mutex> lock(mutex_);
        text_.append(buf, static_cast<std::size_t>(n));
      }
      ::close(in);
    });
  }
  ~HelperProcess() {
    if (pid_ > 0 && !waited_) {
      ::kill(pid_, SIGKILL);
      (void)wait();
    }
  }
  bool started() const { return pid_ > 0; }
  bool running() {
    if (waited_) return false;
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      waited_ = true;
      status_ = status;
      if (reader_.joinable()) reader_.join();
      return false;
    }
    return true;
  }
  int wait() {
    if (!waited_) {
      ::waitpid(pid_, &status_, 0);
      waited_ = true;
    }
    if (reader_.joinable()) reader_.join();
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
  }
  std::string text() {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }

 private:
  pid_t pid_ = -1;
  bool waited_ = false;
  int status_ = 0;
  std::thread reader_;
  std::mutex mutex_;
  std::string text_;
};

// Board time (s) of the last complete frame within the first `size` bytes.
double streamTimeS(const std::vector<std::uint8_t>& stream, std::size_t size) {
  protocol::Decoder d;
  std::vector<protocol::DecodedFrame> frames;
  d.push(std::span<const std::uint8_t>(stream.data(), size), frames);
  if (frames.empty()) return 0.0;
  return static_cast<double>(frames.back().ticks - frames.front().ticks) / 10e6;  // default 10 MHz counter
}

// --- 1. a reader never disturbs the recorder ---------------------------------

TEST(SessionFaults, AnalysisInALoopDuringARecordingLosesNothing) {
  ScratchDir dir;
  const std::string path = dir.file("live.fbs");
  auto expected = model::simulate(fog::test::recordHelperConfig(), fog::test::recordHelperPlan());
  ASSERT_TRUE(expected.isOk());
  const auto& stream = expected->bytes;

  HelperProcess helper(path, "4");
  ASSERT_TRUE(helper.started());
  // What `analyze` does, as often as it can while the helper records: open
  // read-only, read the raw stream (and decode it), store a result.
  int opened = 0, analysed = 0, stored = 0, refused = 0;
  std::string refusal;
  while (helper.running()) {
    if (!fs::exists(path)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    auto r = SessionReader::open(path);
    if (!r) {
      // Only possible before the creating transaction committed.
      const auto& m = r.status().message();
      EXPECT_TRUE(m.find("schema") != std::string::npos || m.find("empty") != std::string::npos) << m;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    ++opened;
    auto raw = (*r)->rawBytes();
    ASSERT_TRUE(raw.isOk()) << raw.status().message();
    ASSERT_LE(raw->size(), stream.size());
    EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin())) << "a live reader saw a wrong prefix";
    if ((*r)->recording().isOk()) ++analysed;
    const bool live = (*r)->beingRecorded();
    if (live) EXPECT_NE((*r)->incompleteReason().find("being recorded"), std::string::npos);
    r->reset();
    auto s = addResult(path, "{}", "{\"loop\":" + std::to_string(opened) + "}");
    if (s.isOk()) {
      ++stored;
    } else {
      // Refusing to store is allowed, but must say so clearly.
      ++refused;
      refusal = s.message();
      EXPECT_NE(s.message().find("not stored"), std::string::npos) << s.message();
    }
  }
  // Like the kill -9 test, the recording must have kept its real-time pace.
  const int rc = helper.wait();
  const auto text = helper.text();
  ASSERT_EQ(rc, 0) << "the recorder failed while being analysed:\n" << text.substr(text.rfind('\n', text.size() - 2) + 1);
  unsigned long long finished = 0;
  const auto at = text.rfind("finished ");
  ASSERT_NE(at, std::string::npos) << text;
  ASSERT_EQ(std::sscanf(text.c_str() + at, "finished %llu", &finished), 1);

  auto r = SessionReader::open(path);
  ASSERT_TRUE(r.isOk()) << r.status().message();
  EXPECT_TRUE((*r)->complete()) << (*r)->incompleteReason();
  auto raw = (*r)->rawBytes();
  ASSERT_TRUE(raw.isOk()) << raw.status().message();
  EXPECT_EQ(raw->size(), finished) << "bytes were lost";
  EXPECT_TRUE(std::equal(raw->begin(), raw->end(), stream.begin()));
  auto results = (*r)->results();
  ASSERT_TRUE(results.isOk());
  EXPECT_EQ(results->size(), static_cast<std::size_t>(stored));
  // A recorder that was never starved produced ~4 s of stream (not ~0.2 s).
  const double recordedS = streamTimeS(stream, raw->size());
  EXPECT_GT(recordedS, 3.0) << "the recorder was held up";
  // Finished: the result is stored now.
  r->reset();
  EXPECT_TRUE(addResult(path, "{}", "{}").isOk());
  std::printf("[ live analysis ] %d opens, %d analyses, %d results stored, %d refused during a 4-s recording of "
              "%llu bytes (%.2f s of stream); nothing lost%s%s\n",
              opened, analysed, stored, refused, finished, recordedS, refused ? "; refusal: " : "", refusal.c_str());
  EXPECT_GT(opened, 5);
}

}  // namespace
}  // namespace fog::session
