// libFuzzer entry for the analysis: a swing recording whose numbers the input
// chooses, given to analyzeRecording() and the verdict as `analyze` gives them.
//
// The input's first 8 bytes choose the swing (frequency, amplitude, lag,
// sample counts up to 4 000 table and 2 000 gyro samples, axis, pulse
// equivalent); the rest, in 11-byte edits, overwrite single numbers: which
// field (table time or angle, gyro time or increment, lost frames, nominal
// frequency or amplitude, a bench constant, the pulse equivalent), which
// sample, and the value: either one of the extremes below (±1e±300,
// subnormals, NaN, ±inf, huge counts) or 8 raw bytes as a double.
//
// The analysis must return a report or a status with a message, never crash;
// every delay it reports must be finite with a finite, non-negative
// uncertainty; a PASS must rest on finite numbers below the limit; the text
// and JSON reports must be written without a crash.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/analysis/delay_analysis.h"
#include "core/analysis/report_writer.h"
#include "core/analysis/verdict.h"
#include "core/common/units.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

constexpr double kExtremes[] = {0.0,
                                -0.0,
                                1e300,
                                -1e300,
                                1e-300,
                                -1e-300,
                                1e200,
                                1e155,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min() / 2,
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                4294967295.0,
                                9.2e18,
                                1e10,
                                -1.0,
                                1.0};

double valueOf(const std::uint8_t* v) {
  if (v[0] < 128) return kExtremes[v[0] % (sizeof kExtremes / sizeof kExtremes[0])];
  double d;
  std::memcpy(&d, v, sizeof d);
  return d;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 8) return 0;
  const double frequencyHz = 0.05 + data[0] / 16.0;  // 0.05 .. 16 Hz
  const double amplitudeDeg = 0.01 + data[1] / 8.0;
  const double lagS = (static_cast<int>(data[2]) - 64) * 1e-5;
  const std::size_t tableCount = 16 + static_cast<std::size_t>(data[3]) * 15;  // .. 3 841
  const std::size_t imuCount = 8 + static_cast<std::size_t>(data[4]) * 7;      // .. 1 793
  const auto axis = static_cast<fog::Axis>(data[5] % fog::kAxisCount);
  const double pulse = data[6] % 2 ? 5e-5 : 0.0;  // 0: increments in degrees
  const double durationS = 1.0 + data[7] / 4.0;

  fog::Recording rec;
  rec.pulseEquivalentDeg = 1.0;
  fog::TestPointData tp;
  tp.axis = axis;
  tp.nominalFrequencyHz = frequencyHz;
  tp.nominalAmplitudeDeg = amplitudeDeg;
  const auto a = static_cast<std::size_t>(axis);
  const double w = fog::kTwoPi * frequencyHz;
  for (std::size_t i = 0; i < tableCount; ++i) {
    fog::TableSample s;
    s.timeS = durationS * static_cast<double>(i) / static_cast<double>(tableCount);
    s.angleDeg[a] = amplitudeDeg * std::sin(w * s.timeS);
    tp.table.push_back(s);
  }
  double previous = 0.0;
  for (std::size_t k = 0; k < imuCount; ++k) {
    fog::ImuSample s;
    s.timeS = durationS * (static_cast<double>(k) + 0.5) / static_cast<double>(imuCount);
    const double angle = amplitudeDeg * std::sin(w * (s.timeS - lagS));
    s.incrementDeg[a] = pulse > 0.0 ? std::round((angle - previous) / pulse) * pulse : angle - previous;
    previous += s.incrementDeg[a];
    tp.imu.push_back(s);
  }

  fog::BenchConstants constants;
  constants.pulseEquivalentDeg = 5e-5;
  for (std::size_t at = 8; at + 11 <= size; at += 11) {
    const std::uint8_t field = data[at] % 11;
    const std::size_t index = static_cast<std::size_t>(data[at + 1]) << 8 | data[at + 2];
    const double v = valueOf(data + at + 3);
    auto& t = tp.table[index % tp.table.size()];
    auto& g = tp.imu[index % tp.imu.size()];
    switch (field) {
      case 0: t.timeS = v; break;
      case 1: t.angleDeg[a] = v; break;
      case 2: g.timeS = v; break;
      case 3: g.incrementDeg[a] = v; break;
      case 4: g.lostBefore = std::isfinite(v) && v >= 0 && v < 4294967295.0 ? static_cast<std::uint32_t>(v) : 7u; break;
      case 5: tp.nominalFrequencyHz = v; break;
      case 6: tp.nominalAmplitudeDeg = v; break;
      case 7: constants.tableReadDelayMs = v; break;
      case 8: constants.boardDelayMs = v; break;
      case 9: constants.pulseEquivalentDeg = v; break;
      default: rec.pulseEquivalentDeg = v; break;
    }
  }
  rec.testPoints.push_back(std::move(tp));

  auto report = fog::analysis::analyzeRecording(rec, constants);
  if (!report) {
    check(!report.status().message().empty());
    return 0;
  }
  for (const auto& p : report->points) {
    check(std::isfinite(p.lagMs) && std::isfinite(p.lagStdMs) && p.lagStdMs >= 0.0);
    check(std::isfinite(p.crlbMs));
  }
  const auto verdict = fog::analysis::judgeReport(*report, fog::analysis::kDefaultImuDelayLimitMs);
  for (const auto& pv : verdict.points)
    if (pv.verdict == fog::analysis::Verdict::kPass) check(std::isfinite(pv.upperMs) && pv.upperMs < 0.8);
  fog::analysis::ReportContext context;
  check(!fog::analysis::formatReportText(*report, context).empty());
  check(!fog::analysis::formatReportJson(*report, context).empty());
  return 0;
}
