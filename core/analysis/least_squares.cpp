#include "analysis/least_squares.h"

#include <ceres/ceres.h>

#include <cmath>

namespace fog::analysis {

Result<LeastSquaresSolution> solveLeastSquares(std::vector<std::unique_ptr<ceres::CostFunction>> costs,
                                               const Eigen::VectorXd& x0) {
  const int p = static_cast<int>(x0.size());
  LeastSquaresSolution out;
  out.x = x0;

  ceres::Problem::Options problemOptions;
  problemOptions.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problemOptions);
  for (auto& c : costs) {
    problem.AddResidualBlock(c.get(), nullptr, out.x.data());
    out.residuals += static_cast<std::size_t>(c->num_residuals());
  }
  if (out.residuals <= static_cast<std::size_t>(p))
    return insufficientData("not enough samples to fit " + std::to_string(p) + " parameters");

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 50;
  // Tight: the delay is a small difference of two phases.
  options.function_tolerance = 1e-13;
  options.parameter_tolerance = 1e-13;
  options.gradient_tolerance = 1e-16;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  out.iterations = static_cast<int>(summary.iterations.size());
  if (!summary.IsSolutionUsable() || summary.termination_type == ceres::NO_CONVERGENCE)
    return Status(StatusCode::kNotConverged, "the fit did not converge: " + summary.message);

  // Covariance from J^T J at the solution, accumulated per residual block.
  Eigen::MatrixXd jtj = Eigen::MatrixXd::Zero(p, p);
  double chi2 = 0.0;
  const double* params[] = {out.x.data()};
  std::vector<double> r, j;
  for (auto& c : costs) {
    const auto n = static_cast<std::size_t>(c->num_residuals());
    r.resize(n);
    j.resize(n * static_cast<std::size_t>(p));
    double* jac[] = {j.data()};
    if (!c->Evaluate(params, r.data(), jac)) return Status(StatusCode::kInternal, "cost evaluation failed");
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
        j.data(), static_cast<Eigen::Index>(n), p);
    jtj.noalias() += J.transpose() * J;
    for (double v : r) chi2 += v * v;
  }
  out.chiSquare = chi2;
  const double scale = chi2 / static_cast<double>(out.residuals - static_cast<std::size_t>(p));
  Eigen::LDLT<Eigen::MatrixXd> ldlt(jtj);
  if (ldlt.info() != Eigen::Success || ldlt.rcond() < 1e-300)
    return Status(StatusCode::kNotConverged, "the fit's parameters are not determined by the data");
  out.covariance = ldlt.solve(Eigen::MatrixXd::Identity(p, p)) * scale;
  for (int i = 0; i < p; ++i)
    if (!(out.covariance(i, i) >= 0.0) || !std::isfinite(out.covariance(i, i)))
      return Status(StatusCode::kNotConverged, "the fit's covariance is not positive");
  return out;
}

}  // namespace fog::analysis
