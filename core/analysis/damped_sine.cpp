#include "core/analysis/damped_sine.h"

#include <Eigen/Dense>
#include <cmath>

#include "core/analysis/least_squares.h"
#include "core/analysis/sample_passes.h"
#include "core/common/units.h"

namespace fog::analysis {

namespace {

enum Param { kW = 0, kLambda, kA, kB, kC, kParams };

// Table rows exp(-lambda*t)*(a*sin(w*t) + b*cos(w*t)) + c, unit weights (the
// covariance is scaled by chi^2/(N - p), so the weight's level does not matter).
class DampedTableProblem final : public LeastSquaresProblem {
 public:
  explicit DampedTableProblem(const TableChannel& table) : t_(table) {}
  std::size_t numResiduals() const override { return t_.timeS.size(); }
  int numParameters() const override { return kParams; }
  double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    countPass(SampleStream::kTable);
    NormalSums<kParams> sums;
    double rss = 0.0;
    for (std::size_t i = 0; i < t_.timeS.size(); ++i) {
      const double t = t_.timeS[i];
      const double e = std::exp(-x[kLambda] * t), sn = std::sin(x[kW] * t), cs = std::cos(x[kW] * t);
      const double shape = x[kA] * sn + x[kB] * cs;
      const double r = t_.angleDeg[i] - (e * shape + x[kC]);
      rss += r * r;
      if (jtj) {
        const double row[kParams] = {-e * t * (x[kA] * cs - x[kB] * sn), t * e * shape, -e * sn, -e * cs, -1.0};
        sums.add(row, r);
      }
    }
    if (jtj) sums.addTo(*jtj, *jtr);
    return rss;
  }

 private:
  const TableChannel& t_;
};

}  // namespace

std::optional<DampedSineLag> fitDampedSineLag(const Channels& ch, double omegaStart, double lambdaStart) {
  const auto& tt = ch.table.timeS;
  if (tt.size() < 32 || ch.gyro.size() < 32) return std::nullopt;
  // Linear start at (omega, lambda).
  countPass(SampleStream::kTable);
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < tt.size(); ++i) {
    const double e = std::exp(-lambdaStart * tt[i]);
    const Eigen::Vector3d row(e * std::sin(omegaStart * tt[i]), e * std::cos(omegaStart * tt[i]), 1.0);
    ata.noalias() += row * row.transpose();
    aty.noalias() += row * ch.table.angleDeg[i];
  }
  const Eigen::Vector3d lin = ata.ldlt().solve(aty);
  Eigen::VectorXd x0(kParams);
  x0 << omegaStart, lambdaStart, lin[0], lin[1], lin[2];
  auto sol = solveLeastSquares(DampedTableProblem(ch.table), x0);
  if (!sol) return std::nullopt;
  const Eigen::VectorXd& x = sol->x;
  const double w = x[kW], lambda = x[kLambda];
  if (!(w > 0.0) || !std::isfinite(lambda)) return std::nullopt;

  // Gyro increments at the table's (w, lambda): d_k = [f(t_k) - f(s_k)] with
  // f = exp(-lambda*t)*(p*sin + q*cos), plus trend*dt. Ordinary least squares.
  const GyroChannel& g = ch.gyro;
  Eigen::Matrix3d gtg = Eigen::Matrix3d::Zero();
  Eigen::Vector3d gty = Eigen::Vector3d::Zero();
  auto basis = [&](double t, double& s, double& c) {
    const double e = std::exp(-lambda * t);
    s = e * std::sin(w * t);
    c = e * std::cos(w * t);
  };
  countPass(SampleStream::kGyro, 2);  // the fit and its residuals
  for (std::size_t k = 0; k < g.size(); ++k) {
    double s1, c1, s0, c0;
    basis(g.endS[k], s1, c1);
    basis(g.startS[k], s0, c0);
    const Eigen::Vector3d row(s1 - s0, c1 - c0, g.endS[k] - g.startS[k]);
    gtg.noalias() += row * row.transpose();
    gty.noalias() += row * g.incrementDeg[k];
  }
  const Eigen::Vector3d gp = gtg.ldlt().solve(gty);
  double rss = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k) {
    double s1, c1, s0, c0;
    basis(g.endS[k], s1, c1);
    basis(g.startS[k], s0, c0);
    const double r = g.incrementDeg[k] - (gp[0] * (s1 - s0) + gp[1] * (c1 - c0) + gp[2] * (g.endS[k] - g.startS[k]));
    rss += r * r;
  }
  const Eigen::Matrix3d gcov = gtg.inverse() * (rss / static_cast<double>(g.size() - 3));

  // Phase psi of p*sin + q*cos (= R*sin(w*t + psi)); lag = (psiT - psiG)/w.
  const double psiT = std::atan2(x[kB], x[kA]), psiG = std::atan2(gp[1], gp[0]);
  double dpsi = std::remainder(psiT - psiG, kTwoPi);
  const double r2 = gp[0] * gp[0] + gp[1] * gp[1];
  // d psiG / d(p, q) = (-q, p)/R^2.
  const Eigen::Vector2d grad(-gp[1] / r2, gp[0] / r2);
  const double varPsiG = grad.dot(gcov.topLeftCorner<2, 2>() * grad);
  const double rt2 = x[kA] * x[kA] + x[kB] * x[kB];
  const Eigen::Vector2d gradT(-x[kB] / rt2, x[kA] / rt2);
  const Eigen::Matrix2d tcov = sol->covariance.block<2, 2>(kA, kA);
  const double varPsiT = gradT.dot(tcov * gradT);

  DampedSineLag out;
  out.lagMs = dpsi / w * 1e3;
  out.lagStdMs = std::sqrt(varPsiG + varPsiT) / w * 1e3;
  out.frequencyHz = w / kTwoPi;
  out.decayTimeS = lambda != 0.0 ? 1.0 / lambda : INFINITY;
  out.tableResidualRmsDeg = std::sqrt(sol->chiSquare / static_cast<double>(tt.size()));
  out.gain = std::sqrt(r2 / rt2) * std::exp(-lambda * out.lagMs * 1e-3);
  // Degenerate increments (all but zero: a frame period of 1e-300 ms) leave a
  // singular gyro system: no lag is offered rather than "± nan".
  if (!std::isfinite(out.lagMs) || !(out.lagStdMs >= 0.0) || !std::isfinite(out.lagStdMs) ||
      !std::isfinite(out.gain) || !std::isfinite(out.tableResidualRmsDeg))
    return std::nullopt;
  return out;
}

}  // namespace fog::analysis
