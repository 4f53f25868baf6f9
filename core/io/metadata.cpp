#include "core/io/metadata.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <utility>
#include <vector>

#include "core/common/test_plan.h"

namespace fog::io::detail {

namespace {

using Json = nlohmann::ordered_json;

// Physical bounds of the metadata's numbers (docs/formats.md): beyond them a
// value is a unit or typing error, and near a double's range it overflows.
// (The bench constants' ranges: checkBenchConstants, core/common/bench_constants.h.)
constexpr double kMaxSwingFrequencyHz = 1000.0;
constexpr double kMaxSwingAmplitudeDeg = 3600.0;   // ten turns each way

}  // namespace

const char* rateConventionName(RateConvention convention) {
  switch (convention) {
    case RateConvention::kFrameAverage: return "frame_average";
    case RateConvention::kSampleAtStamp: return "sample_at_stamp";
    case RateConvention::kNone: break;
  }
  return "";
}

RateConvention rateConventionFromName(const std::string& name) {
  for (auto c : {RateConvention::kFrameAverage, RateConvention::kSampleAtStamp})
    if (name == rateConventionName(c)) return c;
  return RateConvention::kNone;
}

namespace {

// Reads one JSON object's keys, refusing unknown ones so that a typo is not
// silently replaced by a default.
class Reader {
 public:
  Reader(const std::string& path, const Json& object, std::string where)
      : path_(path), j_(object), where_(std::move(where)) {}

  Status checkKeys(const std::set<std::string>& known) const {
    for (const auto& item : j_.items())
      if (!known.count(item.key())) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        return corruptData(path_ + ": unknown key \"" + name(item.key()) + "\"; known keys here: " + list +
                           " (docs/formats.md)");
      }
    return Status::ok();
  }

  bool has(const char* key) const { return j_.contains(key) && !j_.at(key).is_null(); }

  Status string(const char* key, std::string& out) const {
    if (!has(key)) return Status::ok();
    if (!j_.at(key).is_string()) return corruptData(path_ + ": \"" + name(key) + "\" must be a string");
    out = j_.at(key).get<std::string>();
    return Status::ok();
  }

  // A finite number within [min, max]; required when `required` (otherwise
  // `out` keeps its default). The bounds are physical: near a double's range a
  // constant overflows the sums it enters (a frame period of 1e300 ms crashed
  // the fit; 1e-300 gave "± -nan ms").
  Status number(const char* key, double& out, bool required, double min = -HUGE_VAL, double max = HUGE_VAL) const {
    if (!has(key)) {
      if (required)
        return corruptData(path_ + ": missing \"" + name(key) + "\"; it is required (docs/formats.md)");
      return Status::ok();
    }
    const Json& v = j_.at(key);
    if (!v.is_number()) return corruptData(path_ + ": \"" + name(key) + "\" must be a number, not " + v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < min || d > max)
      return corruptData(path_ + ": \"" + name(key) + "\" = " + v.dump() + " is out of range" + bounds(min, max));
    out = d;
    return Status::ok();
  }

  Status integer(const char* key, std::uint64_t& out) const {
    if (!has(key)) return Status::ok();
    const Json& v = j_.at(key);
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<std::int64_t>() >= 0))
      return corruptData(path_ + ": \"" + name(key) + "\" must be a non-negative integer, not " + v.dump());
    out = v.get<std::uint64_t>();
    return Status::ok();
  }

  static std::string bounds(double min, double max) {
    if (min > -HUGE_VAL && max < HUGE_VAL) return " (must be within " + Json(min).dump() + " .. " + Json(max).dump() + ")";
    if (min > -HUGE_VAL) return " (must be >= " + Json(min).dump() + ")";
    if (max < HUGE_VAL) return " (must be <= " + Json(max).dump() + ")";
    return "";
  }

  std::string name(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }

 private:
  const std::string& path_;
  const Json& j_;
  std::string where_;
};

}  // namespace

