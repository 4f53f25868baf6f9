// fog_make_sessions DIR COUNT [PRESET|short [FIRST]]: writes COUNT distinct finished
// session files of one simulated run (as `fogbench-cli run --out` leaves
// them: raw stream, decoded samples, one stored result), with serials
// SN-0001… (from FIRST, default 1: two processes can share the work), lots of 40 units (L01, L02, …), two benches and creation times an
// hour apart — the input of the catalog and batch benchmarks
// (bench/catalog_bench.sh, docs/benchmarks.md). "short": 8 s at 1 Hz on z.
// Simulating once and writing COUNT times keeps making 1 000 4.9-min
// sessions a matter of disk speed.

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>

#include "core/common/test_plan.h"
#include "core/model/simulator.h"
#include "core/protocol/recording_builder.h"
#include "core/session/session_api.h"
#include "core/session/session_file.h"

int main(int argc, char** argv) {
  using namespace fog;
  if (argc < 3) {
    std::fprintf(stderr, "usage: fog_make_sessions DIR COUNT [PRESET|short [FIRST]]\n");
    return 2;
  }
  const std::string dir = argv[1];
  const int count = std::atoi(argv[2]);
  const std::string preset = argc > 3 ? argv[3] : "paper-slow";
  const int first = argc > 4 ? std::atoi(argv[4]) : 1;
  TestPlan plan;
  if (preset == "short") {
    TestPoint p;
    p.axis = Axis::kZ;
    p.frequencyHz = 1.0;
    p.amplitudeDeg = 3.0;
    p.durationS = 8.0;
    p.settleS = 2.0;
    plan.points.push_back(p);
  } else {
    auto pp = presetPlan(preset);
    if (!pp) {
      std::fprintf(stderr, "%s\n", pp.status().message().c_str());
      return 2;
    }
    plan = *pp;
  }
  model::SimConfig config;
  config.seed = 7;
  auto run = model::simulate(config, plan);
  if (!run) return std::fprintf(stderr, "%s\n", run.status().message().c_str()), 1;
  auto decoded = protocol::decodeRecording(run->bytes);
  if (!decoded) return std::fprintf(stderr, "%s\n", decoded.status().message().c_str()), 1;
  std::filesystem::create_directories(dir);
  const std::time_t start = 1793520000;  // 2026-11-01T00:00:00Z
  for (int i = first - 1; i < first - 1 + count; ++i) {
    SessionInfo info;
    char serial[32], lot[16], when[32];
    std::snprintf(serial, sizeof serial, "SN-%04d", i + 1);
    std::snprintf(lot, sizeof lot, "L%02d", i / 40 + 1);
    const std::time_t t = start + static_cast<std::time_t>(i) * 3600;
    std::tm tm{};
    gmtime_r(&t, &tm);
    std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &tm);
    info.imuSerial = serial;
    info.imuModel = "FOG-3";
    info.lot = lot;
    info.benchId = i % 2 ? "B2" : "B1";
    info.operatorName = "bench";
    info.createdUtc = when;
    info.source = "simulator, seed 7";
    info.plan = plan;
    const std::string path = dir + "/" + serial + session::kFileExtension;
    auto w = session::SessionWriter::create(path, info);
    if (!w) return std::fprintf(stderr, "%s\n", w.status().message().c_str()), 1;
    if (!(*w)->appendRaw(run->bytes.data(), run->bytes.size()).isOk() || !(*w)->storeRecording(*decoded).isOk() ||
        !(*w)->finish(true, "").isOk())
      return std::fprintf(stderr, "writing %s failed\n", path.c_str()), 1;
    auto opened = session::openSessionOrStream(path);
    if (!opened) return std::fprintf(stderr, "%s\n", opened.status().message().c_str()), 1;
    session::AnalysisSettings settings;
    settings.producedBy = "fog_make_sessions";
    const auto stored = session::analyseAndStore(*opened, settings);
    if (!stored.stored) return std::fprintf(stderr, "%s: not stored: %s\n", path.c_str(), stored.notStored.c_str()), 1;
  }
  std::printf("%d sessions (%s) in %s\n", count, preset.c_str(), dir.c_str());
  return 0;
}
