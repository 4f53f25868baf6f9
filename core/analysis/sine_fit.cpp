#include "core/analysis/sine_fit.h"

#include <Eigen/Dense>
#include <cmath>
#include <future>

#include "core/analysis/least_squares.h"
#include "core/analysis/sample_passes.h"
#include "core/analysis/sin_cos_series.h"
#include "core/common/units.h"

namespace fog::analysis {

double wrapToHalfPeriod(double t, double period) {
  double w = std::fmod(t, period);
  if (w <= -0.5 * period) w += period;
  if (w > 0.5 * period) w -= period;
  return w;
}

namespace {

// Fills the paper-convention fields of a fit from (a, b, omega) and, when
// given, the covariance of (a, b, omega) (indices ia, ib, iw; -1 = fixed).
void finishFit(SineFit& f, const Eigen::MatrixXd* cov, int ia, int ib, int iw) {
  const double a = f.a, b = f.b, w = f.omegaRadPerS;
  f.amplitudeDeg = std::hypot(a, b);
  f.frequencyHz = w / kTwoPi;
  const double period = kTwoPi / w;
  f.periodMs = period * 1e3;
  // a*sin(w*tau) + b*cos(w*tau) = A*sin(w*tau + psi) = A*sin(w*(t - t0))
  const double psi = std::atan2(b, a);
  const double t0 = f.referenceS - psi / w;
  f.phaseMs = wrapToHalfPeriod(t0, period) * 1e3;
  if (!cov) return;
  const double A2 = a * a + b * b;
  // Gradients of amplitude, t0 and period with respect to (a, b, w).
  const Eigen::Vector3d gA(a / f.amplitudeDeg, b / f.amplitudeDeg, 0.0);
  const Eigen::Vector3d gT0((b / A2) / w, (-a / A2) / w, psi / (w * w));
  const Eigen::Vector3d gP(0.0, 0.0, -kTwoPi / (w * w));
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  const int idx[3] = {ia, ib, iw};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (idx[i] >= 0 && idx[j] >= 0) c(i, j) = (*cov)(idx[i], idx[j]);
  f.amplitudeStdDeg = std::sqrt(gA.dot(c * gA));
  f.phaseStdMs = std::sqrt(gT0.dot(c * gT0)) * 1e3;
  f.periodStdMs = std::sqrt(gP.dot(c * gP)) * 1e3;
  f.frequencyStdHz = iw >= 0 ? std::sqrt(c(2, 2)) / kTwoPi : 0.0;
}

// Table: y = a*sin(w*t) + b*cos(w*t) + c, parameters (a, b, c, w).
class TableSineProblem final : public LeastSquaresProblem {
 public:
  explicit TableSineProblem(const TableChannel& table) : t_(table), n_(table.timeS.size()) {}
  std::size_t numResiduals() const override { return n_; }
  int numParameters() const override { return 4; }
  // Rows are independent: the two halves are summed on two threads.
  double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    countPass(SampleStream::kTable);  // one pass, its halves on two threads
    NormalSums<4> first, second;
    const bool withJacobian = jtj != nullptr;
    auto half = std::async(std::launch::async, [&] { return accumulateRows(x, 0, n_ / 2, withJacobian, first); });
    const double rss = accumulateRows(x, n_ / 2, n_, withJacobian, second) + half.get();
    if (withJacobian) {
      first.addTo(*jtj, *jtr);
      second.addTo(*jtj, *jtr);
    }
    return rss;
  }

