#include "core/analysis/validity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "core/analysis/sin_cos_series.h"
#include "core/common/units.h"

namespace fog::analysis {

namespace {

// Variance a least-squares fit of a*sin(w*t) + b*cos(w*t) + c explains in a
// uniformly binned series (the least-squares periodogram: unlike |DFT|^2 it
// has no bias from the negative-frequency image on short records).
double power(const std::vector<double>& y, double binS, double w) {
  // The distinct sums of the symmetric Gram matrix of rows (sin, cos, 1),
  // accumulated by hand: the golden-section search calls this 42 times over
  // up to 65 536 bins, and the full 3x3 outer product per bin was a tenth of
  // the analysis.
  double ss = 0.0, sc = 0.0, cc = 0.0, s1 = 0.0, c1 = 0.0, ys = 0.0, yc = 0.0, y1 = 0.0;
  // Four rotations, bin i from bin i - 4 (one rotation from the last, a
  // multiply waiting on the previous one's, was the latency the loop waited
  // on), each re-anchored every 1024 bins; the sums still taken in order.
  constexpr std::size_t kChains = 4;
  const double stepRe = std::cos(kChains * w * binS), stepIm = std::sin(kChains * w * binS);
  double re[kChains], im[kChains];
  auto anchor = [&](std::size_t first) {
    for (std::size_t k = 0; k < kChains; ++k) {
      re[k] = std::cos(w * binS * static_cast<double>(first + k));
      im[k] = std::sin(w * binS * static_cast<double>(first + k));
    }
  };
  anchor(0);
  for (std::size_t i = 0; i < y.size(); ++i) {
    const std::size_t k = i & (kChains - 1);
    const double s = im[k], c = re[k];
    ss += s * s;
    sc += c * s;
    cc += c * c;
    s1 += s;
    c1 += c;
    ys += s * y[i];
    yc += c * y[i];
    y1 += y[i];
    re[k] = c * stepRe - s * stepIm;
    im[k] = c * stepIm + s * stepRe;
    if ((i & 1023) == 1023) anchor(i + 1);  // no drift
  }
  Eigen::Matrix3d ata;
  ata << ss, sc, s1, sc, cc, c1, s1, c1, static_cast<double>(y.size());
  const Eigen::Vector3d aty(ys, yc, y1);
  const Eigen::Vector3d p = ata.ldlt().solve(aty);
  return p.dot(aty);
}

}  // namespace

Result<double> estimateSwingFrequencyHz(const TableChannel& table) {
  const auto& t = table.timeS;
  const auto& y = table.angleDeg;
  if (y.size() < 16) return insufficientData("too few table samples to find the swing frequency");
  const double spanS = t.back() - t.front();
  if (!(spanS > 0.0)) return insufficientData("the table samples do not span any time");
  // Box averages over equal bins: a uniform series (stamps may jitter or
  // have gaps) and an anti-alias filter in one step. 500 bins a second (a
  // Nyquist frequency of 250 Hz, far above any swing a table makes), at
  // least 4 096 and at most 65 536: the estimate only starts the fits (they
  // refine it), and its cost grows with the bins.
  const auto wanted = static_cast<std::size_t>(std::clamp(std::ceil(spanS * 500.0), 4096.0, 32768.0));
  const std::size_t bins = std::min<std::size_t>(y.size(), wanted);
  const double binS = spanS / static_cast<double>(bins);
  std::vector<double> sum(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  countPass(SampleStream::kTable);
  for (std::size_t i = 0; i < y.size(); ++i) {
    const auto b = std::min(bins - 1, static_cast<std::size_t>((t[i] - t.front()) / binS));
    sum[b] += y[i];
    ++count[b];
  }
  std::vector<double> series(bins);
  double last = y.front();
  for (std::size_t b = 0; b < bins; ++b) {
    if (count[b]) last = sum[b] / static_cast<double>(count[b]);
    series[b] = last;  // an empty bin (a gap) holds the previous value
  }
  // Remove a straight line (offset and drift would dominate the low bins).
  {
    Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
    Eigen::Vector2d aty = Eigen::Vector2d::Zero();
    for (std::size_t b = 0; b < bins; ++b) {
      const double x = static_cast<double>(b) / static_cast<double>(bins) - 0.5;
      ata(0, 0) += 1.0;
      ata(0, 1) += x;
      ata(1, 1) += x * x;
      aty[0] += series[b];
      aty[1] += x * series[b];
    }
    ata(1, 0) = ata(0, 1);
    const Eigen::Vector2d p = ata.ldlt().solve(aty);
    for (std::size_t b = 0; b < bins; ++b)
      series[b] -= p[0] + p[1] * (static_cast<double>(b) / static_cast<double>(bins) - 0.5);
  }
  const auto [lo, hi] = std::minmax_element(series.begin(), series.end());
  if (!(*hi - *lo > 0.0)) return insufficientData("the table did not move on the swing axis");

  // Periodogram, zero-padded twice (bins half a record's resolution apart:
  // the peak's bin is within half a bin of the peak, which the search below
  // finds); the peak above 1.5 cycles per record.
  std::size_t n = 1;
  while (n < 2 * bins) n <<= 1;
  std::vector<double> padded(n, 0.0);
  std::copy(series.begin(), series.end(), padded.begin());
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  const double df = 1.0 / (static_cast<double>(n) * binS);
  const auto first = static_cast<std::size_t>(std::ceil(1.5 / spanS / df));
  std::size_t peak = 0;
  double best = -1.0;
  for (std::size_t k = std::max<std::size_t>(first, 1); k < n / 2; ++k)
    if (std::norm(spectrum[k]) > best) {
      best = std::norm(spectrum[k]);
      peak = k;
    }
  if (peak == 0) return insufficientData("the table angle holds no swing");
  // Golden-section search of the exact periodogram within one padded bin.
  double a = (static_cast<double>(peak) - 1.0) * df * kTwoPi, b = (static_cast<double>(peak) + 1.0) * df * kTwoPi;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double pc = power(series, binS, c), pd = power(series, binS, d);
  // 24 steps narrow two padded bins to 1e-5 of a bin: far below what the
  // fits that start from it resolve.
  for (int it = 0; it < 24; ++it) {
    if (pc > pd) {
      b = d;
      d = c;
      pd = pc;
      c = b - g * (b - a);
      pc = power(series, binS, c);
    } else {
      a = c;
      c = d;
      pc = pd;
      d = a + g * (b - a);
      pd = power(series, binS, d);
    }
  }
  const double f = 0.5 * (a + b) / kTwoPi;
  // Counted as the plan counts a point's duration: the span and one sample
  // interval (kMinSwingPeriods, test_plan.h).
  const double interval = spanS / static_cast<double>(t.size() - 1);
  if (const std::string few = tooFewSwingPeriods(f * (spanS + interval)); !few.empty())
    return insufficientData("the table angle " + few + " (at " + std::to_string(f).substr(0, 6) + " Hz)");
  return f;
}

double smoothResidualRms(const std::vector<double>& timeS, const std::vector<double>& r, double windowS,
                         SampleStream stream) {
  if (r.empty() || !(windowS > 0.0)) return 0.0;
  countPass(stream);
  double sumSq = 0.0, weight = 0.0;
  std::size_t i = 0;
  while (i < r.size()) {
    const double end = timeS[i] + windowS;
    double s = 0.0;
    std::size_t n = 0;
    for (; i < r.size() && timeS[i] < end; ++i, ++n) s += r[i];
    const double mean = s / static_cast<double>(n);
    sumSq += static_cast<double>(n) * mean * mean;
    weight += static_cast<double>(n);
  }
  return std::sqrt(sumSq / weight);
}

double harmonicAmplitude(const std::vector<double>& timeS, const std::vector<double>& r, double w,
                         SampleStream stream) {
  constexpr int kFirst = 2, kLast = 5, kCols = 2 * (kLast - kFirst + 1) + 1, kTop = 2 * kLast;
  countPass(stream);
  // The Gram matrix of the columns sin(k theta), cos(k theta) (k = 2..5) and
  // 1 holds only sums of cos(m theta) and sin(m theta), m = 0..10, by the
  // product-to-sum identities (2 sin a sin b = cos(a - b) - cos(a + b), ...):
  // 20 sums a sample instead of its 45 products. sin/cos of m theta come from
  // the fundamental's by angle addition (tests/core/analysis/
  // harmonic_amplitude_test.cpp compares the amplitude with a direct fit's).
  SinCosStream phase(w, 0.0);
  double sumC[kTop + 1] = {}, sumS[kTop + 1] = {}, rs[kCols] = {};
  for (std::size_t i = 0; i < r.size(); ++i) {
    double sn[kTop + 1], cs[kTop + 1];
    phase.next(timeS[i], sn[1], cs[1]);
    // m = j + k from j and k, nearly halves: four additions deep, where
    // m = 2..10 in turn would be a chain of nine that the CPU waits on.
    for (const auto& [m, j] : {std::pair{2, 1}, {3, 2}, {4, 2}, {5, 3}, {6, 3}, {7, 4}, {8, 4}, {9, 5}, {10, 5}}) {
      const int k = m - j;
      sn[m] = sn[j] * cs[k] + cs[j] * sn[k];
      cs[m] = cs[j] * cs[k] - sn[j] * sn[k];
    }
    for (int m = 1; m <= kTop; ++m) {
      sumS[m] += sn[m];
      sumC[m] += cs[m];
    }
    for (int m = kFirst; m <= kLast; ++m) {
      rs[2 * (m - kFirst)] += r[i] * sn[m];
      rs[2 * (m - kFirst) + 1] += r[i] * cs[m];
    }
    rs[kCols - 1] += r[i];
  }
  sumC[0] = static_cast<double>(r.size());
  auto cosSum = [&](int m) { return sumC[m < 0 ? -m : m]; };
  auto sinSum = [&](int m) { return m < 0 ? -sumS[-m] : sumS[m]; };
  Eigen::Matrix<double, kCols, kCols> ata;
  Eigen::Matrix<double, kCols, 1> aty;
  for (int k = kFirst; k <= kLast; ++k) {
    const int sk = 2 * (k - kFirst), ck = sk + 1;
    for (int l = kFirst; l <= kLast; ++l) {
      const int sl = 2 * (l - kFirst), cl = sl + 1;
      ata(sk, sl) = 0.5 * (cosSum(k - l) - cosSum(k + l));
      ata(ck, cl) = 0.5 * (cosSum(k - l) + cosSum(k + l));
      ata(sk, cl) = 0.5 * (sinSum(k + l) + sinSum(k - l));
      ata(cl, sk) = ata(sk, cl);
    }
    ata(sk, kCols - 1) = ata(kCols - 1, sk) = sumS[k];
    ata(ck, kCols - 1) = ata(kCols - 1, ck) = sumC[k];
  }
  ata(kCols - 1, kCols - 1) = sumC[0];
  for (int i = 0; i < kCols; ++i) aty[i] = rs[i];
  const Eigen::Matrix<double, kCols, 1> p = ata.ldlt().solve(aty);
  double sumSq = 0.0;
  for (int j = 0; j + 1 < kCols; ++j) sumSq += p[j] * p[j];
  return std::sqrt(sumSq);
}

namespace {

// The phase's repeating part when it is negative (periodicErrorCovariance's
// fold, validity.h): an error that depends on the angle alone, read at
// phases that drift slowly through it (quantisation, stamps a few ppm off
// the swing), has no cos(psi) component in the limit, since the rising and
// the falling half of the swing read the same angles with opposite cos(psi);
// the fold then sums to less than the white noise model carries. Its total,
// sum_j c_j^2 (D_j - D_(j+B/2))^2 (each bin with the one half a period on,
// which an even B pairs), is a sum of squares: a chi^2 of nu degrees of
// freedom (from the bins' weights; less the harmonics taken out), whose
// white part is (1 - eps) sum_j c_j^2 S_j. Returned: the total at its
// one-sided 69 % upper bound (half a sigma, Wilson-Hilferty) less that
// white part, when negative and nu >= 8; 0 otherwise (too few bins to
// vouch for less than white: the white model stands). In the fold's units
// (times periodicErrorCovariance's scale).
double phaseBelowWhite(const std::vector<double>& sum, const std::vector<double>& sumSq,
                       const std::vector<double>& cosOf, const std::vector<double>& sinOf, double s0, double c0,
                       std::size_t half, int harmonics, double eps) {
  const std::size_t bins = sum.size();
  const std::size_t terms = half > 0 ? half : bins;
  double total = 0.0, white = 0.0, whiteSq = 0.0;
  for (std::size_t j = 0; j < terms; ++j) {
    const double c = c0 * cosOf[j] - s0 * sinOf[j], w = c * c;
    const double d = half > 0 ? sum[j] - sum[j + half] : sum[j];
    const double v = w * (half > 0 ? sumSq[j] + sumSq[j + half] : sumSq[j]);
    total += w * d * d;
    white += v;
    whiteSq += v * v;
  }
  if (!(white > 0.0) || !(whiteSq > 0.0)) return 0.0;
  const double binsD = static_cast<double>(bins);
  const double nu = white * white / whiteSq * (binsD - 1.0 - 2.0 * harmonics) / binsD;
  if (!(nu >= 8.0)) return 0.0;
  // chi^2_nu's 31 % quantile, z = -0.5 (Wilson-Hilferty).
  const double k = 2.0 / (9.0 * nu), lower = nu * std::pow(1.0 - k - 0.5 * std::sqrt(k), 3);
  const double upper = total * nu / lower;
  return std::min(0.0, upper - (1.0 - eps) * white);
}

}  // namespace

PeriodicErrorCovariance periodicErrorCovariance(const std::vector<double>& t, const std::vector<double>& r,
                                                double w, double a, double b, SampleStream stream) {
  PeriodicErrorCovariance out;
  const std::size_t n = std::min(t.size(), r.size());
  const double amplitude = std::hypot(a, b);
  if (n < 16 || !(w > 0.0) || !std::isfinite(w) || !(amplitude > 0.0) || !std::isfinite(amplitude)) return out;
  const double cycles = (t[n - 1] - t[0]) * w / kTwoPi;  // periods the samples span
  const double samplesPerPeriod = static_cast<double>(n - 1) / cycles;
  if (!(cycles >= 2.0) || !(samplesPerPeriod >= 4.0) || samplesPerPeriod > 1e7) return out;
  // One bin per sample of a period, at the sample phases of the first
  // period: with commensurate stamps every period's samples fall on the
  // same bins. Two samples of one period never share a bin (they are a
  // sample apart, a bin is no wider), so a bin's pairs are always whole
  // periods apart.
  const auto bins = static_cast<std::size_t>(std::llround(samplesPerPeriod));
  std::vector<double> sum(bins, 0.0), sumSq(bins, 0.0);
  // The second differences' mean is the ends' slopes' difference over n - 2: it telescopes.
  const double mean = (r[n - 1] - r[n - 2] - r[1] + r[0]) / static_cast<double>(n - 2);
  const double cyclesPerS = w / kTwoPi;
  countPass(stream);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double d = r[i + 1] - 2.0 * r[i] + r[i - 1] - mean;
    const double x = (t[i] - t[0]) * cyclesPerS;
    if (!std::isfinite(x)) continue;  // a stamp no bin holds (never cast to an index)
    auto j = static_cast<std::size_t>(std::floor((x - std::floor(x)) * static_cast<double>(bins) + 0.5));
    if (j >= bins) j -= bins;
    sum[j] += d;
    sumSq[j] += d * d;
  }
  // Harmonics 0..5 of the period out of the folded sums: a smooth error that
  // repeats (a table harmonic the fit leaves) is not one the fundamental's
  // estimate carries. An error white within the period loses the share of
  // its second differences' power there, eps = sum over the harmonics of
  // (2 sin(pi m / B))^4 / (6 B), which is restored below (0.15 % at 50 bins,
  // 4 % at 25).
  const int harmonics = static_cast<int>(std::min<std::size_t>(5, (bins - 1) / 2));
  const double binsD = static_cast<double>(bins);
  // cos and sin of 2 pi k / bins, read below by index: harmonic m at bin j
  // is entry m j mod bins, and the swing's phase at bin j is psi0 plus entry
  // j. One sincos per bin instead of eleven (a period of 1-ms stamps at
  // 0.1 Hz is 10 000 bins: those calls were a tenth of the analysis).
  std::vector<double> cosOf(bins), sinOf(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    const double phase = kTwoPi * static_cast<double>(k) / binsD;
    cosOf[k] = std::cos(phase);
    sinOf[k] = std::sin(phase);
  }
  double eps = 0.0;
  {
    double m0 = 0.0;
    for (double v : sum) m0 += v;
    m0 /= binsD;
    for (double& v : sum) v -= m0;
  }
  for (int m = 1; m <= harmonics; ++m) {
    const auto mm = static_cast<std::size_t>(m);
    double cs = 0.0, sn = 0.0;
    for (std::size_t j = 0, k = 0; j < bins; ++j, k = (k + mm) % bins) {
      cs += sum[j] * cosOf[k];
      sn += sum[j] * sinOf[k];
    }
    cs *= 2.0 / binsD;
    sn *= 2.0 / binsD;
    for (std::size_t j = 0, k = 0; j < bins; ++j, k = (k + mm) % bins) sum[j] -= cs * cosOf[k] + sn * sinOf[k];
    eps += 2.0 * std::pow(2.0 * std::sin(kPi * m / binsD), 4) / (6.0 * binsD);
  }
  // The swing's phase psi = w t + theta at each bin; the weights of the
  // in-phase (amplitude) and quadrature (phase) projections.
  // With an even number of bins, the fold half a period on as well: a
  // quantisation error is an odd function of the angle about a grid point,
  // so a swing about a centre on the grid (0, commanded) reads -theta half a
  // period after it read theta, and its error repeats with the sign
  // flipped every half period. Such a pattern holds odd harmonics of the
  // period only, and the fundamental (odd, absorbed by the fit) carries
  // twice the average power the bins' own squares give: the cross products
  // -D_j D_(j+B/2) add it (their expectation is 0 when nothing relates the
  // halves: samples half a period apart share no white error).
  const std::size_t half = bins % 2 == 0 ? bins / 2 : 0;
  const double psi0 = w * t[0] + std::atan2(b, a);
  const double s0 = std::sin(psi0), c0 = std::cos(psi0);
  double qss = 0.0, qcc = 0.0, qsc = 0.0;
  for (std::size_t j = 0; j < bins; ++j) {
    double pairs = sum[j] * sum[j] - (1.0 - eps) * sumSq[j];
    if (half > 0) pairs -= sum[j] * sum[(j + half) % bins];
    const double s = s0 * cosOf[j] + c0 * sinOf[j], c = c0 * cosOf[j] - s0 * sinOf[j];
    qss += s * s * pairs;
    qcc += c * c * pairs;
    qsc += s * c * pairs;
  }
  const double nD = static_cast<double>(n);
  const double scale = 4.0 / (6.0 * nD * nD * amplitude * amplitude * (1.0 - eps));
  // Clipped to positive semi-definite: the estimate of a variance that is
  // not there scatters about 0.
  const Eigen::Matrix2d q = (Eigen::Matrix2d() << qss, qsc, qsc, qcc).finished() * scale;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(q);
  const Eigen::Vector2d lambda = eig.eigenvalues().cwiseMax(0.0);
  const Eigen::Matrix2d psd = eig.eigenvectors() * lambda.asDiagonal() * eig.eigenvectors().transpose();
  if (!psd.allFinite()) return out;
  out.amplitude = psd(0, 0);
  out.phase = psd(1, 1);
  out.cross = psd(0, 1);
  if (qcc < 0.0) {
    const double lowered = phaseBelowWhite(sum, sumSq, cosOf, sinOf, s0, c0, half, harmonics, eps);
    if (lowered < 0.0) {
      out.phase = lowered * scale;
      out.cross = 0.0;  // no covariance with a variance taken below the white model's
    }
  }
  return out;
}

std::optional<LineFit> fitLine(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 3) return std::nullopt;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0.0)) return std::nullopt;
  LineFit f;
  f.points = n;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double rss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = y[i] - (f.intercept + f.slope * x[i]);
    rss += e * e;
  }
  f.residualStd = std::sqrt(rss / static_cast<double>(n - 2));
  f.slopeStd = f.residualStd / std::sqrt(sxx);
  return f;
}

}  // namespace fog::analysis
