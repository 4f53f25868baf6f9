#include "core/analysis/data_coverage.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <cstdio>
#include <vector>

#include "core/analysis/sample_passes.h"
#include "core/analysis/statistics.h"
#include "core/common/test_plan.h"

namespace fog::analysis {

namespace {

std::string fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

template <typename Sample>
double medianInterval(const std::vector<Sample>& s, bool imu) {
  countPass(imu ? SampleStream::kGyro : SampleStream::kTable);
  std::vector<double> d;
  d.reserve(s.size());
  for (std::size_t i = 1; i < s.size(); ++i) {
    if constexpr (std::is_same_v<Sample, ImuSample>)
      if (imu && s[i].lostBefore != 0) continue;
    d.push_back(s[i].timeS - s[i - 1].timeS);
  }
  return medianElement(d);
}

}  // namespace

DataCoverage measureCoverage(const TestPointData& data) {
  DataCoverage c;
  if (data.table.size() < 2 || data.imu.size() < 2) return c;
  const double start = std::max(data.table.front().timeS, data.imu.front().timeS);
  const double end = std::min(data.table.back().timeS, data.imu.back().timeS);
  c.spanS = std::max(end - start, 0.0);

  // Table: stamps on a regular grid; a longer interval is a gap.
  double tableMissingS = 0.0;
  if (const double dt = medianInterval(data.table, false); dt > 0.0) {
    countPass(SampleStream::kTable);
    for (std::size_t i = 1; i < data.table.size(); ++i) {
      const double interval = data.table[i].timeS - data.table[i - 1].timeS;
      if (interval <= 1.5 * dt) continue;
      // Bounded before the conversion: a time of 1e300 in an imported file
      // must not overflow it (the gap's size then says what is wrong).
      const double missing = std::clamp(std::round(interval / dt) - 1.0, 1.0, 1e15);
      c.lostTableFrames += static_cast<std::size_t>(missing);
      tableMissingS += interval - dt;
      c.largestGapS = std::max(c.largestGapS, interval - dt);
    }
  }
  // IMU: the sequence gap says how many frames are missing.
  double imuMissingS = 0.0;
  if (const double dt = medianInterval(data.imu, true); dt > 0.0) {
    countPass(SampleStream::kGyro);
    for (std::size_t i = 1; i < data.imu.size(); ++i) {
      const auto lost = data.imu[i].lostBefore;
      if (lost == 0) continue;
      c.lostImuFrames += lost;
      const double gap = std::max(data.imu[i].timeS - data.imu[i - 1].timeS - dt, lost * dt);
      imuMissingS += gap;
      c.largestGapS = std::max(c.largestGapS, gap);
    }
  }
  c.missingS = std::min(std::max(tableMissingS, imuMissingS), c.spanS);
  return c;
}

std::string coverageRefusal(const DataCoverage& c, double frequencyHz) {
  if (!(frequencyHz > 0.0) || !(c.spanS > 0.0)) return {};
  const double period = 1.0 / frequencyHz;
  const std::string lost = " (" + std::to_string(c.lostTableFrames) + " table and " +
                           std::to_string(c.lostImuFrames) + " IMU frames lost)";
  if (c.largestGapS > period)
    return "a gap of " + fmt("%.2f", c.largestGapS) + " s without data is longer than one swing period (" +
           fmt("%.2f", period) + " s)" + lost + "; no delay is fitted across it: record the point again";
  if (c.missingS > 0.0 && c.coveredS() * frequencyHz < kMinSwingPeriods)
    return "the data cover " + fmt("%.2f", c.coveredS() * frequencyHz) +
           " swing periods once gaps are removed" + lost + "; a delay needs at least two whole periods";
  if (c.missingS > kMaxMissingFraction * c.spanS)
    return fmt("%.1f", 100.0 * c.missingS / c.spanS) + " % of the record is missing" + lost +
           " (at most " + fmt("%.0f", 100.0 * kMaxMissingFraction) + " % may be); record the point again";
  return {};
}

}  // namespace fog::analysis
