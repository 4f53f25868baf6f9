#pragma once
// The bench's dense nonlinear least-squares fits: a handful of parameters and
// hundreds of thousands of residuals.
//
// A problem never materialises its N x p Jacobian: one streaming pass
// accumulates the normal equations J^T J, J^T r and r^T r. Ceres' TinySolver
// (Levenberg-Marquardt on the normal equations, Jacobi-scaled) then runs on
// an equivalent (p+1)-residual problem with the same J^T J, J^T r and cost:
// from the Cholesky factor J^T J = L L^T, J' = [L^T; 0], r' = [z; rho] with
// L z = J^T r and rho^2 = r^T r - z^T z. Its iterates are those of the full
// problem, at a fraction of the memory traffic.
//
// Residuals must already be weighted (unit variance under the noise model);
// the covariance, inv(J^T J) at the solution, is scaled by chi^2/(N - p) so it
// stays honest when the noise level was misjudged. Never throws.

#include <Eigen/Dense>

#include "core/common/status.h"

namespace fog::analysis {

class LeastSquaresProblem {
 public:
  virtual ~LeastSquaresProblem() = default;
  virtual std::size_t numResiduals() const = 0;
  virtual int numParameters() const = 0;
  // Returns r^T r at x. When jtj and jtr are given (sized p x p and p, zeroed),
  // adds J^T J (lower triangle is enough) and J^T r, J = d r / d x.
  virtual double accumulate(const double* x, Eigen::MatrixXd* jtj, Eigen::VectorXd* jtr) const = 0;
};

// Running sums of J^T J (lower triangle) and J^T r over rows with P
// parameters, kept in fixed-size storage for speed; added into a problem's
// (larger) normal equations at parameter offset `first` when done.
template <int P>
struct NormalSums {
  double jtj[P][P] = {};
  double jtr[P] = {};
  void add(const double* row, double r) {
    for (int i = 0; i < P; ++i) {
      jtr[i] += row[i] * r;
      for (int j = 0; j <= i; ++j) jtj[i][j] += row[i] * row[j];
    }
  }
  void addTo(Eigen::MatrixXd& jtjOut, Eigen::VectorXd& jtrOut, int first = 0) const {
    for (int i = 0; i < P; ++i) {
      jtrOut[first + i] += jtr[i];
      for (int j = 0; j <= i; ++j) jtjOut(first + i, first + j) += jtj[i][j];
    }
  }
};

struct LeastSquaresSolution {
  Eigen::VectorXd x;
  Eigen::MatrixXd covariance;
  double chiSquare = 0.0;  // sum of squared weighted residuals at x
  std::size_t residuals = 0;
  int iterations = 0;
};

Result<LeastSquaresSolution> solveLeastSquares(const LeastSquaresProblem& problem, const Eigen::VectorXd& x0);

}  // namespace fog::analysis