std::string metadataToJson(const Metadata& meta) {
  const SessionInfo& s = meta.info;
  const BenchConstants& b = s.bench;
  Json j;
  j["format"] = kFormatName;
  j["format_version"] = kFormatVersion;
  j["operator"] = s.operatorName;
  j["imu_model"] = s.imuModel;
  j["imu_serial"] = s.imuSerial;
  j["lot"] = s.lot;
  j["bench_id"] = s.benchId;
  j["source"] = s.source;
  j["software_version"] = s.softwareVersion;
  j["created_utc"] = s.createdUtc;
  j["notes"] = s.notes;
  j["bench"] = {{"table_read_delay_ms", b.tableReadDelayMs}, {"table_read_delay_std_ms", b.tableReadDelayStdMs},
                {"board_delay_ms", b.boardDelayMs},          {"board_delay_std_ms", b.boardDelayStdMs},
                {"latitude_deg", b.latitudeDeg},             {"pulse_equivalent_deg", b.pulseEquivalentDeg},
                {"counter_hz", b.counterHz},                 {"counter_bits", b.counterBits},
                {"gain_tolerance", b.gainToleranceFraction}};
  // Only the axes mounted the other way round: a file without the key reads +1.
  Json signs = Json::object();
  for (int a = 0; a < kAxisCount; ++a)
    if (b.gyroSign[static_cast<std::size_t>(a)] < 0) signs[axisName(static_cast<Axis>(a))] = -1;
  if (!signs.empty()) j["bench"]["gyro_sign"] = std::move(signs);
  if (b.imuFrame.stated()) j["bench"]["imu_frame"] = imuFrameToText(b.imuFrame);
  j["rest_between_s"] = s.plan.restBetweenS;
  Json points = Json::array();
  for (const auto& p : meta.testPoints) {
    Json e = {{"axis", axisName(p.axis)}, {"frequency_hz", p.frequencyHz}, {"amplitude_deg", p.amplitudeDeg}};
    if (p.kind == TestPointKind::kStatic) e["kind"] = "static";
    if (p.hasPlan) {
      e["duration_s"] = p.durationS;
      e["settle_s"] = p.settleS;
      e["start_phase_deg"] = p.startPhaseDeg;
    }
    points.push_back(std::move(e));
  }
  j["test_points"] = std::move(points);
  if (meta.hasStream) {
    const StreamHealth& h = meta.stream;
    j["stream"] = {{"table_frames", h.tableFrames},         {"imu_frames", h.imuFrames},
                   {"status_frames", h.statusFrames},       {"checksum_failures", h.checksumFailures},
                   {"bytes_skipped", h.bytesSkipped},       {"lost_frames", h.lostFrames},
                   {"duplicate_frames", h.duplicateFrames}, {"out_of_order_frames", h.outOfOrderFrames},
                   {"counter_wraps", h.counterWraps}};
  }
  return j.dump(2) + "\n";
}

// A first pass over the text with nlohmann's SAX interface, before any
// document is built: a key given twice in one object (which would silently
// keep the last value) and sizes no metadata has are refused here. Linear in
// the text: the parser callback this replaces made nlohmann 3.11's DOM
// parser scan every parent array at each object's end (quadratic: 100 000
// test points took 4 s to parse, 300 000 took 50 s), and an object's keys
// are looked up linearly in an ordered_json, so one with very many keys
// would be quadratic too.
class MetadataShape : public nlohmann::json_sax<Json> {
 public:
  static constexpr std::size_t kMaxKeys = 256;  // a metadata object has at most 13 known keys

  std::string problem;  // empty: fine
  std::string parseError;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    if (!value()) return false;
    stack_.push_back({false, 0, {}, pendingKey_});
    return true;
  }
  bool key(string_t& k) override {
    Level& l = stack_.back();
    if (!l.keys.insert(k).second) return fail("the key \"" + k + "\" appears twice in one object; keep one");
    if (l.keys.size() > kMaxKeys)
      return fail("an object with more than " + std::to_string(kMaxKeys) + " keys; metadata objects have a few "
                  "known keys each (docs/formats.md)");
    pendingKey_ = k;
    return true;
  }
  bool end_object() override {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    if (!value()) return false;
    stack_.push_back({true, 0, {}, pendingKey_});
    return true;
  }
  bool end_array() override {
    stack_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    parseError = e.what();
    return false;
  }

 private:
  struct Level {
    bool array = false;
    std::size_t elements = 0;
    std::set<std::string> keys;
    std::string name;  // the key this object or array is the value of
  };
  // Every value, an object's or array's start included, counts as an element
  // of the array it is in.
  bool value() {
    if (stack_.empty() || !stack_.back().array) return true;
    Level& l = stack_.back();
    if (++l.elements <= kMaxPlanPoints) return true;
    if (stack_.size() == 2 && l.name == "test_points")
      return fail("\"test_points\" lists more than " + std::to_string(kMaxPlanPoints) + " test points; at most " +
                  std::to_string(kMaxPlanPoints) + ", as in a plan: split the data into several imports");
    return fail("an array of more than " + std::to_string(kMaxPlanPoints) + " elements; no metadata has one");
  }
  bool fail(std::string why) {
    problem = std::move(why);
    return false;
  }
  std::vector<Level> stack_;
  std::string pendingKey_;
};

