#include "analysis/sine_fit.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <cmath>

#include "analysis/least_squares.h"
#include "common/units.h"

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
class TableSineCost final : public ceres::CostFunction {
 public:
  explicit TableSineCost(const TableChannel& table) : t_(table) {
    set_num_residuals(static_cast<int>(table.timeS.size()));
    mutable_parameter_block_sizes()->push_back(4);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double a = parameters[0][0], b = parameters[0][1], c = parameters[0][2], w = parameters[0][3];
    const double inv = 1.0 / t_.noiseDeg;
    const std::size_t n = t_.timeS.size();
    double* J = jacobians ? jacobians[0] : nullptr;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = t_.timeS[i];
      const double s = std::sin(w * t), co = std::cos(w * t);
      residuals[i] = (t_.angleDeg[i] - (a * s + b * co + c)) * inv;
      if (J) {
        double* row = J + 4 * i;
        row[0] = -s * inv;
        row[1] = -co * inv;
        row[2] = -inv;
        row[3] = -(a * co - b * s) * t * inv;
      }
    }
    return true;
  }

 private:
  const TableChannel& t_;
};

// Gyro increments: d_k = f(t_k) - f(s_k), f = a*sin(w*t) + b*cos(w*t) + g*t,
// parameters (a, b, g, w), whitened by the channel's noise model.
class GyroSineCost final : public ceres::CostFunction {
 public:
  explicit GyroSineCost(const GyroChannel& gyro) : g_(gyro) {
    set_num_residuals(static_cast<int>(gyro.size()));
    mutable_parameter_block_sizes()->push_back(4);
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double a = parameters[0][0], b = parameters[0][1], d = parameters[0][2], w = parameters[0][3];
    const std::size_t n = g_.size();
    double* J = jacobians ? jacobians[0] : nullptr;
    for (std::size_t k = 0; k < n; ++k) {
      const double t1 = g_.endS[k], t0 = g_.startS[k];
      const double s1 = std::sin(w * t1), c1 = std::cos(w * t1);
      const double s0 = std::sin(w * t0), c0 = std::cos(w * t0);
      residuals[k] = g_.incrementDeg[k] - (a * (s1 - s0) + b * (c1 - c0) + d * (t1 - t0));
      if (J) {
        double* row = J + 4 * k;
        row[0] = -(s1 - s0);
        row[1] = -(c1 - c0);
        row[2] = -(t1 - t0);
        row[3] = -(a * (t1 * c1 - t0 * c0) - b * (t1 * s1 - t0 * s0));
      }
    }
    g_.whiten(residuals);
    if (J)
      for (int col = 0; col < 4; ++col) g_.whiten(J + col, 4);
    return true;
  }

 private:
  const GyroChannel& g_;
};

}  // namespace

SineFit fitTableLinear(const TableChannel& table, double w, double referenceS) {
  Eigen::Matrix3d xtx = Eigen::Matrix3d::Zero();
  Eigen::Vector3d xty = Eigen::Vector3d::Zero();
  const std::size_t n = table.timeS.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d x(std::sin(w * table.timeS[i]), std::cos(w * table.timeS[i]), 1.0);
    xtx.noalias() += x * x.transpose();
    xty.noalias() += x * table.angleDeg[i];
  }
  const Eigen::Vector3d p = xtx.ldlt().solve(xty);
  SineFit f;
  f.a = p[0];
  f.b = p[1];
  f.offsetDeg = p[2];
  f.omegaRadPerS = w;
  f.referenceS = referenceS;
  f.samples = n;
  const auto r = tableResiduals(table, f);
  double rss = 0.0;
  for (double v : r) rss += v * v;
  f.residualRmsDeg = std::sqrt(rss / static_cast<double>(n));
  const double sigma2 = rss / static_cast<double>(n - 3);
  f.chiSquarePerDof = sigma2 / (table.noiseDeg * table.noiseDeg);
  const Eigen::MatrixXd cov = xtx.inverse() * sigma2;
  finishFit(f, &cov, 0, 1, -1);
  return f;
}

SineFit fitGyroLinear(const GyroChannel& gyro, double w, double referenceS, bool weighted) {
  const std::size_t n = gyro.size();
  Eigen::MatrixXd x(n, 3);
  Eigen::VectorXd y(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t1 = gyro.endS[k], t0 = gyro.startS[k];
    x(k, 0) = std::sin(w * t1) - std::sin(w * t0);
    x(k, 1) = std::cos(w * t1) - std::cos(w * t0);
    x(k, 2) = t1 - t0;
    y[k] = gyro.incrementDeg[k];
  }
  if (weighted) {
    for (int c = 0; c < 3; ++c) gyro.whiten(x.col(c).data());
    gyro.whiten(y.data());
  }
  const Eigen::Matrix3d xtx = x.transpose() * x;
  const Eigen::Vector3d p = xtx.ldlt().solve(x.transpose() * y);
  const double rss = (y - x * p).squaredNorm();
  SineFit f;
  f.a = p[0];
  f.b = p[1];
  f.trendDegPerS = p[2];
  f.omegaRadPerS = w;
  f.referenceS = referenceS;
  f.samples = n;
  const double sigma2 = rss / static_cast<double>(n - 3);
  f.chiSquarePerDof = weighted ? sigma2 : 0.0;
  const Eigen::MatrixXd cov = xtx.inverse() * sigma2;
  f.trendStdDegPerS = std::sqrt(cov(2, 2));
  finishFit(f, &cov, 0, 1, -1);
  const auto r = gyroIncrementResiduals(gyro, f);
  double raw = 0.0;
  for (double v : r) raw += v * v;
  f.residualRmsDeg = std::sqrt(raw / static_cast<double>(n));
  return f;
}

Result<SineFit> fitTableNonlinear(const TableChannel& table, const SineFit& start) {
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  costs.push_back(std::make_unique<TableSineCost>(table));
  Eigen::VectorXd x0(4);
  x0 << start.a, start.b, start.offsetDeg, start.omegaRadPerS;
  auto sol = solveLeastSquares(std::move(costs), x0);
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
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  costs.push_back(std::make_unique<GyroSineCost>(gyro));
  Eigen::VectorXd x0(4);
  x0 << start.a, start.b, start.trendDegPerS, start.omegaRadPerS;
  auto sol = solveLeastSquares(std::move(costs), x0);
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
  const auto r = gyroIncrementResiduals(gyro, f);
  double raw = 0.0;
  for (double v : r) raw += v * v;
  f.residualRmsDeg = std::sqrt(raw / static_cast<double>(r.size()));
  return f;
}

std::vector<double> tableResiduals(const TableChannel& table, const SineFit& f) {
  std::vector<double> r(table.timeS.size());
  const double w = f.omegaRadPerS;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double t = table.timeS[i];
    r[i] = table.angleDeg[i] - (f.a * std::sin(w * t) + f.b * std::cos(w * t) + f.offsetDeg);
  }
  return r;
}

std::vector<double> gyroIncrementResiduals(const GyroChannel& gyro, const SineFit& f) {
  std::vector<double> r(gyro.size());
  const double w = f.omegaRadPerS;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double t1 = gyro.endS[k], t0 = gyro.startS[k];
    r[k] = gyro.incrementDeg[k] - (f.a * (std::sin(w * t1) - std::sin(w * t0)) +
                                   f.b * (std::cos(w * t1) - std::cos(w * t0)) + f.trendDegPerS * (t1 - t0));
  }
  return r;
}

}  // namespace fog::analysis
