// Writes an imported-bench session as CSV (docs/formats.md) for
// diagnose_bounded.cmake: a damped pendulum about X, 20 deg at 0.5 Hz
// decaying as exp(-0.03 t), 60 s, table angles at 90 Hz and gyro increments
// at 50 Hz 0.5 ms behind them, every stamp jittered by N(0, JITTER_S) (the
// recording of the unbounded-memory issue; /tmp/repro/gen.py made it so).
//
//   fog_pendulum_csv DIR JITTER_S
//
// Deterministic (fixed seed). Exit 0, or 2 with a line on stderr.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

namespace {

constexpr double kPi = 3.14159265358979323846;

double angleDeg(double t) { return 20.0 * std::exp(-0.03 * t) * std::sin(2.0 * kPi * 0.5 * t); }

bool writeFile(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fog_pendulum_csv DIR JITTER_S\n");
    return 2;
  }
  const std::string dir = argv[1];
  const double jitterS = std::atof(argv[2]);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> normal(0.0, 1.0);
  char line[128];
  std::string table = "time_s,x_deg\n", gyro = "time_s,x_inc_deg\n";
  for (int k = 0; k < 90 * 60; ++k) {
    const double t = k / 90.0;
    std::snprintf(line, sizeof line, "%.6f,%.9g\n", t + jitterS * normal(rng), angleDeg(t));
    table += line;
  }
  const double lag = 0.5e-3, h = 1.0 / 50.0;
  for (int k = 0; k < 50 * 60; ++k) {
    const double t = k * h;
    std::snprintf(line, sizeof line, "%.6f,%.12g\n", t + jitterS * normal(rng), angleDeg(t - lag) - angleDeg(t - lag - h));
    gyro += line;
  }
  const std::string meta =
      R"({"bench": {"table_read_delay_ms": 0.05, "board_delay_ms": 0.28, "pulse_equivalent_deg": 5e-05},)"
      R"( "test_points": [{"axis": "x", "frequency_hz": 0.5, "amplitude_deg": 20}]})";
  if (!writeFile(dir + "/metadata.json", meta) || !writeFile(dir + "/table.csv", table) ||
      !writeFile(dir + "/gyro.csv", gyro)) {
    std::fprintf(stderr, "fog_pendulum_csv: cannot write the CSV files in %s\n", dir.c_str());
    return 2;
  }
  return 0;
}
