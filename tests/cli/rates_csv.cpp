// Writes an imported-bench recording as CSV (docs/formats.md) for
// constants.cmake: a steady 1 Hz / 3 deg swing about X for 20 s, table
// angles at 1 kHz, and the gyro as rates, one row per 2-ms IMU frame, each
// the frame's angle increment (0.5 ms behind the table) over 2 ms: the
// "frame_average" convention, whose frame period the import is told
// (--frame-period-ms). The metadata states neither convention nor period.
// White noise on both (fixed seed): deterministic.
//
//   fog_rates_csv DIR
//
// Exit 0, or 2 with a line on stderr.

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace {

constexpr double kPi = 3.14159265358979323846;

double angleDeg(double t) { return 3.0 * std::sin(2.0 * kPi * t + 0.4); }

bool writeFile(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fog_rates_csv DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  char line[128];
  std::string table = "time_s,x_deg\n", gyro = "time_s,x_rate_deg_s\n";
  for (int ms = 0; ms < 20000; ++ms) {
    const double t = 0.5 + ms * 1e-3;
    std::snprintf(line, sizeof line, "%.6f,%.9f\n", t, angleDeg(t) + 2e-4 * normal(rng));
    table += line;
  }
  const double lag = 0.5e-3, frame = 2e-3;
  for (int k = 1; k <= 10000; ++k) {
    const double t = 0.5 + k * frame;
    const double rate = (angleDeg(t - lag) - angleDeg(t - lag - frame)) / frame + 0.05 * normal(rng);
    std::snprintf(line, sizeof line, "%.6f,%.12g\n", t, rate);
    gyro += line;
  }
  const std::string meta =
      R"({"bench": {"table_read_delay_ms": 0.05, "board_delay_ms": 0.28, "pulse_equivalent_deg": 1e-06},)"
      R"( "test_points": [{"axis": "x", "frequency_hz": 1, "amplitude_deg": 3}]})";
  if (!writeFile(dir + "/metadata.json", meta) || !writeFile(dir + "/table.csv", table) ||
      !writeFile(dir + "/gyro.csv", gyro)) {
    std::fprintf(stderr, "fog_rates_csv: cannot write the CSV files in %s\n", dir.c_str());
    return 2;
  }
  return 0;
}
