#pragma once
// Parameters of every stage of the simulated measurement chain, with the
// paper's values as defaults (docs/simulator.md). Units are in the names.
//
// Chain: turntable motion -> encoder read (table frames, 1 ms) and
//        FOG sensing -> pulse output -> IMU processing board (IMU frames, 2 ms)
//        -> sampling board, which stamps both with one common counter.

#include <array>
#include <cstdint>
#include <string>

#include "core/common/imu_frame.h"
#include "core/common/test_plan.h"

namespace fog::model {

struct TurntableParams {
  // Rate error of the table's own time base against true time. The paper's
  // fitted table period, 10000.0837 ms for a nominal 10 s, is -8.37 ppm.
  double frequencyErrorPpm = -8.37;
  TurntableLimits limits;
  // The table's axes from the outer frame to the inner one (model/attitude.h):
  // a precision three-axis table has the azimuth (z) outside, then y, then x.
  std::array<Axis, kAxisCount> axisOrder{Axis::kZ, Axis::kY, Axis::kX};
  // The IMU on the inner frame: roll (x), pitch (y), yaw (z), deg, applied
  // as R_z(yaw) R_y(pitch) R_x(roll). Zero: gyro x senses table axis x.
  std::array<double, kAxisCount> mountingDeg{};
  // The table's base is not level: its vertical is tilted by baseTiltDeg
  // (deg, right-handed) about the horizontal axis at azimuth
  // baseTiltAzimuthDeg (deg from north toward east), so the Earth rate and
  // gravity reach the table turned by that rotation (model/attitude.h).
  // 0 = a level base.
  double baseTiltDeg = 0.0;
  double baseTiltAzimuthDeg = 0.0;
  // Axis non-orthogonality, arcsec: the middle axis leans this far toward
  // the outer one ([0]) and the inner axis toward the middle one ([1]), so
  // the angle between them is 90 deg minus it. 0 = square axes.
  std::array<double, 2> nonOrthogonalityArcsec{};
};

struct EncoderParams {
  double samplePeriodS = 1e-3;  // the board reads the table angle every 1 ms
  double readDelayS = 0.05e-3;  // angle latched this long before the board stamps it
  double quantumDeg = 1e-4;     // 0.36 arcsec encoder resolution
  // Eccentricity of every axis' grating against its axis: a once-per-
  // revolution reading error (e / r) sin(theta + phase), rad, with e the
  // eccentricity in um and r the read head's radius in mm. 0 um = none.
  double eccentricityUm = 0.0;
  double eccentricityRadiusMm = 100.0;
  double eccentricityPhaseDeg = 0.0;
  // Table readings lost on the way to the board, per mille (each frame
  // independently; its sequence number is still used). 0 = none.
  double lostPerMille = 0.0;
  // Peak reading error of the eccentricity, deg.
  double eccentricityPeakDeg() const;
};

struct FogParams {
  double fibreLengthM = 1000.0;
  double groupIndex = 1.0;  // the paper's eigen period is L/c (3.4 us for 1000 m)
  double loopDelayEigenPeriods = 2.0;  // closed-loop delay: at most two eigen periods
  double pulseUpdatePeriodS = 0.5e-3;  // pulse output register updated every 0.5 ms
  // Time from the last pulse-register update to the IMU board's sampling of
  // it; with the FOG and board clocks locked this is constant in [0, update period).
  // Default: gyro's own delay = 0.2358 ms, the paper's X-axis result.
  double sampleAfterUpdateS = 0.2358e-3 - 2.0 * 1000.0 / 299792458.0;
  // The pulse register modelled explicitly (0 = off: the time from the last
  // update to the board's sampling is the constant sampleAfterUpdateS,
  // FOG and board clocks locked). registerPeriodS > 0, s: the register is
  // updated at instants registerOffsetS + j registerPeriodS of true time
  // (the FOG's own clock; offset in [0, period)), latching the angle sensed
  // up to that instant; what the board would read without the register
  // (ownDelayS() before its sample) is the value of the last update at or
  // before it, held until the next. This adds the hold: on average P / 2
  // when the update grid and the IMU frames are not locked.
  double registerPeriodS = 0.0;
  double registerOffsetS = 0.0;
  // Averaging (boxcar) filter of the rate over boxcarS, s, before it is
  // integrated into the frame (0 = off): delay T / 2, gain sinc(pi f T).
  double boxcarS = 0.0;
  // First-order low-pass of the rate, time constant in s (0 = off):
  // phase atan(omega T), delay T at low frequency.
  double rateFilterTimeConstantS = 0.0;
  // Second-order (resonant) low-pass of the rate: natural frequency in Hz
  // (0 = off) and damping ratio; phase atan2(2 zeta w / wn, 1 - (w / wn)^2),
  // delay 2 zeta / wn at low frequency.
  double rateFilterNaturalHz = 0.0;
  double rateFilterDamping = 0.7;
  double pulseEquivalentDeg = 5e-5;  // 0.18 arcsec per pulse
  std::array<double, kAxisCount> biasDegPerH{0.3, -0.2, 0.15};
  double arwDegPerSqrtH = 0.004;  // angle random walk
  // Bias instability as a first-order Gauss-Markov rate: 1-sigma value (the
  // paper's 0.5 deg/h stability) and correlation time.
  double biasInstabilityDegPerH = 0.5;
  double biasCorrelationS = 300.0;
  double temperatureC = 25.0;

