#pragma once
// Residual features of one recording, the coordinates of the gap map
// (docs/diagnosis.md): per test point and per time segment, per channel
// (table, gyro, gyro-minus-table, timing), per harmonic 0..5 of the swing
// frequency and per axis. Real and simulated recordings go through the same
// function with the same FeatureReference, so their features line up index by
// index and can be compared as z-scores.
//
// Each segment is fitted by linear least squares at the reference frequency:
//   table(t) = sum_{h=1..5} (a_h sin h w t + b_h cos h w t) + c + d t
//   gyro increments d_k = Phi(t_k) - Phi(s_k), Phi the same harmonic series
//   plus a trend (the exact difference model of core/analysis), for the
//   swing axis and the two other axes.
// Harmonics are reported relative to the channel's fundamental, in phase and
// in quadrature with it (ppm), so they do not depend on the swing's start phase.
// Qt-free; pure functions, thread-safe.

#include <memory>
#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/common/status.h"

namespace fog::diagnosis {

enum class Channel { kTable = 0, kGyro = 1, kGyroMinusTable = 2, kTiming = 3 };
inline constexpr int kChannelCount = 4;
const char* channelName(Channel c);  // "table", "gyro", "gyro-table", "timing"

// What a feature measures. Harmonic features carry their harmonic in
// FeatureKey::harmonic.
enum class Quantity {
  kInPhase,             // harmonic h in phase with the channel's fundamental
  kQuadrature,          // harmonic h in quadrature with it
  kResidualMeanSquare,  // mean square of the segment's fit residual
  kGain,                // gyro/table amplitude - 1
  kDelay,               // gyro behind table at the fundamental
  kTrend,               // gyro rate trend (bias)
  kCrossInPhase,        // another gyro's response to the swing, in phase
  kCrossQuadrature,     // the same, in quadrature
  kTableInterval,       // mean table sample interval against nominal
  kTableIntervalVariance,
  kImuInterval,         // mean IMU frame interval against nominal
  kImuIntervalVariance,
  kImuLost,             // IMU frames lost
  kTableLost,           // table samples missing (stamp gaps of whole periods)
};
enum class Unit { kPpm, kMicroseconds, kDegPerHour, kMicroDegSquared, kMicrosecondsSquared, kFrames };

struct FeatureKey {
  Channel channel = Channel::kTable;
  Quantity quantity = Quantity::kInPhase;
  Unit unit = Unit::kPpm;
  int harmonic = -1;     // 0..5 where the feature belongs to one harmonic, else -1
  int axis = -1;         // gyro axis (0..2) the feature is measured on, -1 for table/timing
  int point = 0;         // test point position in the recording
  int segment = 0;       // time segment within the test point
};

// The names the JSON output and the reports use: "h3_in_phase", "delay",
// "residual_ms", "imu_lost", "table_lost", ...; "ppm", "us", "deg/h", "udeg^2", "us^2", "frames".
std::string quantityName(const FeatureKey& key);
const char* unitName(Unit unit);
// The same quantity in words for people ("harmonic 2, quadrature",
// "IMU stamp-interval variance"): what the text report and the GUI show;
// the name above stays the key of the JSON (and the GUI's tooltip).
std::string quantityTitle(const FeatureKey& key);

struct PointReference {
  double omegaRadPerS = 0.0;  // reference swing frequency (the real session's table fit)
  int segments = 4;
  int swingAxis = 0;
};

struct FeatureReference {
  std::vector<PointReference> points;
  double tablePeriodS = 1e-3;  // nominal intervals the timing features are stated against
  double imuPeriodS = 2e-3;
};

// Whole-record view of one test point, for plotting.
struct PointSpectrum {
  // Amplitude of harmonic h (0..5) relative to the fundamental, ppm; h = 0 is
  // the gyro trend in deg/h (table: 0), h = 1 is 1e6.
  std::vector<double> tableHarmonicPpm, gyroHarmonicPpm;
  double delayUs = 0.0;           // gyro behind table, from the fundamentals
  double gainPpm = 0.0;           // gyro/table amplitude - 1
  std::vector<double> residualTimeS;   // decimated, relative to the record middle
  std::vector<double> gyroResidualDeg; // cumulative gyro-angle residual of the whole-record fit
};

struct FeatureSet {
  std::vector<FeatureKey> keys;
  std::vector<double> values;
  // White-noise standard error of the table's part of each value from its
  // own least-squares fit (0 where there is none, and for the gyro's part:
  // its white-noise error overstates the spread of differenced pulse
  // quantisation several times over, and the replays show the gyro's spread).
  std::vector<double> formalStd;
  std::vector<PointSpectrum> spectra;  // one per test point
};

// Segments per test point: 4, fewer when the point has under 8 periods
// (at least 2 periods per segment), at least 1.
int segmentsFor(double durationS, double frequencyHz);

// Whether extractFeatures() fills PointSpectrum's cumulative gyro residual
// (residualTimeS, gyroResidualDeg): a whole pass over the IMU samples with a
// harmonic basis per sample, drawn for the session and its first replay
// only. kSkip leaves them empty; every other feature and spectrum value is
// the same either way.
enum class ResidualView { kCompute, kSkip };

// The sums one recording's features were taken from that depend on its
// stamps and table readings alone: per test point, the table fit's sums and
// interval statistics, the gyro fit's normal matrix and the IMU frame
// interval, with the samples they came from. A recording whose table samples
// (stamps and swing-axis angles) or IMU stamps (and lost-frame counts) are
// those same ones takes them instead of summing again, with the same values
// to the bit: the replays at one seed whose effects act on the gyro alone
// differ from the first only in their gyro increments.
class FeatureSums {
 public:
  FeatureSums();
  ~FeatureSums();
  struct Point;
  std::vector<Point> points;
};

// Fails when a test point has too little data or the reference does not
// match the recording's test points. Walks each test point's table samples
// once and its IMU samples twice (the frame interval's median, the fit),
// three times with the residual view (core/diagnosis/replay_passes.h); a
// test point whose table samples or IMU stamps are those of `reuse` is
// compared with them in that pass instead of summed (or its median taken).
// `record`, when given, receives the sums of this recording.
Result<FeatureSet> extractFeatures(const Recording& recording, const FeatureReference& reference,
                                   ResidualView residual = ResidualView::kCompute, FeatureSums* record = nullptr,
                                   const FeatureSums* reuse = nullptr);

// Timing audit of one stream (docs/diagnosis.md).
struct StreamTiming {
  std::size_t samples = 0;
  double intervalMeanPpm = 0.0;   // mean interval against nominal, ppm
  double intervalStdUs = 0.0;     // spread of the intervals (gaps excluded)
  std::size_t gaps = 0;           // intervals over 1.5 nominal
  std::size_t duplicates = 0;     // intervals <= 0
};
struct TimingAudit {
  StreamTiming table, imu;
  std::uint64_t lostFrames = 0, duplicateFrames = 0, counterWraps = 0, checksumFailures = 0, outOfOrderFrames = 0;
};
// One pass over the table stamps and one over the IMU stamps; reads only the
// samples' times and the recording's health, not their values.
TimingAudit auditTiming(const Recording& recording, double tablePeriodS, double imuPeriodS);

}  // namespace fog::diagnosis
