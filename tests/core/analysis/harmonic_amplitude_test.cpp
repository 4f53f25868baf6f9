// harmonicAmplitude (steady_sine's harmonics 2..5): its Gram matrix is built
// from sums of cos(m theta) and sin(m theta) by the product-to-sum
// identities, not from the columns' products. Checked against a direct
// least-squares fit of the nine columns, written out here, and against
// harmonics of known size.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <array>
#include <random>
#include <vector>

#include "core/analysis/validity.h"
#include "core/common/units.h"

namespace fog::analysis {
namespace {

// The amplitude a direct fit of sin(k w t), cos(k w t) (k = 2..5) and 1
// gives, from the nine columns themselves (QR, each sine from libm).
double directAmplitude(const std::vector<double>& t, const std::vector<double>& r, double w) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(t.size()), 9);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    for (int k = 2; k <= 5; ++k) {
      a(row, 2 * (k - 2)) = std::sin(k * w * t[i]);
      a(row, 2 * (k - 2) + 1) = std::cos(k * w * t[i]);
    }
    a(row, 8) = 1.0;
  }
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
  const Eigen::VectorXd p = a.colPivHouseholderQr().solve(y);
  return p.head(8).norm();
}

struct Series {
  std::vector<double> t, r;
};

// 1-kHz stamps with 20 us of jitter (so no sum is exact by symmetry), a
// swing frequency incommensurate with them, harmonics 2..5 of the given
// amplitudes at scattered phases, an offset and white noise.
Series makeSeries(double w, double seconds, const double (&amplitude)[4], double noise, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> jitter(-2e-5, 2e-5);
  Series s;
  for (double t = 0.0; t < seconds; t += 1e-3) {
    const double ti = t + jitter(rng);
    double v = 0.37;
    for (int k = 2; k <= 5; ++k) v += amplitude[k - 2] * std::sin(k * w * ti + 0.7 * k);
    s.t.push_back(ti);
    s.r.push_back(v + noise * n01(rng));
  }
  return s;
}

TEST(HarmonicAmplitude, EqualsADirectFitOfTheNineColumns) {
  const double w = kTwoPi * 1.2345;
  for (const auto& amplitudes : {std::array{1e-3, 0.0, 5e-4, 2e-4}, std::array{0.0, 0.0, 0.0, 0.0}}) {
    const double a[4] = {amplitudes[0], amplitudes[1], amplitudes[2], amplitudes[3]};
    const Series s = makeSeries(w, 30.0, a, 1e-3, 3);
    const double direct = directAmplitude(s.t, s.r, w);
    const double fast = harmonicAmplitude(s.t, s.r, w, SampleStream::kTable);
    // 30 000 samples: the two differ by rounding, far below a part in 1e9.
    EXPECT_NEAR(fast, direct, 1e-9 * direct) << "harmonics " << a[0] << ", " << a[2] << ", " << a[3];
  }
}

TEST(HarmonicAmplitude, RecoversHarmonicsOfKnownSize) {
  const double w = kTwoPi * 0.1;
  const double a[4] = {2e-3, 1e-3, 0.0, 5e-4};
  const double truth = std::sqrt(4e-6 + 1e-6 + 0.25e-6);
  const Series s = makeSeries(w, 60.0, a, 1e-4, 11);
  // White noise of 1e-4 over 60 000 samples adds about 1e-4 * sqrt(8 / 30 000)
  // = 1.6e-6 in quadrature: 1e-5 is six times that.
  EXPECT_NEAR(harmonicAmplitude(s.t, s.r, w, SampleStream::kTable), truth, 1e-5);
  // A fundamental alone is no harmonic (the residual of a fit holds none,
  // but the columns are not orthogonal to it on a record of 6 periods).
  Series f = s;
  for (std::size_t i = 0; i < f.t.size(); ++i) f.r[i] = 0.01 * std::sin(w * f.t[i]);
  EXPECT_NEAR(harmonicAmplitude(f.t, f.r, w, SampleStream::kTable), directAmplitude(f.t, f.r, w), 1e-12);
}

}  // namespace
}  // namespace fog::analysis