namespace {

// The "bench" object: the bench constants, the rate convention and the gyro signs.
Status readBench(const std::string& path, const Json& j, Metadata& meta) {
  // The delays and the pulse equivalent belong to the bench that recorded
  // the data: defaulting them to this bench's values would give a wrong
  // breakdown without a word, so they are required.
  if (!j.contains("bench") || !j.at("bench").is_object())
    return corruptData(path + ": missing \"bench\" object with table_read_delay_ms, board_delay_ms and "
                              "pulse_equivalent_deg (docs/formats.md)");
  const Reader bench(path, j.at("bench"), "bench");
  BenchConstants& b = meta.info.bench;
  FOG_RETURN_IF_ERROR(bench.checkKeys({"table_read_delay_ms", "table_read_delay_std_ms", "board_delay_ms",
                                       "board_delay_std_ms", "latitude_deg", "pulse_equivalent_deg", "counter_hz",
                                       "counter_bits", "gyro_rate_convention", "gyro_frame_period_ms",
                                       "gyro_sign", "imu_frame", "gain_tolerance"}));
  FOG_RETURN_IF_ERROR(bench.number("table_read_delay_ms", b.tableReadDelayMs, true));
  FOG_RETURN_IF_ERROR(bench.number("table_read_delay_std_ms", b.tableReadDelayStdMs, false));
  FOG_RETURN_IF_ERROR(bench.number("board_delay_ms", b.boardDelayMs, true));
  FOG_RETURN_IF_ERROR(bench.number("board_delay_std_ms", b.boardDelayStdMs, false));
  FOG_RETURN_IF_ERROR(bench.number("latitude_deg", b.latitudeDeg, false));
  FOG_RETURN_IF_ERROR(bench.number("pulse_equivalent_deg", b.pulseEquivalentDeg, true));
  FOG_RETURN_IF_ERROR(bench.number("counter_hz", b.counterHz, false));
  FOG_RETURN_IF_ERROR(bench.number("gain_tolerance", b.gainToleranceFraction, false));
  std::uint64_t bits = static_cast<std::uint64_t>(b.counterBits);
  FOG_RETURN_IF_ERROR(bench.integer("counter_bits", bits));
  // Held as an int: beyond 64 it is out of range whatever the cast would make of it.
  b.counterBits = bits > 64 ? 65 : static_cast<int>(bits);
  // The ranges the command line and the GUI's dialog check too
  // (checkBenchConstants): a delay of 1e308 ms is a typo or a unit error.
  if (const auto problems = benchConstantProblems(b); !problems.empty())
    return corruptData(path + ": \"bench." + benchConstantKey(problems.front().field) + "\": " +
                       (bits > 64 && problems.front().field == BenchConstantProblem::Field::kCounterBits
                            ? "the sampling board's counter width must be 1 .. 64 bits, not " + std::to_string(bits)
                            : problems.front().message) +
                       " (docs/formats.md)");
  // An import must state its pulse equivalent: 0 ("not set") is for a
  // stream that states its own.
  if (!(b.pulseEquivalentDeg > 0.0))
    return corruptData(path + ": \"bench.pulse_equivalent_deg\" must be > 0 (degrees per gyro pulse)");
  std::string convention;
  FOG_RETURN_IF_ERROR(bench.string("gyro_rate_convention", convention));
  meta.rateConvention = rateConventionFromName(convention);
  if (meta.rateConvention == RateConvention::kNone && !convention.empty())
    return corruptData(path + ": \"bench.gyro_rate_convention\" must be \"frame_average\" (each rate is its frame's "
                              "increment over the IMU's frame period) or \"sample_at_stamp\" (each rate is the "
                              "rate at its row's time stamp), not \"" + convention + "\"");
  FOG_RETURN_IF_ERROR(bench.number("gyro_frame_period_ms", meta.gyroFramePeriodMs, false, 0.0));
  if (bench.has("gyro_frame_period_ms") &&
      !(meta.gyroFramePeriodMs >= kMinFramePeriodMs && meta.gyroFramePeriodMs <= kMaxFramePeriodMs))
    return corruptData(path + ": \"bench.gyro_frame_period_ms\" = " + Json(meta.gyroFramePeriodMs).dump() +
                       " must be within 0.001 .. 1000 (the IMU's own frame period in milliseconds: 1 MHz to 1 Hz)");
  if (bench.has("gyro_sign")) {
    const Json& signs = j.at("bench").at("gyro_sign");
    if (!signs.is_object())
      return corruptData(path + ": \"bench.gyro_sign\" must be an object such as {\"x\": -1} (the sense of each "
                                "gyro axis against the table's)");
    for (const auto& item : signs.items()) {
      auto axis = parseAxis(item.key());
      const Json& v = item.value();
      if (!axis || !v.is_number_integer() || (v.get<std::int64_t>() != 1 && v.get<std::int64_t>() != -1))
        return corruptData(path + ": \"bench.gyro_sign\" takes the axes \"x\", \"y\", \"z\" with 1 or -1, not \"" +
                           item.key() + "\": " + v.dump());
      b.gyroSign[static_cast<std::size_t>(*axis)] = static_cast<int>(v.get<std::int64_t>());
    }
  }
  std::string frame;
  FOG_RETURN_IF_ERROR(bench.string("imu_frame", frame));
  auto parsed = imuFrameFromText(frame);
  if (!parsed) return corruptData(path + ": \"bench.imu_frame\": " + parsed.status().message());
  b.imuFrame = *parsed;

  return Status::ok();
}

// The "test_points" array: one entry per test point, as a plan's point.
Status readTestPoints(const std::string& path, const Json& j, Metadata& meta) {
  if (!j.contains("test_points") || !j.at("test_points").is_array() || j.at("test_points").empty())
    return corruptData(path + ": missing \"test_points\": a non-empty array with one {\"axis\": \"x\", ...} per "
                              "test point (docs/formats.md)");
  const Json& points = j.at("test_points");
  if (points.size() > kMaxPlanPoints)  // (the first pass refuses them already)
    return corruptData(path + ": \"test_points\" lists " + std::to_string(points.size()) + " test points; at most " +
                       std::to_string(kMaxPlanPoints));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string where = "test_points[" + std::to_string(i) + "]";
    if (!points[i].is_object()) return corruptData(path + ": \"" + where + "\" must be an object");
    const Reader r(path, points[i], where);
    FOG_RETURN_IF_ERROR(
        r.checkKeys({"axis", "frequency_hz", "amplitude_deg", "duration_s", "settle_s", "start_phase_deg", "kind"}));
    MetaTestPoint p;
    std::string kind = "swing";
    FOG_RETURN_IF_ERROR(r.string("kind", kind));
    if (kind != "swing" && kind != "static")
      return corruptData(path + ": \"" + where + ".kind\" must be \"swing\" or \"static\"");
    p.kind = kind == "static" ? TestPointKind::kStatic : TestPointKind::kSwing;
    std::string axis;
    FOG_RETURN_IF_ERROR(r.string("axis", axis));
    auto parsed = parseAxis(axis);
    if (!r.has("axis") || !parsed)
      return corruptData(path + ": \"" + where + ".axis\" must be \"x\", \"y\" or \"z\" (the swing axis)");
    p.axis = *parsed;
    FOG_RETURN_IF_ERROR(r.number("frequency_hz", p.frequencyHz, false, 0.0, kMaxSwingFrequencyHz));
    FOG_RETURN_IF_ERROR(r.number("amplitude_deg", p.amplitudeDeg, false, 0.0, kMaxSwingAmplitudeDeg));
    p.hasPlan = r.has("duration_s");
    FOG_RETURN_IF_ERROR(r.number("duration_s", p.durationS, false, 0.0, kMaxPlanDurationS));
    FOG_RETURN_IF_ERROR(r.number("settle_s", p.settleS, false, 0.0, kMaxPlanDurationS));
    FOG_RETURN_IF_ERROR(r.number("start_phase_deg", p.startPhaseDeg, false, -1e6, 1e6));
    meta.testPoints.push_back(p);
  }

