#pragma once
// The two observed channels of one test point, prepared for fitting.
//
// Table: encoder angles y_i at stamps t_i, white (quantisation) noise.
// Gyro:  per-frame angle increments d_k = theta(t_k) - theta(s_k) over the
//        frame's own interval [s_k, t_k] (the exact difference model), never a
//        per-frame rate: a rate belongs to the middle of its frame and fitting
//        it would bias the delay by half a frame. Increment noise is angle
//        random walk (white, variance q*(t_k - s_k)) plus differenced pulse
//        quantisation (variance 2*s2, covariance -s2 between neighbours that
//        share an end point): a tridiagonal covariance, whitened exactly in
//        O(N) by its bidiagonal Cholesky factor.
//
// Times are relative to referenceS (the middle of the record) so that phase
// and frequency are nearly uncorrelated in the fits.

#include <cstddef>
#include <vector>

#include "core/analysis/sin_cos_series.h"
#include "core/common/recording.h"
#include "core/common/status.h"

namespace fog::analysis {

struct TableChannel {
  std::vector<double> timeS;  // relative to referenceS
  std::vector<double> angleDeg;
  double noiseDeg = 1.0;       // white noise sigma, from a fit's residuals
};

struct GyroChannel {
  std::vector<double> startS;  // interval start s_k, relative to referenceS
  std::vector<double> endS;    // interval end t_k (the frame's stamp)
  std::vector<double> incrementDeg;
  // false where the interval does not share its start with the previous
  // interval's end (a frame was lost in between)
  std::vector<bool> continuesPrevious;
  std::size_t lostFrames = 0;
  double framePeriodS = 0.0;   // median stamp interval

  // Noise model of the increments (see above) and its Cholesky factor.
  double arwVarianceDeg2PerS = 0.0;  // q
  // Standard error of q as estimated (estimateGyroNoise): large when pulse
  // quantisation dominates the block sums of a short record.
  double arwVarianceStdDeg2PerS = 0.0;
  double quantisationVarianceDeg2 = 0.0;  // s2
  std::vector<double> cholDiag, cholSub;

  std::size_t size() const { return incrementDeg.size(); }
  // Sets the noise model and factorises the covariance.
  void setNoise(double qDeg2PerS, double s2Deg2);
  // In-place z = L^-1 x for a vector laid out like incrementDeg.
  void whiten(double* x) const;
  // The same for each column of a row-major matrix with one row per increment.
  void whitenRows(double* x, std::size_t columns) const;
};

// sin/cos of w*(t - shift) at each increment's end (s1, c1) and start
// (s0, c0), walking the channel in order; a start that continues the previous
// interval reuses its end.
class GyroSinCosStream {
 public:
  GyroSinCosStream(const GyroChannel& gyro, double w, double shift) : g_(gyro), w_(w), shift_(shift), ends_(w, shift) {}
  void next(std::size_t k, double& s1, double& c1, double& s0, double& c0) {
    if (g_.continuesPrevious[k]) {
      s0 = lastS_;
      c0 = lastC_;
    } else {
      s0 = std::sin(w_ * (g_.startS[k] - shift_));
      c0 = std::cos(w_ * (g_.startS[k] - shift_));
    }
    ends_.next(g_.endS[k], s1, c1);
    lastS_ = s1;
    lastC_ = c1;
  }

 private:
  const GyroChannel& g_;
  double w_, shift_;
  SinCosStream ends_;
  double lastS_ = 0.0, lastC_ = 1.0;
};

struct Channels {
  TableChannel table;
  GyroChannel gyro;
  double referenceS = 0.0;   // absolute time (s) of the zero of the channel times
  double startS = 0.0, endS = 0.0;  // record span, absolute
  int axis = 0;
};

// Builds the channels for the test point's swing axis. Fails with a reason
// when the data cannot support a delay (too few samples, no gyro scale).
// incrementScale multiplies the recorded increments (in degrees): the
// stated gyro sign of the axis (+1, or -1 for one mounted the other way
// round: TestPointResult::gyroSign).
Result<Channels> makeChannels(const TestPointData& data, double incrementScale);

// What every noise estimate below starts from, taken from residuals of
// increments in two passes, so that estimates over several block lengths
// share them: s2 (pulse quantisation, from the lag-1 autocovariance) and the
// residuals' prefix sums (prefix[k] = sum of the first k).
struct IncrementResidualSums {
  double quantisationVarianceDeg2 = 0.0;
  std::vector<double> prefix;
};
IncrementResidualSums incrementResidualSums(const GyroChannel& gyro, const std::vector<double>& residualDeg);

// q from the variance of sums of increments over blockS seconds (one pass),
// with its standard error: what estimateGyroNoise applies.
struct BlockRateVariance {
  double varianceDeg2PerS = 0.0, stdDeg2PerS = 0.0;
};
BlockRateVariance blockRateVariance(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS);

// What measureGyroNoise (delay_analysis.cpp) takes from one set of sums, in
// one pass over them: estimateWhiteRateVariance and blockRateVariance at
// blockS, and blockRateVariance at weightBlockS (what estimateGyroNoise
// applies), each the same number, to the bit, as from its own pass.
struct GyroNoiseViews {
  double whiteRateVarianceDeg2PerS = 0.0;
  BlockRateVariance swingBlocks, weightBlocks;
};
GyroNoiseViews gyroNoiseViews(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS,
                              double weightBlockS);

// Estimates q and s2 from residuals of increments and applies them to the
// channel: s2 from the lag-1 autocovariance, q from the variance of sums of
// increments over blockS seconds.
void estimateGyroNoise(GyroChannel& gyro, const std::vector<double>& residualDeg, double blockS);
void estimateGyroNoise(GyroChannel& gyro, const IncrementResidualSums& sums, double blockS);

// The white rate noise alone (angle random walk, deg^2/s) from the same
// residuals: the variance of the difference of two adjacent sums over blockS
// (the overlapping Allan variance's second difference) is 2 q blockS + 6 s2,
// and a slowly varying bias (a bias wander over an hour, a trend the fit
// left) cancels in it, where the sums alone take it for a random walk.
double estimateWhiteRateVariance(const GyroChannel& gyro, const std::vector<double>& residualDeg, double blockS);
double estimateWhiteRateVariance(const GyroChannel& gyro, const IncrementResidualSums& sums, double blockS);


// Cumulative gyro angle at each interval end (starting from 0 before the
// first interval); lost frames' increments are missing.
std::vector<double> cumulativeGyroAngle(const GyroChannel& gyro);

}  // namespace fog::analysis
