// The nonlinear least-squares driver: Gauss-Newton from good starts, with
// Levenberg-Marquardt (Ceres TinySolver) taking over when a step fails, and
// the covariance of either path.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/analysis/least_squares.h"

namespace fog::analysis {
namespace {

// y_i = model(t_i, x) with unit weights and two parameters; the model returns
// its value and fills d model / d x.
using Model = double (*)(double t, const double* x, double* gradient);

class CurveFit final : public LeastSquaresProblem {
 public:
  CurveFit(Model model, std::vector<double> t, std::vector<double> y)
      : model_(model), t_(std::move(t)), y_(std::move(y)) {}
  std::size_t numResiduals() const override { return t_.size(); }
  int numParameters() const override { return 2; }
  double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const override {
    NormalSums<2> sums;
    double rss = 0.0;
    for (std::size_t i = 0; i < t_.size(); ++i) {
      double gradient[2];
      const double r = y_[i] - model_(t_[i], x, gradient);
      rss += r * r;
      const double row[2] = {-gradient[0], -gradient[1]};
      sums.add(row, r);
    }
    if (jtj) sums.addTo(*jtj, *jtr);
    return rss;
  }

 private:
  Model model_;
  std::vector<double> t_, y_;
};

// A exp(-k t), parameters (A, k).
double exponentialDecay(double t, const double* x, double* gradient) {
  const double e = std::exp(-x[1] * t);
  gradient[0] = e;
  gradient[1] = -x[0] * t * e;
  return x[0] * e;
}

// p0 + p1 t: linear, so one Gauss-Newton step lands on the optimum.
double straightLine(double t, const double* x, double* gradient) {
  gradient[0] = 1.0;
  gradient[1] = t;
  return x[0] + x[1] * t;
}

struct Data {
  std::vector<double> t, y;
};

Data decay(double amplitude, double rate, double noise, int n) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, noise);
  Data d;
  for (int i = 0; i < n; ++i) {
    d.t.push_back(0.01 * i);
    d.y.push_back(amplitude * std::exp(-rate * d.t.back()) + gauss(rng));
  }
  return d;
}

TEST(LeastSquares, StraightLineGivesTheClosedFormSolutionAndCovariance) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss(0.0, 0.1);
  Data d;
  for (int i = 0; i < 1000; ++i) {
    d.t.push_back(0.001 * i);
    d.y.push_back(2.0 - 3.0 * d.t.back() + gauss(rng));
  }
  Eigen::MatrixXd x(d.t.size(), 2);
  Eigen::VectorXd y(d.t.size());
  for (std::size_t i = 0; i < d.t.size(); ++i) {
    x(i, 0) = 1.0;
    x(i, 1) = d.t[i];
    y[i] = d.y[i];
  }
  const Eigen::Vector2d ols = (x.transpose() * x).ldlt().solve(x.transpose() * y);
  const double rss = (y - x * ols).squaredNorm();
  const Eigen::Matrix2d cov = (x.transpose() * x).inverse() * rss / (static_cast<double>(d.t.size()) - 2.0);

  auto sol = solveLeastSquares(CurveFit(straightLine, d.t, d.y), Eigen::Vector2d(0.0, 0.0));
  ASSERT_TRUE(sol.isOk()) << sol.status().toString();
  EXPECT_EQ(sol->iterations, 2);  // one step to the optimum, one pass to see it is there
  EXPECT_NEAR(sol->x[0], ols[0], 1e-12);
  EXPECT_NEAR(sol->x[1], ols[1], 1e-12);
  EXPECT_NEAR(sol->chiSquare / rss, 1.0, 1e-9);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(sol->covariance(i, j) / cov(i, j), 1.0, 1e-9);
}

TEST(LeastSquares, FarStartFallsBackToLevenbergMarquardtAndAgreesWithANearStart) {
  const Data d = decay(5.0, 2.0, 0.05, 500);
  const CurveFit problem(exponentialDecay, d.t, d.y);
  // From the truth's neighbourhood Gauss-Newton converges in a few passes.
  auto near = solveLeastSquares(problem, Eigen::Vector2d(5.1, 2.05));
  ASSERT_TRUE(near.isOk()) << near.status().toString();
  EXPECT_LE(near->iterations, 4);
  // From a rate 15x too high, a Gauss-Newton step overshoots into a worse
  // cost; Levenberg-Marquardt must still find the same optimum.
  auto far = solveLeastSquares(problem, Eigen::Vector2d(1.0, 30.0));
  ASSERT_TRUE(far.isOk()) << far.status().toString();
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(far->x[i], near->x[i], 1e-3 * std::sqrt(near->covariance(i, i)));
    EXPECT_NEAR(far->covariance(i, i) / near->covariance(i, i), 1.0, 1e-3);
  }
  EXPECT_NEAR(near->x[0], 5.0, 4.0 * std::sqrt(near->covariance(0, 0)));
  EXPECT_NEAR(near->x[1], 2.0, 4.0 * std::sqrt(near->covariance(1, 1)));
  EXPECT_NEAR(far->chiSquare / near->chiSquare, 1.0, 1e-9);
}

TEST(LeastSquares, FewerResidualsThanParametersIsInsufficientData) {
  auto sol = solveLeastSquares(CurveFit(straightLine, {0.0, 1.0}, {1.0, 2.0}), Eigen::Vector2d(0.0, 0.0));
  ASSERT_FALSE(sol.isOk());
  EXPECT_EQ(sol.status().code(), StatusCode::kInsufficientData);
}

}  // namespace
}  // namespace fog::analysis
