#include "core/analysis/least_squares.h"

#include <ceres/tiny_solver.h>

#include <cmath>
#include <limits>
#include <string>

namespace fog::analysis {

namespace {

// Full symmetric J^T J from the accumulated lower triangle.
Eigen::MatrixXd symmetric(const Eigen::MatrixXd& lower) { return lower.selfadjointView<Eigen::Lower>(); }

// Factorises a symmetric J^T J, adding a tiny ridge only if it is
// numerically singular. Returns false if no ridge helps.
bool factor(const Eigen::MatrixXd& jtj, Eigen::LLT<Eigen::MatrixXd>& llt) {
  const int p = static_cast<int>(jtj.rows());
  llt.compute(jtj);
  for (double ridge = 1e-14; llt.info() != Eigen::Success && ridge < 1.0; ridge *= 100.0)
    llt.compute(jtj + ridge * jtj.diagonal().cwiseAbs().maxCoeff() * Eigen::MatrixXd::Identity(p, p));
  return llt.info() == Eigen::Success;
}

// Presents the problem to ceres::TinySolver as its (p+1)-residual equivalent.
struct CompressedProblem {
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };
  const LeastSquaresProblem& problem;
  // The normal matrix of the last full evaluation, kept for the covariance:
  // TinySolver stops after a step too small to matter, so this is J^T J a
  // negligible step from the solution, and saves one more pass over the data.
  mutable Eigen::MatrixXd lastJtj;
  int NumResiduals() const { return problem.numParameters() + 1; }
  int NumParameters() const { return problem.numParameters(); }

  bool operator()(const double* x, double* residuals, double* jacobian) const {
    const int p = problem.numParameters();
    if (!jacobian) {
      const double rss = problem.accumulate(x, nullptr, nullptr);
      for (int i = 0; i < p; ++i) residuals[i] = 0.0;
      residuals[p] = std::sqrt(rss);
      return std::isfinite(rss);
    }
    Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(p, p);
    Eigen::VectorXd jtr = Eigen::VectorXd::Zero(p);
    const double rss = problem.accumulate(x, &jtj, &jtr);
    if (!std::isfinite(rss)) return false;
    jtj = symmetric(jtj);
    lastJtj = jtj;
    // A tiny ridge only if the normal matrix is numerically singular.
    Eigen::LLT<Eigen::MatrixXd> llt;
    if (!factor(jtj, llt)) return false;
    const Eigen::MatrixXd l = llt.matrixL();
    const Eigen::VectorXd z = l.triangularView<Eigen::Lower>().solve(jtr);
    Eigen::Map<Eigen::MatrixXd> j(jacobian, p + 1, p);
    j.topRows(p) = l.transpose();
    j.row(p).setZero();
    for (int i = 0; i < p; ++i) residuals[i] = z[i];
    residuals[p] = std::sqrt(std::max(rss - z.squaredNorm(), 0.0));
    return true;
  }
};

// The covariance inv(J^T J) * chi^2/(N - p), or an error if it is not usable.
// A solver that never completed a finite evaluation leaves `jtj` empty, and
// data with a value near the double's range (an increment of 1e200 squares to
// inf) leave it or chi^2 non-finite: both are refusals, never a covariance.
Status fillCovariance(const Eigen::MatrixXd& jtj, LeastSquaresSolution& out, int p) {
  if (jtj.rows() != p || jtj.cols() != p || !jtj.allFinite() || !std::isfinite(out.chiSquare))
    return Status(StatusCode::kNotConverged,
                  "the fit's sums are not finite numbers (a value in the data is far beyond its range)");
  Eigen::LDLT<Eigen::MatrixXd> ldlt(jtj);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-300))
    return Status(StatusCode::kNotConverged, "the fit's parameters are not determined by the data");
  const double scale = out.chiSquare / static_cast<double>(out.residuals - static_cast<std::size_t>(p));
  out.covariance = ldlt.solve(Eigen::MatrixXd::Identity(p, p)) * scale;
  for (int i = 0; i < p; ++i)
    if (!(out.covariance(i, i) >= 0.0) || !std::isfinite(out.covariance(i, i)))
      return Status(StatusCode::kNotConverged, "the fit's covariance is not positive");
  return Status::ok();
}

