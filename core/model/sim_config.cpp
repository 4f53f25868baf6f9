#include "core/model/sim_config.h"

#include <cmath>

#include "core/common/units.h"

namespace fog::model {

double FogParams::eigenPeriodS() const { return fibreLengthM * groupIndex / kSpeedOfLightMPerS; }
double FogParams::loopDelayS() const { return loopDelayEigenPeriods * eigenPeriodS(); }

double FogParams::filterDelayS() const {
  double d = 0.0;
  if (registerPeriodS > 0.0) d += registerPeriodS / 2.0;
  if (boxcarS > 0.0) d += boxcarS / 2.0;
  if (rateFilterTimeConstantS > 0.0) d += rateFilterTimeConstantS;
  if (rateFilterNaturalHz > 0.0) d += 2.0 * rateFilterDamping / (kTwoPi * rateFilterNaturalHz);
  return d;
}

double EncoderParams::eccentricityPeakDeg() const {
  return eccentricityUm > 0.0 ? eccentricityUm * 1e-6 / (eccentricityRadiusMm * 1e-3) * kDegPerRad : 0.0;
}

std::array<double, 3> EarthParams::rateLocalDegPerH() const {
  const double lat = latitudeDeg * kRadPerDeg;
  return {kEarthRateDegPerH * std::cos(lat), 0.0, -kEarthRateDegPerH * std::sin(lat)};
}

double EarthParams::projectionDegPerH(Axis axis) const {
  const auto n = rateLocalDegPerH();
  const double h = headingDeg * kRadPerDeg;
  const double up = zUp ? -1.0 : 1.0;  // R_x(180) negates y and z
  switch (axis) {
    case Axis::kX: return n[0] * std::cos(h);
    case Axis::kY: return -up * n[0] * std::sin(h);
    case Axis::kZ: return up * n[2];
  }
  return 0.0;
}

void applyImuFrame(const ImuFrame& frame, EarthParams& earth) {
  if (!frame.stated()) return;
  earth.zUp = frame.zUp();
  if (const auto h = frame.xHeadingDeg()) {
    double r = std::remainder(*h, 360.0);  // [-180, 180]
    if (r == -180.0) r = 180.0;
    earth.headingDeg = r;
  }
}

namespace {
bool positive(double v) { return std::isfinite(v) && v > 0.0; }
bool nonNegative(double v) { return std::isfinite(v) && v >= 0.0; }
}  // namespace

Status SimConfig::validate() const {
  // Physical ranges: beyond them a value is a unit error, and near a
  // double's range the simulated stream or the fits overflow (docs/simulator.md).
  // The periods' lower bound, 0.1 us, is far below any bench's: a replay
  // calibrated from crafted stamps that fast is left to the diagnosis'
  // memory budget, which says what it would cost.
  if (!(encoder.samplePeriodS >= 1e-7 && encoder.samplePeriodS <= 1.0))
    return invalidArgument("encoder sample period must be within 0.0001 .. 1000 ms");
  if (!nonNegative(encoder.readDelayS) || encoder.readDelayS >= encoder.samplePeriodS)
    return invalidArgument("encoder read delay must be in [0, sample period)");
  // Up to 90 deg: a replay calibrated on a swing the sine model misfits
  // takes the misfit as encoder noise (0.9 deg on a decaying pendulum).
  if (!(encoder.quantumDeg >= 0.0 && encoder.quantumDeg <= 90.0))
    return invalidArgument("encoder quantum must be within 0 .. 90 deg");
  if (!positive(fog.fibreLengthM) || !positive(fog.groupIndex))
    return invalidArgument("fibre length and group index must be > 0");
  if (!nonNegative(fog.loopDelayEigenPeriods)) return invalidArgument("loop delay must be >= 0");
  if (!positive(fog.pulseUpdatePeriodS)) return invalidArgument("pulse update period must be > 0 s");
  if (!nonNegative(fog.sampleAfterUpdateS) || fog.sampleAfterUpdateS >= fog.pulseUpdatePeriodS)
    return invalidArgument("time from pulse update to board sampling must be in [0, pulse update period); "
                       "the requested gyro delay is not reachable with this loop delay");
  // The register and the filters: up to 1 s (a filter far beyond any
  // gyro's is a unit error), offsets within the period.
  if (!(fog.registerPeriodS >= 0.0 && fog.registerPeriodS <= 1.0))
    return invalidArgument("pulse register period must be within 0 (off) .. 1000 ms");
  if (!(fog.registerOffsetS >= 0.0 && (fog.registerOffsetS < fog.registerPeriodS || fog.registerOffsetS == 0.0)))
    return invalidArgument("pulse register offset must be in [0, register period)");
  if (!(fog.boxcarS >= 0.0 && fog.boxcarS <= 1.0))
    return invalidArgument("boxcar length must be within 0 (off) .. 1000 ms");
  if (!(fog.rateFilterTimeConstantS >= 0.0 && fog.rateFilterTimeConstantS <= 1.0))
    return invalidArgument("rate filter time constant must be within 0 (off) .. 1000 ms");
  if (!(fog.rateFilterNaturalHz >= 0.0 && fog.rateFilterNaturalHz <= 1e6))
    return invalidArgument("rate filter natural frequency must be within 0 (off) .. 1 MHz");
  if (!(fog.rateFilterDamping > 0.0 && fog.rateFilterDamping <= 100.0))
    return invalidArgument("rate filter damping must be within (0, 100]");
  if (!(fog.pulseEquivalentDeg >= 1e-9 && fog.pulseEquivalentDeg <= 1.0))
    return invalidArgument("pulse equivalent must be within 1e-9 .. 1 deg");
  for (double b : fog.biasDegPerH)
    if (!std::isfinite(b) || std::abs(b) > 3600.0) return invalidArgument("gyro bias must be finite and under 3600 deg/h");
  if (!(fog.arwDegPerSqrtH >= 0.0 && fog.arwDegPerSqrtH <= 100.0))
    return invalidArgument("angle random walk must be within 0 .. 100 deg/sqrt(h)");
  if (!(fog.biasInstabilityDegPerH >= 0.0 && fog.biasInstabilityDegPerH <= 3600.0))
    return invalidArgument("bias instability must be within 0 .. 3600 deg/h");
  if (!(fog.biasCorrelationS > 0.0 && fog.biasCorrelationS <= 1e6))
    return invalidArgument("bias correlation time must be within 0 .. 1e6 s");
  if (!std::isfinite(earth.latitudeDeg) || std::abs(earth.latitudeDeg) > 90.0)
    return invalidArgument("latitude must be within [-90, 90] deg");
  if (!std::isfinite(earth.headingDeg) || std::abs(earth.headingDeg) > 360.0)
    return invalidArgument("heading must be within [-360, 360] deg");
  {
    const auto& o = turntable.axisOrder;
    if (o[0] == o[1] || o[1] == o[2] || o[0] == o[2])
      return invalidArgument("the table's axis order must name x, y and z once each (outer to inner)");
  }
  if (!std::isfinite(turntable.baseTiltDeg) || std::abs(turntable.baseTiltDeg) > 90.0)
    return invalidArgument("base tilt must be within [-90, 90] deg");
  if (!std::isfinite(turntable.baseTiltAzimuthDeg) || std::abs(turntable.baseTiltAzimuthDeg) > 360.0)
    return invalidArgument("base tilt azimuth must be within [-360, 360] deg");
  // 1 deg of non-orthogonality is far beyond any table's (arcsec).
  for (double n : turntable.nonOrthogonalityArcsec)
    if (!std::isfinite(n) || std::abs(n) > 3600.0)
      return invalidArgument("axis non-orthogonality must be within +-3600 arcsec");
  if (!(encoder.eccentricityUm >= 0.0 && encoder.eccentricityUm <= 1e4))
    return invalidArgument("encoder eccentricity must be within 0 .. 10000 um");
  if (!(encoder.eccentricityRadiusMm >= 1.0 && encoder.eccentricityRadiusMm <= 1e4))
    return invalidArgument("encoder read-head radius must be within 1 .. 10000 mm");
  if (encoder.eccentricityUm * 1e-3 >= 0.1 * encoder.eccentricityRadiusMm)
    return invalidArgument("encoder eccentricity must be under a tenth of the read-head radius");
  if (!std::isfinite(encoder.eccentricityPhaseDeg) || std::abs(encoder.eccentricityPhaseDeg) > 360.0)
    return invalidArgument("encoder eccentricity phase must be within [-360, 360] deg");
  if (!(encoder.lostPerMille >= 0.0 && encoder.lostPerMille < 1000.0))
    return invalidArgument("lost table frames must be within 0 .. 1000 per mille (not all)");
  for (double m : turntable.mountingDeg)
    if (!std::isfinite(m) || std::abs(m) > 360.0)
      return invalidArgument("IMU mounting angles must be within [-360, 360] deg");
  if (!(imuBoard.framePeriodS >= 1e-7 && imuBoard.framePeriodS <= 1.0))
    return invalidArgument("IMU frame period must be within 0.0001 .. 1000 ms");
  if (!nonNegative(imuBoard.firstSampleS)) return invalidArgument("IMU first sample time must be >= 0 s");
  if (!nonNegative(imuBoard.processingS) || !positive(imuBoard.baud) || imuBoard.frameBytes <= 0 ||
      !positive(imuBoard.bitsPerByte))
    return invalidArgument("IMU board processing time, frame size and baud rate must be positive");
  if (imuBoard.boardDelayS() >= imuBoard.framePeriodS)
    return invalidArgument("IMU board delay must be shorter than the frame period");
  if (!std::isfinite(imuBoard.clockErrorPpm) || std::abs(imuBoard.clockErrorPpm) > 1000.0)
    return invalidArgument("IMU clock error must be within +-1000 ppm");
  if (!std::isfinite(turntable.frequencyErrorPpm) || std::abs(turntable.frequencyErrorPpm) > 1000.0)
    return invalidArgument("turntable frequency error must be within +-1000 ppm");
  if (!(samplingBoard.counterHz >= 1e3 && samplingBoard.counterHz <= 4e9))
    return invalidArgument("counter frequency must be within 1 kHz .. 4 GHz");
  if (samplingBoard.counterBits < 16 || samplingBoard.counterBits > 32)
    return invalidArgument("counter width must be 16..32 bits");
  const double wrapS = std::ldexp(1.0, samplingBoard.counterBits) / samplingBoard.counterHz;
  if (wrapS < 0.01)
    return invalidArgument("the counter wraps every " + std::to_string(wrapS) +
                           " s, faster than frames arrive; use a wider counter or a lower frequency");
  if (!positive(samplingBoard.statusPeriodS)) return invalidArgument("status period must be > 0 s");
  return Status::ok();
}

}  // namespace fog::model
