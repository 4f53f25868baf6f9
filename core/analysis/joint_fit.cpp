#include "analysis/joint_fit.h"

#include <ceres/ceres.h>

#include <cmath>

#include "analysis/least_squares.h"
#include "common/units.h"

namespace fog::analysis {

namespace {

enum Param { kW = 0, kA, kB, kC, kG, kLag, kD, kParams };

class TableJointCost final : public ceres::CostFunction {
 public:
  explicit TableJointCost(const TableChannel& table) : t_(table) {
    set_num_residuals(static_cast<int>(table.timeS.size()));
    mutable_parameter_block_sizes()->push_back(kParams);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const double w = p[0][kW], a = p[0][kA], b = p[0][kB], c = p[0][kC];
    const double inv = 1.0 / t_.noiseDeg;
    double* J = jacobians ? jacobians[0] : nullptr;
    for (std::size_t i = 0; i < t_.timeS.size(); ++i) {
      const double t = t_.timeS[i];
      const double s = std::sin(w * t), co = std::cos(w * t);
      residuals[i] = (t_.angleDeg[i] - (a * s + b * co + c)) * inv;
      if (J) {
        double* row = J + kParams * i;
        row[kW] = -(a * co - b * s) * t * inv;
        row[kA] = -s * inv;
        row[kB] = -co * inv;
        row[kC] = -inv;
        row[kG] = row[kLag] = row[kD] = 0.0;
      }
    }
    return true;
  }

 private:
  const TableChannel& t_;
};

class GyroJointCost final : public ceres::CostFunction {
 public:
  explicit GyroJointCost(const GyroChannel& gyro) : g_(gyro) {
    set_num_residuals(static_cast<int>(gyro.size()));
    mutable_parameter_block_sizes()->push_back(kParams);
  }
  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const double w = p[0][kW], a = p[0][kA], b = p[0][kB], g = p[0][kG], lag = p[0][kLag], d = p[0][kD];
    double* J = jacobians ? jacobians[0] : nullptr;
    for (std::size_t k = 0; k < g_.size(); ++k) {
      const double t1 = g_.endS[k] - lag, t0 = g_.startS[k] - lag;
      const double s1 = std::sin(w * t1), c1 = std::cos(w * t1);
      const double s0 = std::sin(w * t0), c0 = std::cos(w * t0);
      const double ds = s1 - s0, dc = c1 - c0;
      const double dt = g_.endS[k] - g_.startS[k];
      residuals[k] = g_.incrementDeg[k] - (g * (a * ds + b * dc) + d * dt);
      if (J) {
        double* row = J + kParams * k;
        // derivative of a*cos(w*x) - b*sin(w*x) terms
        const double q1 = a * c1 - b * s1, q0 = a * c0 - b * s0;
        row[kW] = -g * (q1 * t1 - q0 * t0);
        row[kA] = -g * ds;
        row[kB] = -g * dc;
        row[kC] = 0.0;
        row[kG] = -(a * ds + b * dc);
        row[kLag] = g * w * (q1 - q0);
        row[kD] = -dt;
      }
    }
    g_.whiten(residuals);
    if (J)
      for (int col = 0; col < kParams; ++col) g_.whiten(J + col, kParams);
    return true;
  }

 private:
  const GyroChannel& g_;
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
  x0[kG] = gyroFit.amplitudeDeg / tableFit.amplitudeDeg;
  x0[kLag] = wrapToHalfPeriod((psiT - psiG) / w, period);
  x0[kD] = gyroFit.trendDegPerS;

  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  costs.push_back(std::make_unique<TableJointCost>(ch.table));
  costs.push_back(std::make_unique<GyroJointCost>(ch.gyro));
  auto sol = solveLeastSquares(std::move(costs), x0);
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
  f.trendDegPerS = x[kD];
  f.trendStdDegPerS = std::sqrt(cov(kD, kD));
  f.chiSquarePerDof = sol->chiSquare / static_cast<double>(sol->residuals - kParams);
  f.iterations = sol->iterations;
  return f;
}

}  // namespace fog::analysis
