#include "core/analysis/joint_fit.h"

#include <cmath>
#include <future>

#include "core/analysis/least_squares.h"
#include "core/analysis/sample_passes.h"
#include "core/analysis/sin_cos_series.h"
#include "core/common/units.h"

namespace fog::analysis {

namespace {

enum Param { kW = 0, kA, kB, kC, kG, kLag, kD, kParams };

// Residuals: the table's (weighted by its white noise), then the gyro
// increments' (whitened by their noise model).
class JointProblem final : public LeastSquaresProblem {
 public:
  JointProblem(const TableChannel& table, const GyroChannel& gyro)
      : t_(table), g_(gyro), nT_(table.timeS.size()), nG_(gyro.size()) {}
  std::size_t numResiduals() const override { return nT_ + nG_; }
  int numParameters() const override { return kParams; }

  // The table and gyro rows are independent sums: each pass runs them on two
  // threads (the bench machine has two cores) and adds the results.
  double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    countPass(SampleStream::kTable);
    countPass(SampleStream::kGyro);
    NormalSums<4> tableSums;
    NormalSums<kParams> gyroSums;
    const bool withJacobian = jtj != nullptr;
    auto table = std::async(std::launch::async, [&] { return accumulateTable(x, withJacobian, tableSums); });
    const double rssGyro = accumulateGyro(x, withJacobian, gyroSums);
    const double rss = table.get() + rssGyro;
    if (withJacobian) {
      // The table rows touch only (w, a, b, c), the first four parameters.
      static_assert(kW == 0 && kA == 1 && kB == 2 && kC == 3);
      tableSums.addTo(*jtj, *jtr);
      gyroSums.addTo(*jtj, *jtr);
    }
    return rss;
  }

 private:
  // Table rows: a*sin(w*t) + b*cos(w*t) + c, parameters (w, a, b, c).
  // Both accumulators sum into a local and copy it out at the end: summed
  // into `out` directly, every add was a load and a store (the compiler
  // cannot tell it from the samples).
  double accumulateTable(const double* x, bool withJacobian, NormalSums<4>& out) const {
    const double w = x[kW], a = x[kA], b = x[kB], c = x[kC];
    NormalSums<4> sums;
    const double inv = 1.0 / t_.noiseDeg;
    SinCosStream phase(w, 0.0);
    double rss = 0.0;
    for (std::size_t i = 0; i < nT_; ++i) {
      double sn, cs;
      phase.next(t_.timeS[i], sn, cs);
      const double r = (t_.angleDeg[i] - (a * sn + b * cs + c)) * inv;
      rss += r * r;
      if (withJacobian) {
        const double row[4] = {-(a * cs - b * sn) * t_.timeS[i] * inv, -sn * inv, -cs * inv, -inv};
        sums.add(row, r);
      }
    }
    out = sums;
    return rss;
  }

  // Gyro rows: g*(a*sin(w*(t - lag)) + b*cos(w*(t - lag))) + d*t, differenced
  // over each frame and whitened.
  double accumulateGyro(const double* x, bool withJacobian, NormalSums<kParams>& out) const {
    const double w = x[kW], a = x[kA], b = x[kB], g = x[kG], lag = x[kLag], d = x[kD];
    NormalSums<kParams> sums;
    GyroSinCosStream phase(g_, w, lag);
    double rss = 0.0;
    double prev[kParams + 1] = {};  // previous whitened row and residual
    for (std::size_t k = 0; k < nG_; ++k) {
      double s1, c1, s0, c0;
      phase.next(k, s1, c1, s0, c0);
      const double t1 = g_.endS[k] - lag, t0 = g_.startS[k] - lag;
      const double ds = s1 - s0, dc = c1 - c0;
      const double dt = g_.endS[k] - g_.startS[k];
      // d/dx of a*sin(w*x) + b*cos(w*x) is w*(a*cos - b*sin)
      const double q1 = a * c1 - b * s1, q0 = a * c0 - b * s0;
      double raw[kParams + 1];
      raw[kW] = -g * (q1 * t1 - q0 * t0);
      raw[kA] = -g * ds;
      raw[kB] = -g * dc;
      raw[kC] = 0.0;
      raw[kG] = -(a * ds + b * dc);
      raw[kLag] = g * w * (q1 - q0);
      raw[kD] = -dt;
      raw[kParams] = g_.incrementDeg[k] - (g * (a * ds + b * dc) + d * dt);
      const double m = g_.cholSub[k], inv = 1.0 / g_.cholDiag[k];
      const int from = withJacobian ? 0 : kParams;
      for (int j = from; j <= kParams; ++j) prev[j] = (raw[j] - m * prev[j]) * inv;
      rss += prev[kParams] * prev[kParams];
      if (withJacobian) sums.add(prev, prev[kParams]);
    }
    out = sums;
    return rss;
  }

  const TableChannel& t_;
  const GyroChannel& g_;
  std::size_t nT_, nG_;
};

}  // namespace

Result<JointFit> fitJoint(const Channels& ch, const SineFit& tableFit, const SineFit& gyroFit) {
  Eigen::VectorXd x0(kParams);
  const double w = tableFit.omegaRadPerS;
  const double period = kTwoPi / w;
  const double psiT = std::atan2(tableFit.b, tableFit.a);
  const double psiG = std::atan2(gyroFit.b, gyroFit.a);
  x0[kW] = w;
  x0[kA] = tableFit.a;
  x0[kB] = tableFit.b;
  x0[kC] = tableFit.offsetDeg;
  // A gyro that turns against the table (reversed axis) is in antiphase: its
  // gain starts negative, so the lag stays the small delay, never a half period.
  double dpsi = std::remainder(psiT - psiG, kTwoPi);
  double gain = gyroFit.amplitudeDeg / tableFit.amplitudeDeg;
  if (std::abs(dpsi) > 0.5 * kPi) {
    gain = -gain;
    dpsi = std::remainder(dpsi + kPi, kTwoPi);
  }
  x0[kG] = gain;
  x0[kLag] = wrapToHalfPeriod(dpsi / w, period);
  x0[kD] = gyroFit.trendDegPerS;

  auto sol = solveLeastSquares(JointProblem(ch.table, ch.gyro), x0);
  if (!sol) return Status(sol.status().code(), "joint fit: " + sol.status().message());

  JointFit f;
  const auto& x = sol->x;
  const auto& cov = sol->covariance;
  f.omegaRadPerS = x[kW];
  f.frequencyHz = x[kW] / kTwoPi;
  f.frequencyStdHz = std::sqrt(cov(kW, kW)) / kTwoPi;
  f.a = x[kA];
  f.b = x[kB];
  f.offsetDeg = x[kC];
  f.gain = x[kG];
  f.gainStd = std::sqrt(cov(kG, kG));
  f.lagS = x[kLag];
  f.lagStdS = std::sqrt(cov(kLag, kLag));
  if (f.gainStd > 0.0 && f.lagStdS > 0.0) f.gainLagCorrelation = cov(kG, kLag) / (f.gainStd * f.lagStdS);
  f.trendDegPerS = x[kD];
  f.trendStdDegPerS = std::sqrt(cov(kD, kD));
  f.chiSquarePerDof = sol->chiSquare / static_cast<double>(sol->residuals - kParams);
  f.iterations = sol->iterations;
  return f;
}

}  // namespace fog::analysis
