#pragma once
// metadata.json of the CSV layout (docs/formats.md): one schema, used by both
// the exporter and the importer so that they cannot drift apart. Internal to
// fog::io.

#include <string>
#include <vector>

#include "common/recording.h"
#include "common/session_info.h"
#include "common/status.h"

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

struct Metadata {
  SessionInfo info;  // plan left empty; built by the importer from testPoints
  std::vector<MetaTestPoint> testPoints;
  bool hasStream = false;
  StreamHealth stream;
};

// Serialises; pulseEquivalentDeg/counter values are taken from info.bench.
std::string metadataToJson(const Metadata& meta);
// Parses and checks every key; errors are kCorruptData naming `path` and
// the offending key.
Result<Metadata> metadataFromJson(const std::string& path, const std::string& text);

}  // namespace fog::io::detail
