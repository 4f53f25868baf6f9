// Session files (docs/sessions.md):
//  - BM_SessionRecord: recording a 60-s simulated stream (1 kHz table + 500 Hz
//    IMU, 3 axes) as the recorder does it: raw bytes appended in 10-ms pieces,
//    then the decoded samples, then finish. Counter x_realtime = stream
//    seconds written per wall-clock second (target >= 50).
//  - BM_SessionOpenAnalyse30Min: open a 30-min session (0.1 Hz / 10 deg),
//    read its stored samples and analyse them.
//  - BM_SessionOpenRead30Min / BM_SessionRawDecode30Min: the open + read part
//    alone, from the stored samples and from the raw stream (the path after a
//    crash, when no samples were stored).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "core/analysis/delay_analysis.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_file.h"

namespace {

namespace fs = std::filesystem;

struct Stream {
  fog::TestPlan plan;
  std::vector<std::uint8_t> bytes;
  fog::Recording recording;
  double seconds = 0.0;
};

Stream makeStream(double frequencyHz, double amplitudeDeg, double durationS) {
  fog::TestPoint p;
  p.frequencyHz = frequencyHz;
  p.amplitudeDeg = amplitudeDeg;
  p.durationS = durationS;
  p.settleS = 1.0;
  Stream s;
  s.plan.points.push_back(p);
  auto run = fog::model::simulate(fog::model::SimConfig{}, s.plan);
  if (!run) std::abort();
  s.bytes = std::move(run->bytes);
  s.recording = *fog::protocol::decodeRecording(s.bytes);
  s.seconds = s.plan.totalDurationS();
  return s;
}

fs::path scratch() {
  static const fs::path dir = [] {
    auto d = fs::temp_directory_path() / ("fog_session_bench_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

fog::Status writeSession(const std::string& path, const Stream& s, std::size_t piece) {
  fog::SessionInfo info;
  info.plan = s.plan;
  auto w = fog::session::SessionWriter::create(path, info);
  if (!w) return w.status();
  for (std::size_t at = 0; at < s.bytes.size(); at += piece)
    if (auto st = (*w)->appendRaw(s.bytes.data() + at, std::min(piece, s.bytes.size() - at)); !st.isOk()) return st;
  if (auto st = (*w)->storeRecording(s.recording); !st.isOk()) return st;
  return (*w)->finish(true, "");
}

void BM_SessionRecord(benchmark::State& state) {
  static const Stream s = makeStream(1.0, 3.0, 60.0);
  // 10 ms of stream per appendRaw call, as a serial read would deliver it.
  const auto piece = static_cast<std::size_t>(static_cast<double>(s.bytes.size()) / s.seconds * 0.01);
  int n = 0;
  for (auto _ : state) {
    const auto path = (scratch() / ("rec" + std::to_string(n++) + ".fbs")).string();
    if (auto st = writeSession(path, s, piece); !st.isOk()) state.SkipWithError(st.message().c_str());
    state.PauseTiming();
    fs::remove(path);
    state.ResumeTiming();
  }
  state.counters["x_realtime"] = benchmark::Counter(s.seconds * static_cast<double>(state.iterations()),
                                                    benchmark::Counter::kIsRate);
  state.SetBytesProcessed(static_cast<std::int64_t>(s.bytes.size()) * state.iterations());
}
BENCHMARK(BM_SessionRecord)->Unit(benchmark::kMillisecond)->UseRealTime();

const std::string& thirtyMinuteSession() {
  static const std::string path = [] {
    const Stream s = makeStream(0.1, 10.0, 1800.0);
    const auto p = (scratch() / "thirty.fbs").string();
    fs::remove(p);
    if (auto st = writeSession(p, s, 1 << 16); !st.isOk()) std::abort();
    return p;
  }();
  return path;
}

void BM_SessionOpenAnalyse30Min(benchmark::State& state) {
  const auto& path = thirtyMinuteSession();
  for (auto _ : state) {
    auto r = fog::session::SessionReader::open(path);
    auto rec = (*r)->recording();
    auto report = fog::analysis::analyzeRecording(*rec, fog::BenchConstants{});
    if (!report) state.SkipWithError(report.status().message().c_str());
    benchmark::DoNotOptimize(report);
  }
  state.counters["file_MB"] = static_cast<double>(fs::file_size(path)) / 1e6;
}
BENCHMARK(BM_SessionOpenAnalyse30Min)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SessionOpenRead30Min(benchmark::State& state) {
  const auto& path = thirtyMinuteSession();
  for (auto _ : state) {
    auto r = fog::session::SessionReader::open(path);
    auto rec = (*r)->recording();
    if (!rec) state.SkipWithError(rec.status().message().c_str());
    benchmark::DoNotOptimize(rec);
  }
}
BENCHMARK(BM_SessionOpenRead30Min)->Unit(benchmark::kMillisecond)->UseRealTime();

// What opening a session for analysis now adds (session_api's check that
// the raw stream still vouches for the stored samples): every chunk read and
// its checksum computed, none kept.
void BM_SessionCheckRawStream30Min(benchmark::State& state) {
  const auto& path = thirtyMinuteSession();
  for (auto _ : state) {
    auto r = fog::session::SessionReader::open(path);
    const auto status = (*r)->checkRawStream();
    if (!status.isOk()) state.SkipWithError(status.message().c_str());
  }
  state.counters["raw_MB"] = 0.0;
  if (auto r = fog::session::SessionReader::open(path)) state.counters["raw_MB"] = static_cast<double>((*r)->rawByteCount()) / 1e6;
}
BENCHMARK(BM_SessionCheckRawStream30Min)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SessionRawDecode30Min(benchmark::State& state) {
  const auto& path = thirtyMinuteSession();
  for (auto _ : state) {
    auto r = fog::session::SessionReader::open(path);
    auto raw = (*r)->rawBytes();
    auto rec = fog::protocol::decodeRecording(*raw);
    if (!rec) state.SkipWithError(rec.status().message().c_str());
    benchmark::DoNotOptimize(rec);
  }
}
BENCHMARK(BM_SessionRawDecode30Min)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ec;
  fs::remove_all(scratch(), ec);
  return 0;
}
