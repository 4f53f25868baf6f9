#pragma once
// Gyro noise characterisation from the static segments of a recording
// (docs/noise.md): mean bias and its Earth-rate-corrected value, the
// overlapping Allan deviation with chi-squared confidence intervals, the
// IEEE Std 952 noise terms, what they mean for a planned swing test (the
// Cramer-Rao prediction of analysis/theory.h), and simulator parameters that
// reproduce them.
//
// Units in this header: rates in deg/h, Allan deviations in deg/h, tau in s;
// the NoiseModel inside the report keeps fog::noise's units (deg, deg/s).
// Pure functions, thread-safe, no exceptions.

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/theory.h"
#include "core/common/recording.h"
#include "core/common/status.h"
#include "core/model/sim_config.h"
#include "core/noise/noise_terms.h"

namespace fog::noise {

struct GyroNoiseOptions {
  std::optional<Axis> gyroAxis;  // default: each static segment's own axis
  AllanOptions allan;
  IdentifyOptions identify;
  model::EarthParams earth;      // site latitude and IMU axes, for the Earth-rate correction
  // Model the quantisation as the pulse count of the angle (exact at rest,
  // where the angle moves a pulse only every few frames) when every increment
  // is a whole number of pulses; false: white quantisation (IEEE 952).
  bool pulseQuantisation = true;
};

struct GyroNoiseReport {
  int testPointIndex = 0;
  Axis gyroAxis = Axis::kX;
  double durationS = 0.0;
  double intervalS = 0.0;  // mean IMU frame interval (tau0)
  std::size_t samples = 0, lostFrames = 0;
  double biasDegPerH = 0.0, biasStdDegPerH = 0.0;  // mean rate; std from the noise model at tau = duration
  double earthRateDegPerH = 0.0;                   // Earth-rate projection on this gyro
  double earthCorrectedBiasDegPerH = 0.0;
  AllanCurve curve;    // deviations in deg/s
  NoiseModel model;    // terms in deg, deg/s units (noise_terms.h)
  std::vector<std::string> warnings;
};

// One static segment. Fails with kInsufficientData under 8 IMU samples.
// degPerPulse: the gyro's pulse equivalent (0: unknown; white quantisation).
Result<GyroNoiseReport> analyzeStaticSegment(const TestPointData& data, const GyroNoiseOptions& options,
                                             double degPerPulse = 0.0);
// Every static segment of the recording. kInsufficientData ("the recording
// has no static segment ...") when there is none.
Result<std::vector<GyroNoiseReport>> analyzeGyroNoise(const Recording& recording, const GyroNoiseOptions& options);

// A term converted to the gyro's customary units, for reports.
struct TermInUnits {
  double value = 0.0, stdError = 0.0;
  const char* unit = "";  // "arcsec", "deg/sqrt(h)", "deg/h", "deg/h/sqrt(h)", "deg/h^2", "deg/h"
};
TermInUnits termInGyroUnits(const NoiseTerm& term);
// The same term in SI units, as other tools (kalibr, OpenVINS, ROS) take
// them, angles in radians: quantisation rad; angle random walk rad/s/sqrt(Hz)
// (= rad/sqrt(s), the white rate's one-sided density); bias instability and
// the Markov sigma rad/s; rate random walk rad/s^2/sqrt(Hz); rate ramp rad/s^2.
TermInUnits termInSiUnits(const NoiseTerm& term);

// The IMU noise file kalibr and OpenVINS read (imu.yaml; kalibr's
// "IMU Noise Model" wiki): gyroscope_noise_density = the angle random walk N
// in rad/s/sqrt(Hz), gyroscope_random_walk = the rate random walk K in
// rad/s^2/sqrt(Hz), update_rate = 1 / the IMU's frame interval in Hz. A term
// the record did not identify, and the accelerometer's keys (a gyro bench
// measures no accelerometer), are written as .nan with a comment saying so:
// a value that was not measured is never made up. `source` (the session's
// path) is named in the header comment with the conversion used.
std::string formatKalibrYaml(const GyroNoiseReport& report, const std::string& source);

// Simulator parameters that make a simulated session sound like this one:
// angle random walk N, the Markov term (or, for a flicker bias instability B,
// the Gauss-Markov process whose Allan hump peaks at B's plateau 0.664 B in
// the middle of B's tau range), the Earth-corrected bias on the analysed
// axis. Terms the simulator has no process for (rate random walk, rate ramp,
// white angle noise beyond the pulse quantisation) are listed in `notes`.
struct SimulatorFeed {
  model::SimConfig config;
  std::vector<std::string> notes;
};
SimulatorFeed simulatorFeed(const GyroNoiseReport& report, const model::SimConfig& base);

// The bench's Cramer-Rao prediction (analysis::predictedLagStdS) for a planned
// swing test with this gyro: its angle random walk and, when identified, its
// quantisation (as a pulse equivalent Q sqrt 12); the rest of `planned` as given.
struct SwingPrediction {
  analysis::PlannedTest test;
  double lagStdS = 0.0;
};
SwingPrediction predictSwing(const GyroNoiseReport& report, analysis::PlannedTest planned);

// The report as text and as JSON (stable keys, docs/noise.md).
std::string formatNoiseText(const std::vector<GyroNoiseReport>& reports, const std::vector<SwingPrediction>& predictions);
std::string formatNoiseJson(const std::vector<GyroNoiseReport>& reports, const std::vector<SwingPrediction>& predictions);

}  // namespace fog::noise
