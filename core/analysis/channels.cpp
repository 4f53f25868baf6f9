#include "core/analysis/channels.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/analysis/sample_passes.h"
#include "core/analysis/statistics.h"
#include "core/common/units.h"

namespace fog::analysis {

void GyroChannel::setNoise(double qDeg2PerS, double s2Deg2) {
  arwVarianceDeg2PerS = qDeg2PerS;
  quantisationVarianceDeg2 = s2Deg2;
  const std::size_t n = size();
  countPass(SampleStream::kGyro);
  cholDiag.assign(n, 0.0);
  cholSub.assign(n, 0.0);
  // Each factor entry is a division and a square root that wait for the
  // previous entry: about 40 cycles a frame. With equal intervals the
  // recursion settles (to the bit, or into a short cycle) within some
  // hundreds of frames, so the last few (diag, previous entry) -> (sub,
  // entry) results are kept and reused when the same inputs come again:
  // the same inputs give the same doubles, so the factor is unchanged.
  constexpr int kMemo = 4;
  double memoDiag[kMemo], memoPrev[kMemo], memoSub[kMemo], memoChol[kMemo];
  int memoSize = 0, memoNext = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double diag = qDeg2PerS * (endS[k] - startS[k]) + 2.0 * s2Deg2;
    double sub = 0.0;
    if (k > 0 && continuesPrevious[k]) {
      const double prev = cholDiag[k - 1];
      int hit = -1;
      for (int m = 0; m < memoSize; ++m)
        if (memoDiag[m] == diag && memoPrev[m] == prev) hit = m;
      if (hit >= 0) {
        cholSub[k] = memoSub[hit];
        cholDiag[k] = memoChol[hit];
        continue;
      }
      sub = -s2Deg2 / prev;
      cholSub[k] = sub;
      cholDiag[k] = std::sqrt(std::max(diag - sub * sub, 1e-30));
      memoDiag[memoNext] = diag;
      memoPrev[memoNext] = prev;
      memoSub[memoNext] = sub;
      memoChol[memoNext] = cholDiag[k];
      memoNext = (memoNext + 1) % kMemo;
      memoSize = std::min(memoSize + 1, kMemo);
      continue;
    }
    cholSub[k] = sub;
    cholDiag[k] = std::sqrt(std::max(diag - sub * sub, 1e-30));
  }
}

void GyroChannel::whiten(double* x) const {
  const std::size_t n = size();
  countPass(SampleStream::kGyro);
  double previous = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    x[k] = (x[k] - cholSub[k] * previous) / cholDiag[k];
    previous = x[k];
  }
}

void GyroChannel::whitenRows(double* x, std::size_t columns) const {
  const std::size_t n = size();
  countPass(SampleStream::kGyro);
  for (std::size_t j = 0; j < columns; ++j) x[j] /= cholDiag[0];
  for (std::size_t k = 1; k < n; ++k) {
    double* row = x + k * columns;
    const double* prev = row - columns;
    const double m = cholSub[k], inv = 1.0 / cholDiag[k];
    for (std::size_t j = 0; j < columns; ++j) row[j] = (row[j] - m * prev[j]) * inv;
  }
}

namespace {
// Pulse quantisation from the lag-1 autocovariance (g1 = -s2): at the frame
// level quantisation dominates, so this is where it is seen best.
double quantisationVariance(const GyroChannel& gyro, const std::vector<double>& r) {
  countPass(SampleStream::kGyro);
  double g1 = 0.0;
  std::size_t n1 = 0;
  for (std::size_t k = 1; k < r.size(); ++k)
    if (gyro.continuesPrevious[k]) {
      g1 += r[k] * r[k - 1];
      ++n1;
    }
  g1 = n1 ? g1 / static_cast<double>(n1) : 0.0;
  return std::max(-g1, 0.0);
}

// m, the block length in frames nearest blockS (at least 1, at most an
// eighth of the record); sum(k) = prefix[k + m] - prefix[k].
struct Blocks {
  std::size_t m = 1;
  double blockS = 0.0;  // m frame periods: the block length actually used
  const std::vector<double>& prefix;
  double sum(std::size_t k) const { return prefix[k + m] - prefix[k]; }
};

Blocks blocksOf(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS) {
  const std::size_t n = sums.prefix.size() - 1;
  const std::size_t m = std::clamp<std::size_t>(static_cast<std::size_t>(std::llround(blockS / gyro.framePeriodS)), 1,
                                                std::max<std::size_t>(n / 8, 1));
  return {m, static_cast<double>(m) * gyro.framePeriodS, sums.prefix};
}
}  // namespace

