// CSV import and export of a long session: 30 min of table angles at 1 kHz
// (1.8 M rows) and gyro increments at 500 Hz (0.9 M rows), numbers as the
// decoder produces them (micro-degree angles, 5e-5 deg pulses), written with
// the exporter's shortest round-trip text. Reported per whole session.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "core/io/csv_export.h"
#include "core/io/csv_import.h"

namespace {

constexpr double kSessionS = 1800.0;

fog::Recording longSession() {
  fog::Recording rec;
  rec.pulseEquivalentDeg = 5e-5;
  fog::TestPointData p;
  p.nominalFrequencyHz = 0.1;
  p.nominalAmplitudeDeg = 10.0;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 1e-4);
  const auto angle = [](double t) { return 10.0 * std::sin(2.0 * 3.141592653589793 * 0.1 * t); };
  const auto ms = static_cast<long>(kSessionS * 1000.0);
  p.table.reserve(static_cast<std::size_t>(ms));
  p.imu.reserve(static_cast<std::size_t>(ms / 2));
  long lastPulses = 0;
  for (long k = 0; k < ms; ++k) {
    const double t = 3.0 + static_cast<double>(k) * 1e-3;
    fog::TableSample s;
    s.timeS = t;
    s.angleDeg[0] = std::round((angle(t) + noise(rng)) * 1e6) * 1e-6;
    s.angleDeg[1] = std::round(noise(rng) * 1e6) * 1e-6;
    p.table.push_back(s);
    if (k % 2 == 0) {
      const long pulses = std::lround(std::floor(angle(t - 5e-4) / 5e-5));
      fog::ImuSample g;
      g.timeS = t + 5.8e-4;
      g.incrementDeg[0] = static_cast<double>(pulses - lastPulses) * 5e-5;
      g.temperatureC = 25.0 + static_cast<double>(k) * 1e-6;
      p.imu.push_back(g);
      lastPulses = pulses;
    }
  }
  rec.testPoints.push_back(std::move(p));
  return rec;
}

std::string benchDir() {
  return (std::filesystem::temp_directory_path() / "fog_bench_io").string();
}

fog::SessionInfo sessionInfo() {
  fog::SessionInfo info;
  info.plan.points.push_back({fog::Axis::kX, 0.1, 10.0, kSessionS, 5.0, 0.0});
  return info;
}

void BM_ExportCsv30Min(benchmark::State& state) {
  const fog::Recording rec = longSession();
  const fog::SessionInfo info = sessionInfo();
  for (auto _ : state) {
    const fog::Status s = fog::io::exportCsv(benchDir(), info, rec, nullptr, /*overwrite=*/true);
    if (!s.isOk()) state.SkipWithError(s.toString().c_str());
  }
}
BENCHMARK(BM_ExportCsv30Min)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ImportCsv30Min(benchmark::State& state) {
  {
    const fog::Status s = fog::io::exportCsv(benchDir(), sessionInfo(), longSession(), nullptr, true);
    if (!s.isOk()) {
      state.SkipWithError(s.toString().c_str());
      return;
    }
  }
  std::uintmax_t bytes = 0;
  for (const char* f : {"table.csv", "gyro.csv"}) bytes += std::filesystem::file_size(benchDir() + "/" + f);
  std::size_t rows = 0;
  for (auto _ : state) {
    auto r = fog::io::importCsvDirectory(benchDir());
    if (!r) {
      state.SkipWithError(r.status().toString().c_str());
      break;
    }
    rows = r->recording.testPoints[0].table.size() + r->recording.testPoints[0].imu.size();
    benchmark::DoNotOptimize(r);
  }
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_ImportCsv30Min)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
