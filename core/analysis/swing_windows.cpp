#include "core/analysis/swing_windows.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <deque>
#include <optional>
#include <string_view>

#include "core/analysis/channels.h"
#include "core/analysis/validity.h"

namespace fog::analysis {

namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

constexpr double kRestS = 1.0;               // a rest lasts at least this long
constexpr double kAmplitudeTolerance = 0.01; // steady: within 1 % of the median amplitude

// The steady part of one stretch of motion, or nothing.
std::optional<SwingWindow> steadyPart(const std::vector<TableSample>& table, std::size_t from, std::size_t to,
                                      std::size_t axis) {
  TableChannel ch;
  for (std::size_t i = from; i < to; ++i) {
    ch.timeS.push_back(table[i].timeS);
    ch.angleDeg.push_back(table[i].angleDeg[axis]);
  }
  auto f = estimateSwingFrequencyHz(ch);
  if (!f) return std::nullopt;
  const double period = 1.0 / *f;
  // Amplitude per whole period: half the peak-to-peak.
  std::vector<double> amplitude, start;
  std::size_t i = 0;
  for (double a = ch.timeS.front(); a + period <= ch.timeS.back(); a += period) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (; i < ch.timeS.size() && ch.timeS[i] < a + period; ++i) {
      lo = std::min(lo, ch.angleDeg[i]);
      hi = std::max(hi, ch.angleDeg[i]);
    }
    amplitude.push_back(0.5 * (hi - lo));
    start.push_back(a);
  }
  if (amplitude.size() < 2) return std::nullopt;
  const double median = percentile(amplitude, 0.5);
  std::size_t bestFrom = 0, bestLength = 0;
  for (std::size_t k = 0; k < amplitude.size();) {
    if (std::abs(amplitude[k] / median - 1.0) > kAmplitudeTolerance) {
      ++k;
      continue;
    }
    std::size_t e = k;
    while (e < amplitude.size() && std::abs(amplitude[e] / median - 1.0) <= kAmplitudeTolerance) ++e;
    if (e - k > bestLength) {
      bestLength = e - k;
      bestFrom = k;
    }
    k = e;
  }
  // The run's first and last periods may touch a ramp (their amplitude
  // within tolerance, the next one's not): they are left out.
  if (bestLength >= 4) {
    ++bestFrom;
    bestLength -= 2;
  }
  if (bestLength < 2) return std::nullopt;
  SwingWindow w;
  w.startS = start[bestFrom];
  w.endS = start[bestFrom + bestLength - 1] + period;
  w.frequencyHz = *f;
  w.amplitudeDeg = median;
  return w;
}

}  // namespace

Result<std::vector<SwingWindow>> findSwingWindows(const std::vector<TableSample>& table, Axis axis) {
  const auto a = static_cast<std::size_t>(axis);
  if (table.size() < 64) return insufficientData("too few table samples to find swing windows");
  std::vector<double> steps;
  steps.reserve(table.size());
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (std::size_t i = 0; i < table.size(); ++i) {
    lo = std::min(lo, table[i].angleDeg[a]);
    hi = std::max(hi, table[i].angleDeg[a]);
    if (i) steps.push_back(std::abs(table[i].angleDeg[a] - table[i - 1].angleDeg[a]));
  }
  if (!(hi > lo)) return insufficientData("the table did not move on the " + std::string(axisName(axis)) + " axis");
  const double band = std::max(20.0 * percentile(steps, 0.1), 1e-4 * (hi - lo));

  // Rest: the angle stays within the band over a trailing second (sliding
  // minimum and maximum with monotonic queues; rest intervals marked by a
  // difference array), O(N).
  std::vector<int> restCount(table.size() + 1, 0);
  std::deque<std::size_t> mins, maxs;
  std::size_t j = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const double v = table[i].angleDeg[a];
    while (!mins.empty() && table[mins.back()].angleDeg[a] >= v) mins.pop_back();
    while (!maxs.empty() && table[maxs.back()].angleDeg[a] <= v) maxs.pop_back();
    mins.push_back(i);
    maxs.push_back(i);
    while (table[i].timeS - table[j].timeS > kRestS) ++j;
    while (mins.front() < j) mins.pop_front();
    while (maxs.front() < j) maxs.pop_front();
    if (table[i].timeS - table[j].timeS < 0.9 * kRestS) continue;
    if (table[maxs.front()].angleDeg[a] - table[mins.front()].angleDeg[a] < band) {
      ++restCount[j];
      --restCount[i + 1];
    }
  }
  std::vector<bool> rest(table.size(), false);
  long long level = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    level += restCount[i];
    rest[i] = level > 0;
  }
  std::vector<SwingWindow> windows;
  for (std::size_t i = 0; i < table.size();) {
    if (rest[i]) {
      ++i;
      continue;
    }
    std::size_t e = i;
    while (e < table.size() && !rest[e]) ++e;
    if (auto w = steadyPart(table, i, e, a)) windows.push_back(*w);
    i = e;
  }
  if (windows.empty())
    return insufficientData("no steady swing of two or more whole periods found on the " +
                            std::string(axisName(axis)) + " axis; give the windows yourself (--segment START-END,...)");
  return windows;
}

namespace {

// A whole field as one finite number of seconds within the range a time
// stamp may take (the CSV reader's): from_chars stops at the first character
// it cannot use, so "1e" of "1e-300" read as 1.
bool wholeSeconds(std::string_view s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && std::isfinite(out) &&
         std::abs(out) <= 1e10;
}

// "START-END": the separating dash is the one whose both sides read whole
// (an exponent's or a sign's dash does not), e.g. "1e-3-2e-3", "-5--2".
bool splitWindow(std::string_view item, double& start, double& end) {
  for (std::size_t dash = item.find('-', 1); dash != std::string_view::npos; dash = item.find('-', dash + 1))
    if (wholeSeconds(item.substr(0, dash), start) && wholeSeconds(item.substr(dash + 1), end)) return true;
  return false;
}

}  // namespace

Result<std::vector<SwingWindow>> parseSwingWindows(const std::string& text) {
  std::vector<SwingWindow> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    const auto end = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, end - at);
    SwingWindow w;
    const bool ok = splitWindow(item, w.startS, w.endS) && w.endS > w.startS &&
                    (out.empty() || w.startS >= out.back().endS);
    if (!ok)
      return invalidArgument("--segment takes 'auto' or windows START-END in seconds, ascending and not overlapping, "
                             "separated by commas (e.g. 5-35,40.5-70), not '" + item + "'");
    out.push_back(w);
    at = end + 1;
  }
  return out;
}

std::vector<TestPointData> splitIntoWindows(const TestPointData& whole, const std::vector<SwingWindow>& windows) {
  std::vector<TestPointData> out;
  for (const auto& w : windows) {
    TestPointData tp;
    tp.index = static_cast<int>(out.size());
    tp.axis = whole.axis;
    tp.kind = TestPointKind::kSwing;
    tp.nominalFrequencyHz = w.frequencyHz;
    tp.nominalAmplitudeDeg = w.amplitudeDeg;
    for (const auto& s : whole.table)
      if (s.timeS >= w.startS && s.timeS <= w.endS) tp.table.push_back(s);
    for (const auto& s : whole.imu)
      if (s.timeS >= w.startS && s.timeS <= w.endS) tp.imu.push_back(s);
    out.push_back(std::move(tp));
  }
  return out;
}

}  // namespace fog::analysis