// Gauss-Newton from a start close to the optimum (the bench's starts come
// from linear fits), stopping when the next step is under 1 % of a standard
// error: its Mahalanobis length dx^T J^T J dx / sigma^2 = z^T z / sigma^2 is
// below 1e-4. The last step is taken without another pass, and chi^2 is the
// quadratic model's: the step is far too small for the model to be wrong.
// Returns false (leaving `x` at the best point seen) if a step does not
// reduce the cost or the steps do not converge fast; Levenberg-Marquardt
// then takes over.
bool gaussNewton(const LeastSquaresProblem& problem, Eigen::VectorXd& x, LeastSquaresSolution& out,
                 Eigen::MatrixXd& jtjAtSolution) {
  const int p = problem.numParameters();
  const double dof = static_cast<double>(out.residuals - static_cast<std::size_t>(p));
  constexpr int kMaxSteps = 4;
  constexpr double kConverged = 1e-4;
  double bestRss = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best = x;
  for (int step = 0; step < kMaxSteps; ++step) {
    Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(p, p);
    Eigen::VectorXd jtr = Eigen::VectorXd::Zero(p);
    const double rss = problem.accumulate(x.data(), &jtj, &jtr);
    if (!std::isfinite(rss) || rss >= bestRss) break;
    bestRss = rss;
    best = x;
    jtj = symmetric(jtj);
    Eigen::LLT<Eigen::MatrixXd> llt;
    if (!factor(jtj, llt)) break;
    const Eigen::VectorXd z = llt.matrixL().solve(jtr);
    const Eigen::VectorXd dx = -llt.matrixU().solve(z);
    const double sigma2 = rss / dof;
    x += dx;
    if (sigma2 > 0.0 && z.squaredNorm() < kConverged * sigma2) {
      out.iterations = step + 1;
      out.chiSquare = std::max(rss - z.squaredNorm(), 0.0);
      jtjAtSolution = jtj;
      return x.allFinite();
    }
  }
  x = best;
  return false;
}

}  // namespace

Result<LeastSquaresSolution> solveLeastSquares(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0) {
  const int p = problem.numParameters();
  const std::size_t n = problem.numResiduals();
  if (n <= static_cast<std::size_t>(p))
    return insufficientData("not enough samples to fit " + std::to_string(p) + " parameters");

  LeastSquaresSolution out;
  out.x = x0;
  out.residuals = n;
  Eigen::MatrixXd jtj;
  if (gaussNewton(problem, out.x, out, jtj)) {
    if (auto s = fillCovariance(jtj, out, p); !s.isOk()) return s;
    return out;
  }

  CompressedProblem compressed{problem, {}};
  ceres::TinySolver<CompressedProblem> solver;
  solver.options.max_num_iterations = 50;
  // TinySolver's cost-change test is absolute. The cost is ~N/2 at the
  // optimum and evaluates with ~1e-11 relative rounding noise, so stop when a
  // step changes it by under 1e-10 relative: near the optimum that is a
  // parameter change of under 1 % of its standard error.
  solver.options.function_tolerance = 1e-10 * static_cast<double>(n);
  solver.options.parameter_tolerance = 1e-14;
  solver.options.gradient_tolerance = 1e-12;
  // The starts come from linear fits: the first steps can be Gauss-Newton steps.
  solver.options.initial_trust_region_radius = 1e12;
  const auto& summary = solver.Solve(compressed, &out.x);
  out.iterations = summary.iterations;
  if (summary.status == ceres::TinySolver<CompressedProblem>::HIT_MAX_ITERATIONS || !out.x.allFinite())
    return Status(StatusCode::kNotConverged,
                  "the fit did not converge in " + std::to_string(summary.iterations) + " iterations");

  // Covariance from the last J^T J; chi^2 is TinySolver's cost at the solution.
  out.chiSquare = 2.0 * summary.final_cost;
  if (auto s = fillCovariance(compressed.lastJtj, out, p); !s.isOk()) return s;
  return out;
}

}  // namespace fog::analysis
