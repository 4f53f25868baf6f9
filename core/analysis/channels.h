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

#include "common/recording.h"
#include "common/status.h"

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
  double quantisationVarianceDeg2 = 0.0;  // s2
  std::vector<double> cholDiag, cholSub;

  std::size_t size() const { return incrementDeg.size(); }
  // Sets the noise model and factorises the covariance.
  void setNoise(double qDeg2PerS, double s2Deg2);
  // In-place z = L^-1 x for a vector laid out like incrementDeg; element k
  // at x[k * stride].
  void whiten(double* x, std::size_t stride = 1) const;
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
// incrementScale multiplies the recorded increments (1 when they are already
// in degrees; the pulse equivalent when the stream carried raw pulses).
Result<Channels> makeChannels(const TestPointData& data, double incrementScale);

// Estimates q and s2 from residuals of increments and applies them to the
// channel: s2 from the lag-1 autocovariance, q from the variance of sums of
// increments over blockS seconds.
void estimateGyroNoise(GyroChannel& gyro, const std::vector<double>& residualDeg, double blockS);

// Cumulative gyro angle at each interval end (starting from 0 before the
// first interval); lost frames' increments are missing.
std::vector<double> cumulativeGyroAngle(const GyroChannel& gyro);

}  // namespace fog::analysis