  return Status::ok();
}

// The optional "stream" object: the decoder health of the original stream.
Status readStream(const std::string& path, const Json& j, Metadata& meta) {
  if (j.contains("stream")) {
    if (!j.at("stream").is_object()) return corruptData(path + ": \"stream\" must be an object");
    const Reader r(path, j.at("stream"), "stream");
    FOG_RETURN_IF_ERROR(r.checkKeys({"table_frames", "imu_frames", "status_frames", "checksum_failures",
                                     "bytes_skipped", "lost_frames", "duplicate_frames", "out_of_order_frames",
                                     "counter_wraps"}));
    StreamHealth& h = meta.stream;
    FOG_RETURN_IF_ERROR(r.integer("table_frames", h.tableFrames));
    FOG_RETURN_IF_ERROR(r.integer("imu_frames", h.imuFrames));
    FOG_RETURN_IF_ERROR(r.integer("status_frames", h.statusFrames));
    FOG_RETURN_IF_ERROR(r.integer("checksum_failures", h.checksumFailures));
    FOG_RETURN_IF_ERROR(r.integer("bytes_skipped", h.bytesSkipped));
    FOG_RETURN_IF_ERROR(r.integer("lost_frames", h.lostFrames));
    FOG_RETURN_IF_ERROR(r.integer("duplicate_frames", h.duplicateFrames));
    FOG_RETURN_IF_ERROR(r.integer("out_of_order_frames", h.outOfOrderFrames));
    FOG_RETURN_IF_ERROR(r.integer("counter_wraps", h.counterWraps));
    meta.hasStream = true;
  }
  return Status::ok();
}

}  // namespace