  double eigenPeriodS() const;
  double loopDelayS() const;
  // Delay of the gyro's pulse output relative to the motion: loop delay plus
  // the time since the last pulse update.
  double ownDelayS() const { return loopDelayS() + sampleAfterUpdateS; }
  // Sets sampleAfterUpdateS so that ownDelayS() == delayS.
  void setOwnDelayS(double delayS) { sampleAfterUpdateS = delayS - loopDelayS(); }
  // Low-frequency delay the explicit register (mean hold, P / 2), the boxcar
  // (T / 2) and the rate filters (T; 2 zeta / omega_n) add to ownDelayS();
  // 0 with all of them off.
  double filterDelayS() const;
};

// The site and the table's heading (model/attitude.h): the table's axes at
// zero are the local north-east-down frame turned by headingDeg about down
// (heading 0: x north, y east, z down; 90: x east, y south), and with zUp
// then turned half a turn about x (heading 0: x north, y west, z up; 90: x
// east, y north, z up, east-north-up).
struct EarthParams {
  double latitudeDeg = 40.0;
  double headingDeg = 0.0;  // azimuth of the table's x axis at zero, from north toward east
  bool zUp = false;         // the table's z axis points up at zero angles
  // Earth rate in the local north-east-down frame, deg/h:
  // Omega * (cos(lat), 0, -sin(lat)).
  std::array<double, 3> rateLocalDegPerH() const;
  // Earth rate sensed by a gyro with the table at zero and the IMU mounted
  // square on it, deg/h (Omega cos(lat) cos(heading) on x,
  // -Omega cos(lat) sin(heading) on y, -Omega sin(lat) on z; with zUp the
  // y and z values change sign). The simulator
  // rotates the Earth rate into the body frame at every sample instead.
  double projectionDegPerH(Axis axis) const;
};

// The site's frame as the bench constants state it (core/common/imu_frame.h):
// where z points and, when the frame names it, the heading of x (within
// (-180, 180]); an unstated frame, or an unstated heading, leaves `earth`'s.
void applyImuFrame(const ImuFrame& frame, EarthParams& earth);

struct ImuBoardParams {
  double framePeriodS = 2e-3;  // nominal; the IMU's crystal makes it framePeriodS / (1 + clockErrorPpm)
  double firstSampleS = 0.3e-3;  // IMU clock phase against the sampling board
  // The IMU crystal's frequency error: > 0 runs fast (shorter frames), the
  // sign of a frequency offset and of the reference generator
  // (tests/independent/refgen.py, imu_clock_ppm).
  double clockErrorPpm = 0.0;
  double actualFramePeriodS() const { return framePeriodS / (1.0 + clockErrorPpm * 1e-6); }
  // Processing (pulse sampling, temperature compensation) and the serial
  // frame. The paper measured 0.28 ms on the board and budgets the 31-byte
  // frame at 1 Mbaud as ~0.25 ms (8 bits per byte); the rest is processing.
  double processingS = 0.032e-3;
  int frameBytes = 31;
  double bitsPerByte = 8.0;
  double baud = 1e6;
  double serialS() const { return frameBytes * bitsPerByte / baud; }
  double boardDelayS() const { return processingS + serialS(); }
};

struct SamplingBoardParams {
  double counterHz = 10e6;
  int counterBits = 32;
  std::uint32_t counterStart = 0;  // raw counter value at t = 0 (set near 2^bits to test wrap)
  double statusPeriodS = 0.1;
  // false: a board that does not know the plan: its STATUS frames never name
  // a test point or phase (always idle, test point 0xFFFF); the host segments
  // the stream itself (the table emulator's board, docs/table-control.md).
  bool markTestPoints = true;
};

struct SimConfig {
  TurntableParams turntable;
  EncoderParams encoder;
  FogParams fog;
  EarthParams earth;
  ImuBoardParams imuBoard;
  SamplingBoardParams samplingBoard;
  std::uint64_t seed = 1;

  // An error saying what is impossible in the configuration, or ok.
  Status validate() const;

  // The delays this configuration builds in, for the tests and for the
  // report's theory column. Lag is what the bench measures: the gyro's
  // output against the stamped table angle.
  // With the register or a filter on, the gyro's delay is its low-frequency
  // value (FogParams::filterDelayS()).
  double trueGyroDelayS() const {
    const double filters = fog.filterDelayS();
    return filters == 0.0 ? fog.ownDelayS() : fog.ownDelayS() + filters;
  }
  double trueImuDelayS() const { return trueGyroDelayS() + imuBoard.boardDelayS(); }
  double trueLagS() const { return trueImuDelayS() - encoder.readDelayS; }
};

}  // namespace fog::model