 private:
  // The sums are made in a local and copied out at the end: into `out`
  // directly, every add was a load and a store, for the compiler cannot
  // tell it from the samples (the pass took 2.6 times as long as the linear
  // fit's).
  double accumulateRows(const double* x, std::size_t begin, std::size_t end, bool withJacobian,
                        NormalSums<4>& out) const {
    const double a = x[0], b = x[1], c = x[2], w = x[3];
    const double inv = 1.0 / t_.noiseDeg;
    SinCosStream phase(w, 0.0);
    NormalSums<4> sums;
    double rss = 0.0;
    for (std::size_t i = begin; i < end; ++i) {
      double sn, cs;
      phase.next(t_.timeS[i], sn, cs);
      const double r = (t_.angleDeg[i] - (a * sn + b * cs + c)) * inv;
      rss += r * r;
      if (withJacobian) {
        const double row[4] = {-sn * inv, -cs * inv, -inv, -(a * cs - b * sn) * t_.timeS[i] * inv};
        sums.add(row, r);
      }
    }
    out = sums;
    return rss;
  }

  const TableChannel& t_;
  std::size_t n_;
};

// Gyro increments: d_k = f(t_k) - f(s_k), f = a*sin(w*t) + b*cos(w*t) + g*t,
// parameters (a, b, g, w), whitened by the channel's noise model.
class GyroSineProblem final : public LeastSquaresProblem {
 public:
  explicit GyroSineProblem(const GyroChannel& gyro) : g_(gyro), n_(gyro.size()) {}
  std::size_t numResiduals() const override { return n_; }
  int numParameters() const override { return 4; }
  double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    countPass(SampleStream::kGyro);
    const double a = x[0], b = x[1], d = x[2], w = x[3];
    GyroSinCosStream phase(g_, w, 0.0);
    const auto& te = g_.endS;
    const auto& ts = g_.startS;
    double rss = 0.0;
    NormalSums<4> sums;
    double prev[5] = {0, 0, 0, 0, 0};  // previous whitened row and residual
    for (std::size_t k = 0; k < n_; ++k) {
      double s1, c1, s0, c0;
      phase.next(k, s1, c1, s0, c0);
      const double raw[5] = {-(s1 - s0), -(c1 - c0), -(te[k] - ts[k]),
                             -(a * (te[k] * c1 - ts[k] * c0) - b * (te[k] * s1 - ts[k] * s0)),
                             g_.incrementDeg[k] - (a * (s1 - s0) + b * (c1 - c0) + d * (te[k] - ts[k]))};
      const double m = g_.cholSub[k], inv = 1.0 / g_.cholDiag[k];
      const int from = jtj ? 0 : 4;
      for (int j = from; j < 5; ++j) prev[j] = (raw[j] - m * prev[j]) * inv;
      rss += prev[4] * prev[4];
      if (jtj) sums.add(prev, prev[4]);
    }
    if (jtj) sums.addTo(*jtj, *jtr);
    return rss;
  }

 private:
  const GyroChannel& g_;
  std::size_t n_;
};

}  // namespace

namespace {

// Solves the 3-parameter least-squares problem from the Gram matrix of
// [x0 x1 x2 y] (lower triangle): parameters, their unscaled covariance
// inverse and the residual sum of squares, without a second pass.
struct Linear3 {
  Eigen::Vector3d p;
  Eigen::Matrix3d xtx;
  double rss = 0.0;
};
Linear3 solveGram(const NormalSums<4>& g) {
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) = m(j, i) = g.jtj[i][j];
  Linear3 out;
  out.xtx = m.topLeftCorner<3, 3>();
  const Eigen::Vector3d xty = m.block<3, 1>(0, 3);
  out.p = out.xtx.ldlt().solve(xty);
  out.rss = std::max(m(3, 3) - 2.0 * out.p.dot(xty) + out.p.dot(out.xtx * out.p), 0.0);
  return out;
}

}  // namespace

SineFit fitTableLinear(const TableChannel& table, double w, double referenceS) {
  const std::size_t n = table.timeS.size();
  countPass(SampleStream::kTable);
  SinCosStream phase(w, 0.0);
  NormalSums<4> gram;
  for (std::size_t i = 0; i < n; ++i) {
    double v[4] = {0.0, 0.0, 1.0, table.angleDeg[i]};
    phase.next(table.timeS[i], v[0], v[1]);
    gram.add(v, 0.0);
  }
  const Linear3 lin = solveGram(gram);
  SineFit f;
  f.a = lin.p[0];
  f.b = lin.p[1];
  f.offsetDeg = lin.p[2];
  f.omegaRadPerS = w;
  f.referenceS = referenceS;
  f.samples = n;
  f.residualRmsDeg = std::sqrt(lin.rss / static_cast<double>(n));
  const double sigma2 = lin.rss / static_cast<double>(n - 3);
  f.chiSquarePerDof = sigma2 / (table.noiseDeg * table.noiseDeg);
  const Eigen::MatrixXd cov = lin.xtx.inverse() * sigma2;
  finishFit(f, &cov, 0, 1, -1);
  return f;
}