IncrementResidualSums incrementResidualSums(const GyroChannel& gyro, const std::vector<double>& r) {
  IncrementResidualSums out;
  out.quantisationVarianceDeg2 = quantisationVariance(gyro, r);
  countPass(SampleStream::kGyro);
  out.prefix.assign(r.size() + 1, 0.0);
  for (std::size_t k = 0; k < r.size(); ++k) out.prefix[k + 1] = out.prefix[k] + r[k];
  return out;
}

namespace {
// The white rate noise from the sum of squared differences of adjacent
// block sums (v over `pairs` of them).
double whiteRateFromSums(double v, std::size_t pairs, double s2, const Blocks& b) {
  if (pairs == 0) return 0.0;
  v /= static_cast<double>(pairs);
  return std::max(v - 6.0 * s2, 1e-6 * v) / (2.0 * b.blockS);
}

// q and its standard error from the sum of squared block sums (v over
// `blocks` of them).
BlockRateVariance blockRateFromSums(const GyroChannel& gyro, double v, std::size_t blocks, std::size_t n, double s2,
                                    const Blocks& b) {
  const std::size_t m = b.m;
  const double usedBlockS = b.blockS;
  v /= static_cast<double>(std::max<std::size_t>(blocks, 1));
  const double floorVar = 1e-6 * (v + 2.0 * s2) + 1e-30;
  const double q = std::max(v - 2.0 * s2, floorVar) / usedBlockS;
  // Sampling error of v - 2*s2. The random-walk part of overlapping m-sums
  // varies like 2 (q m dt)^2 (4/3) m/n (few independent blocks); their
  // quantisation part, two values per sum, like 2 (2 s2)^2 * 2/n; the lag-1
  // estimate of s2 like v1^2/n, v1 the per-increment variance. The walk's
  // part is taken at least at the size of the quantisation part, which is
  // where a short record cannot tell how large it is.
  const auto nd = static_cast<double>(std::max<std::size_t>(n, 1));
  const double walk = std::max(q * usedBlockS, 2.0 * s2 * std::sqrt(2.0 / nd));
  const double v1 = 2.0 * s2 + q * gyro.framePeriodS;
  const double varV = 2.0 * walk * walk * (4.0 / 3.0) * static_cast<double>(m) / nd + 16.0 * s2 * s2 / nd;
  return {q, std::sqrt(varV + 4.0 * v1 * v1 / nd) / usedBlockS};
}
}  // namespace

double estimateWhiteRateVariance(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS) {
  const std::size_t n = sums.prefix.size() - 1;
  const Blocks b = blocksOf(gyro, sums, blockS);
  countPass(SampleStream::kGyro);
  double v = 0.0;
  std::size_t pairs = 0;
  for (std::size_t k = 0; k + 2 * b.m <= n; ++k) {
    const double d = b.sum(k) - b.sum(k + b.m);
    v += d * d;
    ++pairs;
  }
  return whiteRateFromSums(v, pairs, sums.quantisationVarianceDeg2, b);
}

double estimateWhiteRateVariance(const GyroChannel& gyro, const std::vector<double>& r, double blockS) {
  return estimateWhiteRateVariance(gyro, incrementResidualSums(gyro, r), blockS);
}

BlockRateVariance blockRateVariance(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS) {
  const std::size_t n = sums.prefix.size() - 1;
  // Angle random walk from overlapping sums of M increments: their variance
  // is q*M*dt + 2*s2 (quantisation enters only at the two ends). Block sums
  // see the noise at low frequencies, near the swing, where the lag is
  // decided; per-frame variances would be swamped by quantisation.
  const Blocks b = blocksOf(gyro, sums, blockS);
  countPass(SampleStream::kGyro);
  double v = 0.0;
  std::size_t blocks = 0;
  for (std::size_t k = 0; k + b.m <= n; ++k) {
    const double sum = b.sum(k);
    v += sum * sum;
    ++blocks;
  }
  return blockRateFromSums(gyro, v, blocks, n, sums.quantisationVarianceDeg2, b);
}

