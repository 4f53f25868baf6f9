#include "ui/plot_data/test_point_traces.h"

#include <cmath>

#include "core/analysis/channels.h"

namespace fog::ui {

namespace {

constexpr double kArcsecPerDeg = 3600.0;

// The periodic part of a fit, a*sin(w*tau) + b*cos(w*tau), tau relative to
// the fit's reference time.
double sinusoidDeg(const analysis::SineFit& f, double tS) {
  const double phase = f.omegaRadPerS * (tS - f.referenceS);
  return f.a * std::sin(phase) + f.b * std::cos(phase);
}

double amplitudeOf(const analysis::SineFit& f) {
  const double a = std::hypot(f.a, f.b);
  return a > 0.0 ? a : 1.0;
}

}  // namespace

double risingZeroCrossingS(const analysis::SineFit& f, double nearS) {
  constexpr double kTwoPi = 6.283185307179586;
  if (!(f.omegaRadPerS > 0.0)) return std::nan("");
  const double phi = std::atan2(f.b, f.a);
  const double k = std::round((f.omegaRadPerS * (nearS - f.referenceS) + phi) / kTwoPi);
  return f.referenceS + (kTwoPi * k - phi) / f.omegaRadPerS;
}

double TestPointTraces::tableFitNormalised(double tS) const {
  return sinusoidDeg(tableFit, tS) / amplitudeOf(tableFit);
}

double TestPointTraces::gyroFitNormalised(double tS) const {
  return sinusoidDeg(gyroFit, tS) / amplitudeOf(gyroFit);
}

Result<TestPointTraces> makeTestPointTraces(const TestPointData& data, const analysis::TestPointResult& result) {
  FOG_ASSIGN_OR_RETURN(auto channels, analysis::makeChannels(data, result.gyroSign));
  const analysis::Channels& ch = channels;

  TestPointTraces t;
  t.index = result.index;
  t.tableFit = result.tableFit;
  t.gyroFit = result.gyroFit;

  const double tableAmp = amplitudeOf(t.tableFit);
  const std::size_t nt = ch.table.timeS.size();
  for (Trace* tr : {&t.tableNormalised, &t.tableResidualArcsec}) {
    tr->x.resize(nt);
    tr->y.resize(nt);
  }
  for (std::size_t i = 0; i < nt; ++i) {
    const double time = ch.table.timeS[i] + ch.referenceS;
    const double centred = ch.table.angleDeg[i] - t.tableFit.offsetDeg;
    t.tableNormalised.x[i] = t.tableResidualArcsec.x[i] = time;
    t.tableNormalised.y[i] = centred / tableAmp;
    t.tableResidualArcsec.y[i] = (centred - sinusoidDeg(t.tableFit, time)) * kArcsecPerDeg;
  }

  // The analysis's gyro offset belongs to this cumulative angle (it starts
  // from 0 before the first interval), so the same sum is used here.
  const std::vector<double> angle = analysis::cumulativeGyroAngle(ch.gyro);
  const double gyroAmp = amplitudeOf(t.gyroFit);
  const std::size_t ng = angle.size();
  for (Trace* tr : {&t.gyroNormalised, &t.gyroResidualArcsec}) {
    tr->x.resize(ng);
    tr->y.resize(ng);
  }
  for (std::size_t k = 0; k < ng; ++k) {
    const double tau = ch.gyro.endS[k];
    const double time = tau + ch.referenceS;
    const double centred = angle[k] - t.gyroFit.trendDegPerS * tau - t.gyroFit.offsetDeg;
    t.gyroNormalised.x[k] = t.gyroResidualArcsec.x[k] = time;
    t.gyroNormalised.y[k] = centred / gyroAmp;
    t.gyroResidualArcsec.y[k] = (centred - sinusoidDeg(t.gyroFit, time)) * kArcsecPerDeg;
  }
  return t;
}

}  // namespace fog::ui