SineFit fitGyroLinear(const GyroChannel& gyro, double w, double referenceS, bool weighted) {
  const std::size_t n = gyro.size();
  countPass(SampleStream::kGyro);
  GyroSinCosStream phase(gyro, w, 0.0);
  // Gram matrices of the raw and (when weighted) the whitened rows.
  NormalSums<4> raw, white;
  double prev[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < n; ++k) {
    double s1, c1, s0, c0;
    phase.next(k, s1, c1, s0, c0);
    const double v[4] = {s1 - s0, c1 - c0, gyro.endS[k] - gyro.startS[k], gyro.incrementDeg[k]};
    raw.add(v, 0.0);
    if (weighted) {
      const double m = gyro.cholSub[k], inv = 1.0 / gyro.cholDiag[k];
      for (int j = 0; j < 4; ++j) prev[j] = (v[j] - m * prev[j]) * inv;
      white.add(prev, 0.0);
    }
  }
  const Linear3 lin = solveGram(weighted ? white : raw);
  SineFit f;
  f.a = lin.p[0];
  f.b = lin.p[1];
  f.trendDegPerS = lin.p[2];
  f.omegaRadPerS = w;
  f.referenceS = referenceS;
  f.samples = n;
  const double sigma2 = lin.rss / static_cast<double>(n - 3);
  f.chiSquarePerDof = weighted ? sigma2 : 0.0;
  const Eigen::MatrixXd cov = lin.xtx.inverse() * sigma2;
  f.trendStdDegPerS = std::sqrt(cov(2, 2));
  finishFit(f, &cov, 0, 1, -1);
  // Raw residual RMS from the raw Gram matrix at these parameters.
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) = m(j, i) = raw.jtj[i][j];
  const Eigen::Vector4d q(lin.p[0], lin.p[1], lin.p[2], -1.0);
  f.residualRmsDeg = std::sqrt(std::max(q.dot(m * q), 0.0) / static_cast<double>(n));
  return f;
}

Result<SineFit> fitTableNonlinear(const TableChannel& table, const SineFit& start) {
  Eigen::VectorXd x0(4);
  x0 << start.a, start.b, start.offsetDeg, start.omegaRadPerS;
  auto sol = solveLeastSquares(TableSineProblem(table), x0);
  if (!sol) return Status(sol.status().code(), "table sine fit: " + sol.status().message());
  SineFit f;
  f.a = sol->x[0];
  f.b = sol->x[1];
  f.offsetDeg = sol->x[2];
  f.omegaRadPerS = sol->x[3];
  f.referenceS = start.referenceS;
  f.samples = sol->residuals;
  f.iterations = sol->iterations;
  f.chiSquarePerDof = sol->chiSquare / static_cast<double>(sol->residuals - 4);
  f.residualRmsDeg = table.noiseDeg * std::sqrt(sol->chiSquare / static_cast<double>(sol->residuals));
  finishFit(f, &sol->covariance, 0, 1, 3);
  return f;
}

