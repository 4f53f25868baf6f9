#pragma once
// A small wrapper over Ceres for the bench's dense fits: a handful of
// parameters in one block, hundreds of thousands of residuals in a few
// residual blocks. Returns the solution, its covariance and a summary; never
// throws. Residuals must already be weighted (unit variance under the noise
// model); the covariance is scaled by chi^2/(N - p) so that it stays honest
// when the noise level was misjudged.

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "common/status.h"

namespace ceres {
class CostFunction;
}

namespace fog::analysis {

struct LeastSquaresSolution {
  Eigen::VectorXd x;
  Eigen::MatrixXd covariance;
  double chiSquare = 0.0;  // sum of squared weighted residuals at x
  std::size_t residuals = 0;
  int iterations = 0;
};

// Every cost function takes the single parameter block (size x0.size()).
Result<LeastSquaresSolution> solveLeastSquares(std::vector<std::unique_ptr<ceres::CostFunction>> costs,
                                               const Eigen::VectorXd& x0);

}  // namespace fog::analysis
