// fog_session_record_helper SESSION.fbs [SECONDS]: records a simulated stream
// into a new session paced in real time (the simulator advanced to the wall
// clock every 10 ms, as a serial source would deliver it), printing one line
// per append:  "appended <bytes> committed <bytes> commits <n>". Used by the
// kill -9 test, which kills it mid-recording, and by the concurrent-reader
// test, which gives SECONDS: the helper then stops appending after SECONDS of
// wall time, finishes the session and prints "finished <bytes>". The stream
// is model::simulate(recordHelperConfig(), recordHelperPlan()).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/model/simulator.h"
#include "record_helper_stream.h"
#include "core/session/session_file.h"

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: fog_session_record_helper SESSION.fbs [SECONDS]\n");
    return 2;
  }
  const double stopAfterS = argc == 3 ? std::atof(argv[2]) : 1e9;
  auto sim = fog::model::Simulator::create(fog::test::recordHelperConfig(), fog::test::recordHelperPlan());
  if (!sim) {
    std::fprintf(stderr, "%s\n", sim.status().message().c_str());
    return 1;
  }
  fog::SessionInfo info;
  info.operatorName = "kill test";
  info.source = "simulator, real-time pacing";
  info.plan = fog::test::recordHelperPlan();
  auto writer = fog::session::SessionWriter::create(argv[1], info);
  if (!writer) {
    std::fprintf(stderr, "%s\n", writer.status().message().c_str());
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::uint8_t> buf;
  bool more = true;
  while (more) {
    const double elapsedS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsedS >= stopAfterS) break;
    buf.clear();
    more = (*sim)->advance(elapsedS, buf);
    if (auto s = (*writer)->appendRaw(buf.data(), buf.size()); !s.isOk()) {
      std::fprintf(stderr, "%s\n", s.message().c_str());
      return 1;
    }
    std::printf("appended %llu committed %llu commits %llu\n",
                static_cast<unsigned long long>((*writer)->appendedBytes()),
                static_cast<unsigned long long>((*writer)->committedBytes()),
                static_cast<unsigned long long>((*writer)->commits()));
    std::fflush(stdout);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (auto s = (*writer)->finish(true, ""); !s.isOk()) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 1;
  }
  std::printf("finished %llu\n", static_cast<unsigned long long>((*writer)->appendedBytes()));
  return 0;
}