Result<SineFit> fitGyroNonlinear(const GyroChannel& gyro, const SineFit& start) {
  Eigen::VectorXd x0(4);
  x0 << start.a, start.b, start.trendDegPerS, start.omegaRadPerS;
  auto sol = solveLeastSquares(GyroSineProblem(gyro), x0);
  if (!sol) return Status(sol.status().code(), "gyro sine fit: " + sol.status().message());
  SineFit f;
  f.a = sol->x[0];
  f.b = sol->x[1];
  f.trendDegPerS = sol->x[2];
  f.trendStdDegPerS = std::sqrt(sol->covariance(2, 2));
  f.omegaRadPerS = sol->x[3];
  f.referenceS = start.referenceS;
  f.samples = sol->residuals;
  f.iterations = sol->iterations;
  f.chiSquarePerDof = sol->chiSquare / static_cast<double>(sol->residuals - 4);
  finishFit(f, &sol->covariance, 0, 1, 3);
  // The raw residuals' RMS, summed as they are computed (the residuals
  // gyroIncrementResiduals gives, in the same order) rather than stored.
  countPass(SampleStream::kGyro);
  GyroSinCosStream phase(gyro, f.omegaRadPerS, 0.0);
  double raw = 0.0;
  for (std::size_t k = 0; k < gyro.size(); ++k) {
    double s1, c1, s0, c0;
    phase.next(k, s1, c1, s0, c0);
    const double r = gyro.incrementDeg[k] -
                     (f.a * (s1 - s0) + f.b * (c1 - c0) + f.trendDegPerS * (gyro.endS[k] - gyro.startS[k]));
    raw += r * r;
  }
  f.residualRmsDeg = std::sqrt(raw / static_cast<double>(gyro.size()));
  return f;
}

std::vector<double> tableResiduals(const TableChannel& table, const SineFit& f) {
  const std::size_t n = table.timeS.size();
  countPass(SampleStream::kTable);
  // Streamed: the sines and cosines are the series sinCosSeries would store,
  // used as they come rather than written out and read back.
  std::vector<double> r(n);
  SinCosStream phase(f.omegaRadPerS, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double sn, cs;
    phase.next(table.timeS[i], sn, cs);
    r[i] = table.angleDeg[i] - (f.a * sn + f.b * cs + f.offsetDeg);
  }
  return r;
}

std::vector<double> gyroIncrementResiduals(const GyroChannel& gyro, const SineFit& f) {
  countPass(SampleStream::kGyro);
  std::vector<double> r(gyro.size());
  GyroSinCosStream phase(gyro, f.omegaRadPerS, 0.0);
  for (std::size_t k = 0; k < r.size(); ++k) {
    double s1, c1, s0, c0;
    phase.next(k, s1, c1, s0, c0);
    r[k] = gyro.incrementDeg[k] -
           (f.a * (s1 - s0) + f.b * (c1 - c0) + f.trendDegPerS * (gyro.endS[k] - gyro.startS[k]));
  }
  return r;
}

IncrementResidualSums gyroIncrementResidualSums(const GyroChannel& gyro, const SineFit& f) {
  // The residual, the lag-1 products of neighbours that share an end point
  // and the prefix sums, each summed in the order the three separate passes
  // (gyroIncrementResiduals, then incrementResidualSums) sum them.
  countPass(SampleStream::kGyro);
  const std::size_t n = gyro.size();
  IncrementResidualSums out;
  out.prefix.resize(n + 1);
  out.prefix[0] = 0.0;
  GyroSinCosStream phase(gyro, f.omegaRadPerS, 0.0);
  double g1 = 0.0, previous = 0.0;
  std::size_t n1 = 0;
  for (std::size_t k = 0; k < n; ++k) {
    double s1, c1, s0, c0;
    phase.next(k, s1, c1, s0, c0);
    const double r = gyro.incrementDeg[k] -
                     (f.a * (s1 - s0) + f.b * (c1 - c0) + f.trendDegPerS * (gyro.endS[k] - gyro.startS[k]));
    if (k > 0 && gyro.continuesPrevious[k]) {
      g1 += r * previous;
      ++n1;
    }
    out.prefix[k + 1] = out.prefix[k] + r;
    previous = r;
  }
  g1 = n1 ? g1 / static_cast<double>(n1) : 0.0;
  out.quantisationVarianceDeg2 = std::max(-g1, 0.0);
  return out;
}

}  // namespace fog::analysis
