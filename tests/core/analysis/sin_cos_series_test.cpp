// The rotation recurrence (sin_cos_series.h) against sin and cos computed
// directly: over a 10-hour record at 1 kHz its sines and cosines, and the
// sums the fits build from them, agree with the direct ones within stated
// bounds; and the fits that use it give the parameters a direct-sincos fit
// gives. Nothing is timed.

#include "core/analysis/sin_cos_series.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "core/analysis/channels.h"
#include "core/analysis/sine_fit.h"
#include "core/common/units.h"
#include "synthetic.h"

namespace fog::analysis {
namespace {

// The sums a 3-parameter fit of y = a sin + b cos + c accumulates, and the
// largest per-sample differences, recurrence minus direct.
struct StreamComparison {
  // recurrence sum - direct sum of s, c, ss, sc, cc, ys, yc, summed term by
  // term (the difference of the sums, without the rounding of two sums of
  // 36 million terms that are each ~1e7)
  double difference[7] = {};
  double w = 0.0;
  double maxSinError = 0.0, maxCosError = 0.0;
  std::uint64_t samples = 0;
};

// n samples every dt seconds from t0 (as channel times run: relative to the
// record's middle, so t0 = -duration / 2), at angular frequency w. y is a
// 10-degree swing read by a 1e-4-degree encoder, from the direct sines.
// Streams: nothing is stored, so 36 million samples take a few seconds.
StreamComparison compare(double w, double t0, double dt, std::uint64_t n) {
  StreamComparison out;
  SinCosStream stream(w, 0.0);
  for (std::uint64_t i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) * dt;
    double s, c;
    stream.next(t, s, c);
    const double sd = std::sin(w * t), cd = std::cos(w * t);
    const double y = std::round((8.0 * sd + 6.0 * cd) / 1e-4) * 1e-4;
    out.maxSinError = std::max(out.maxSinError, std::abs(s - sd));
    out.maxCosError = std::max(out.maxCosError, std::abs(c - cd));
    const double rec[7] = {s, c, s * s, s * c, c * c, y * s, y * c};
    const double dir[7] = {sd, cd, sd * sd, sd * cd, cd * cd, y * sd, y * cd};
    for (int k = 0; k < 7; ++k) out.difference[k] += rec[k] - dir[k];
  }
  out.samples = n;
  out.w = w;
  return out;
}

// The recurrence's contract (sin_cos_series.h): its error is at most that
// of a 0.1-ns timing error, w * 1e-10 s, beside rounding (1e-12 here: the
// direct sines of times near 18 000 s carry ~4e-12 s of rounding in t
// themselves). Measured: 1.8e-12 over 10 h at 0.1 Hz (bound 6.4e-11),
// 4.4e-10 over 1 h at 11 Hz (bound 7.0e-9), where the steps between stamps
// vary below the 1e-12 s at which the rotation is re-derived. Each sum the
// fits use is then within N * max|term| * that bound of the direct one
// (measured: below 2e-15 of N * max|term| at 0.1 Hz, 8e-11 at 11 Hz), so
// their normal equations, and from them their parameters, agree to that
// fraction of their scale.
double sampleBound(double w) { return w * 1e-10 + 1e-12; }

void expectAgreement(const StreamComparison& r) {
  const double bound = sampleBound(r.w);
  EXPECT_LE(r.maxSinError, bound);
  EXPECT_LE(r.maxCosError, bound);
  const auto n = static_cast<double>(r.samples);
  const char* names[7] = {"sum s", "sum c", "sum s^2", "sum s c", "sum c^2", "sum y s", "sum y c"};
  const double scale[7] = {1, 1, 1, 1, 1, 10, 10};  // largest |term|
  for (int k = 0; k < 7; ++k)
    EXPECT_LE(std::abs(r.difference[k]), bound * scale[k] * n) << names[k];
  std::printf("  per sample: |sin error| <= %.2e, |cos error| <= %.2e (bound %.2e)\n", r.maxSinError, r.maxCosError,
              bound);
  for (int k = 0; k < 7; ++k)
    std::printf("  %-8s |recurrence - direct| / (N * max|term|) = %.2e\n", names[k],
                std::abs(r.difference[k]) / (scale[k] * n));
}

TEST(SinCosStream, TenHoursAtOneKilohertzAgreeWithDirectSums) {
  constexpr double kHours = 10.0;
  constexpr std::uint64_t n = static_cast<std::uint64_t>(kHours * 3600.0 * 1000.0);  // 36 million
  expectAgreement(compare(kTwoPi * 0.1, -0.5 * kHours * 3600.0, 1e-3, n));
}

TEST(SinCosStream, TheFastestSwingAgreesWithDirectSums) {
  // 11 Hz (the response preset's top) over an hour at 1 kHz.
  expectAgreement(compare(kTwoPi * 11.0, -1800.0, 1e-3, 3'600'000));
}

// The 3-parameter fits that walk the samples with the recurrence give the
// parameters a fit with sin and cos per sample gives, within 1e-9 degrees
// (the recurrence's sums agree to ~1e-12 of their scale; the table's
// amplitude is 3 degrees and its standard error ~1e-6).
TEST(SinCosStream, LinearFitsAgreeWithDirectSinCos) {
  testing::SyntheticSpec spec;
  spec.durationS = 600.0;
  spec.frequencyHz = 0.1;
  spec.arwDegPerSqrtS = 1e-4;
  const auto data = testing::makeSynthetic(spec);
  auto ch = makeChannels(data, 1.0);
  ASSERT_TRUE(ch.isOk());
  const double w = kTwoPi * 0.1 * (1.0 + 3e-6);
  // Table: y = a sin + b cos + c by normal equations from direct sines.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < ch->table.timeS.size(); ++i) {
    const Eigen::Vector3d x(std::sin(w * ch->table.timeS[i]), std::cos(w * ch->table.timeS[i]), 1.0);
    ata += x * x.transpose();
    aty += x * ch->table.angleDeg[i];
  }
  const Eigen::Vector3d direct = ata.ldlt().solve(aty);
  const SineFit table = fitTableLinear(ch->table, w, ch->referenceS);
  EXPECT_NEAR(table.a, direct[0], 1e-9);
  EXPECT_NEAR(table.b, direct[1], 1e-9);
  EXPECT_NEAR(table.offsetDeg, direct[2], 1e-9);
  // Gyro increments: differences of sin and cos over each frame, and a trend.
  const GyroChannel& g = ch->gyro;
  ata.setZero();
  aty.setZero();
  for (std::size_t k = 0; k < g.size(); ++k) {
    const Eigen::Vector3d x(std::sin(w * g.endS[k]) - std::sin(w * g.startS[k]),
                            std::cos(w * g.endS[k]) - std::cos(w * g.startS[k]), g.endS[k] - g.startS[k]);
    ata += x * x.transpose();
    aty += x * g.incrementDeg[k];
  }
  const Eigen::Vector3d gyroDirect = ata.ldlt().solve(aty);
  const SineFit gyro = fitGyroLinear(g, w, ch->referenceS, false);
  EXPECT_NEAR(gyro.a, gyroDirect[0], 1e-9);
  EXPECT_NEAR(gyro.b, gyroDirect[1], 1e-9);
  EXPECT_NEAR(gyro.trendDegPerS, gyroDirect[2], 1e-12);
}

}  // namespace
}  // namespace fog::analysis