GyroNoiseViews gyroNoiseViews(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS,
                              double weightBlockS) {
  const std::size_t n = sums.prefix.size() - 1;
  const double s2 = sums.quantisationVarianceDeg2;
  const Blocks b = blocksOf(gyro, sums, blockS), w = blocksOf(gyro, sums, weightBlockS);
  // The three sums side by side, each over k in order as in its own pass.
  countPass(SampleStream::kGyro);
  double white = 0.0, swing = 0.0, weight = 0.0;
  std::size_t pairs = 0, swingBlocks = 0, weightBlocks = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k + 2 * b.m <= n) {
      const double d = b.sum(k) - b.sum(k + b.m);
      white += d * d;
      ++pairs;
    }
    if (k + b.m <= n) {
      const double sum = b.sum(k);
      swing += sum * sum;
      ++swingBlocks;
    }
    if (k + w.m <= n) {
      const double sum = w.sum(k);
      weight += sum * sum;
      ++weightBlocks;
    }
  }
  return {whiteRateFromSums(white, pairs, s2, b), blockRateFromSums(gyro, swing, swingBlocks, n, s2, b),
          blockRateFromSums(gyro, weight, weightBlocks, n, s2, w)};
}

void estimateGyroNoise(GyroChannel& gyro, const IncrementResidualSums& sums, double blockS) {
  const BlockRateVariance q = blockRateVariance(gyro, sums, blockS);
  gyro.setNoise(q.varianceDeg2PerS, sums.quantisationVarianceDeg2);
  gyro.arwVarianceStdDeg2PerS = q.stdDeg2PerS;
}

void estimateGyroNoise(GyroChannel& gyro, const std::vector<double>& r, double blockS) {
  estimateGyroNoise(gyro, incrementResidualSums(gyro, r), blockS);
}

Result<Channels> makeChannels(const TestPointData& data, double incrementScale) {
  const int axis = static_cast<int>(data.axis);
  if (data.table.size() < 16 || data.imu.size() < 16)
    return insufficientData("test point " + std::to_string(data.index + 1) + " has " +
                            std::to_string(data.table.size()) + " table and " +
                            std::to_string(data.imu.size()) +
                            " IMU samples; a delay needs at least two whole swing periods of both");
  Channels ch;
  ch.axis = axis;
  ch.startS = std::max(data.table.front().timeS, data.imu.front().timeS);
  ch.endS = std::min(data.table.back().timeS, data.imu.back().timeS);
  if (!(ch.endS > ch.startS))
    return insufficientData("table and IMU samples of test point " + std::to_string(data.index + 1) +
                            " do not overlap in time");
  ch.referenceS = 0.5 * (ch.startS + ch.endS);

  countPass(SampleStream::kTable);
  ch.table.timeS.reserve(data.table.size());
  ch.table.angleDeg.reserve(data.table.size());
  for (const auto& s : data.table) {
    if (!std::isfinite(s.timeS) || !std::isfinite(s.angleDeg[axis])) continue;
    ch.table.timeS.push_back(s.timeS - ch.referenceS);
    ch.table.angleDeg.push_back(s.angleDeg[axis]);
  }

  countPass(SampleStream::kGyro);
  std::vector<double> intervals;
  intervals.reserve(data.imu.size());
  for (std::size_t k = 1; k < data.imu.size(); ++k)
    if (data.imu[k].lostBefore == 0) intervals.push_back(data.imu[k].timeS - data.imu[k - 1].timeS);
  GyroChannel& g = ch.gyro;
  g.framePeriodS = medianElement(intervals);
  if (!(g.framePeriodS > 0.0)) return corruptData("IMU frame times do not increase");

  const std::size_t n = data.imu.size() - 1;
  g.startS.reserve(n);
  g.endS.reserve(n);
  g.incrementDeg.reserve(n);
  g.continuesPrevious.reserve(n);
  countPass(SampleStream::kGyro);
  // The first frame only marks where integration starts: its increment
  // belongs to an interval before the record.
  for (std::size_t k = 1; k < data.imu.size(); ++k) {
    const auto& s = data.imu[k];
    const bool continuous = s.lostBefore == 0;
    const double end = s.timeS - ch.referenceS;
    // After lost frames the interval started one frame period earlier, at the
    // lost frame's sample; its exact stamp is unknown.
    const double start = continuous ? data.imu[k - 1].timeS - ch.referenceS : end - g.framePeriodS;
    g.lostFrames += s.lostBefore;
    g.startS.push_back(start);
    g.endS.push_back(end);
    g.incrementDeg.push_back(s.incrementDeg[axis] * incrementScale);
    g.continuesPrevious.push_back(continuous && !g.continuesPrevious.empty());
  }
  return ch;
}

std::vector<double> cumulativeGyroAngle(const GyroChannel& gyro) {
  countPass(SampleStream::kGyro);
  std::vector<double> out(gyro.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < gyro.size(); ++k) out[k] = (sum += gyro.incrementDeg[k]);
  return out;
}

}  // namespace fog::analysis
