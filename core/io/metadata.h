#pragma once
// metadata.json of the CSV layout (docs/formats.md): one schema, used by both
// the exporter and the importer so that they cannot drift apart. Internal to
// fog::io.

#include <array>
#include <string>
#include <vector>

#include "core/common/recording.h"
#include "core/common/session_info.h"
#include "core/common/status.h"

namespace fog::io::detail {

inline constexpr const char* kFormatName = "fogbench-csv";
inline constexpr int kFormatVersion = 1;

// One entry of "test_points"; entry i describes test point i + 1.
struct MetaTestPoint {
  Axis axis = Axis::kX;
  double frequencyHz = 0.0;  // 0: unknown
  double amplitudeDeg = 0.0; // 0: unknown
  bool hasPlan = false;      // duration_s given (then settle_s, start_phase_deg too, default 0)
  double durationS = 0.0, settleS = 0.0, startPhaseDeg = 0.0;
  TestPointKind kind = TestPointKind::kSwing;  // "kind": "static" is written only for static segments
};

// The IMU's frame period (bench.gyro_frame_period_ms) as a physical bound:
// beyond it a value is a unit or typing error.
inline constexpr double kMinFramePeriodMs = 1e-3;    // an IMU frame at 1 MHz
inline constexpr double kMaxFramePeriodMs = 1000.0;  // ... at 1 Hz

// How a gyro stream of rates (x_rate_deg_s ...) was sampled
// (docs/formats.md, "Rates"); the importer converts them to increments.
enum class RateConvention {
  kNone,           // the gyro file holds increments
  kFrameAverage,   // rate = the frame's increment / the IMU's frame period
  kSampleAtStamp,  // rate = the instantaneous rate at the row's time stamp
};

// A convention's name as the metadata writes it ("frame_average",
// "sample_at_stamp"; "" for kNone), and back: kNone for any other name.
const char* rateConventionName(RateConvention convention);
RateConvention rateConventionFromName(const std::string& name);

struct Metadata {
  SessionInfo info;  // plan left empty; built by the importer from testPoints
  std::vector<MetaTestPoint> testPoints;
  // Import-time facts about the gyro stream, applied where the data enter.
  RateConvention rateConvention = RateConvention::kNone;
  double gyroFramePeriodMs = 0.0;  // the IMU's own frame period; 0 = not stated
  bool hasStream = false;
  StreamHealth stream;
};

// Serialises; pulseEquivalentDeg/counter values and the gyro signs are taken
// from info.bench.
std::string metadataToJson(const Metadata& meta);
// Parses and checks every key; errors are kCorruptData naming `path` and
// the offending key.
Result<Metadata> metadataFromJson(const std::string& path, const std::string& text);

}  // namespace fog::io::detail