Result<Metadata> metadataFromJson(const std::string& path, const std::string& text) {
  Json j;
  MetadataShape shape;
  bool shapeOk = false;
  try {
    shapeOk = Json::sax_parse(text, &shape);
    if (shapeOk) j = Json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number beyond a double
    return corruptData(path + ": not valid JSON (" + e.what() + "); metadata must be one JSON object (docs/formats.md)");
  }
  if (!shape.problem.empty()) return corruptData(path + ": " + shape.problem);
  if (!shapeOk)
    return corruptData(path + ": not valid JSON (" + shape.parseError +
                       "); metadata must be one JSON object (docs/formats.md)");
  if (!j.is_object()) return corruptData(path + ": must hold one JSON object {...} (docs/formats.md)");

  Metadata meta;
  SessionInfo& s = meta.info;
  const Reader top(path, j, "");
  FOG_RETURN_IF_ERROR(top.checkKeys({"format", "format_version", "operator", "imu_model", "imu_serial", "lot",
                                     "bench_id", "source", "software_version", "created_utc", "notes", "bench", "rest_between_s",
                                     "test_points", "stream"}));
  std::string format;
  FOG_RETURN_IF_ERROR(top.string("format", format));
  if (top.has("format") && format != kFormatName)
    return corruptData(path + ": \"format\" is \"" + format + "\", expected \"" + kFormatName + "\"");
  if (top.has("format_version")) {
    const Json& v = j.at("format_version");
    if (!v.is_number_integer() || v.get<std::int64_t>() < 1 || v.get<std::int64_t>() > kFormatVersion)
      return corruptData(path + ": \"format_version\" " + v.dump() + " is not supported; this fogbench reads version " +
                         std::to_string(kFormatVersion));
  }
  FOG_RETURN_IF_ERROR(top.string("operator", s.operatorName));
  FOG_RETURN_IF_ERROR(top.string("imu_model", s.imuModel));
  FOG_RETURN_IF_ERROR(top.string("imu_serial", s.imuSerial));
  // Optional (format version 1 files before them read ""): what the catalog
  // groups results by.
  FOG_RETURN_IF_ERROR(top.string("lot", s.lot));
  FOG_RETURN_IF_ERROR(top.string("bench_id", s.benchId));
  FOG_RETURN_IF_ERROR(top.string("source", s.source));
  FOG_RETURN_IF_ERROR(top.string("software_version", s.softwareVersion));
  FOG_RETURN_IF_ERROR(top.string("created_utc", s.createdUtc));
  FOG_RETURN_IF_ERROR(top.string("notes", s.notes));
  FOG_RETURN_IF_ERROR(top.number("rest_between_s", s.plan.restBetweenS, false, 0.0, kMaxPlanDurationS));

  FOG_RETURN_IF_ERROR(readBench(path, j, meta));
  FOG_RETURN_IF_ERROR(readTestPoints(path, j, meta));
  FOG_RETURN_IF_ERROR(readStream(path, j, meta));
  return meta;
}

}  // namespace fog::io::detail
