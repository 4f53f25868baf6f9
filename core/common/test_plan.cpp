#include "core/common/test_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/file_read.h"
#include "core/common/units.h"

namespace fog {

const char* axisName(Axis axis) {
  switch (axis) {
    case Axis::kX: return "x";
    case Axis::kY: return "y";
    case Axis::kZ: return "z";
  }
  return "?";
}

const char* axisLabel(Axis axis) {
  switch (axis) {
    case Axis::kX: return "X";
    case Axis::kY: return "Y";
    case Axis::kZ: return "Z";
  }
  return "?";
}

Result<Axis> parseAxis(std::string_view text) {
  if (text == "x" || text == "X") return Axis::kX;
  if (text == "y" || text == "Y") return Axis::kY;
  if (text == "z" || text == "Z") return Axis::kZ;
  return invalidArgument("axis must be x, y or z, not '" + std::string(text) + "'");
}

const char* testPointKindName(TestPointKind kind) {
  return kind == TestPointKind::kStatic ? "static" : "swing";
}

TestPoint TestPoint::staticSegment(Axis axis, double durationS, double settleS) {
  TestPoint p;
  p.axis = axis;
  p.kind = TestPointKind::kStatic;
  p.frequencyHz = 0.0;
  p.amplitudeDeg = 0.0;
  p.durationS = durationS;
  p.settleS = settleS;
  return p;
}

namespace {
std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
}  // namespace

std::string tooFewSwingPeriods(double periods) {
  if (periods >= kMinSwingPeriods * (1.0 - 1e-9)) return {};
  // Rounded down: 1.998 periods read "1.99", never "2.00 ... under two".
  const double shown = std::isfinite(periods) ? std::floor(std::max(periods, 0.0) * 100.0) / 100.0 : 0.0;
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", shown);
  return "covers " + std::string(text) + " swing periods, under two swing periods: a delay needs at least two whole periods";
}

std::vector<TestPoint::Problem> TestPoint::problems(const TurntableLimits& limits) const {
  using Field = Problem::Field;
  std::vector<Problem> out;
  auto add = [&out](Field field, std::string message) { out.push_back({field, std::move(message)}); };
  for (int a = 0; a < kAxisCount; ++a)
    if (!std::isfinite(positionDeg[a]) || std::abs(positionDeg[a]) > kMaxPositionDeg)
      add(Field::kPosition, std::string("table position of axis ") + axisLabel(static_cast<Axis>(a)) +
                                " must be within +-" + num(kMaxPositionDeg) + " deg, got " + num(positionDeg[a]) +
                                " deg");
  const bool durationOk = std::isfinite(durationS);
  if (isStatic()) {
    if (frequencyHz != 0.0 || amplitudeDeg != 0.0 || startPhaseDeg != 0.0)
      add(Field::kKind, "a static segment has no frequency, amplitude or start phase (got " + num(frequencyHz) +
                            " Hz, " + num(amplitudeDeg) + " deg, " + num(startPhaseDeg) + " deg); leave them out");
    if (!durationOk || durationS <= 0.0)
      add(Field::kDuration, "a static segment needs a duration > 0 s, got " + num(durationS));
  } else {
    const bool frequencyOk = std::isfinite(frequencyHz) && frequencyHz > 0.0;
    const bool amplitudeOk = std::isfinite(amplitudeDeg) && amplitudeDeg > 0.0;
    if (!frequencyOk)
      add(Field::kFrequency, "frequency must be > 0 Hz, got " + num(frequencyHz));
    else if (frequencyHz > limits.maxFrequencyHz)
      add(Field::kFrequency, "frequency " + num(frequencyHz) + " Hz is beyond the table limit of " +
                                 num(limits.maxFrequencyHz) + " Hz");
    if (!amplitudeOk)
      add(Field::kAmplitude, "amplitude must be > 0 deg, got " + num(amplitudeDeg));
    else if (amplitudeDeg > limits.maxAmplitudeDeg)
      add(Field::kAmplitude, "amplitude " + num(amplitudeDeg) + " deg is beyond the table limit of " +
                                 num(limits.maxAmplitudeDeg) + " deg");
    if (frequencyOk && amplitudeOk) {
      const double w = kTwoPi * frequencyHz;
      const double peakRate = w * amplitudeDeg;
      if (peakRate > limits.maxRateDegPerS)
        add(Field::kFrequency, "peak rate " + num(peakRate) + " deg/s exceeds the table limit of " +
                                   num(limits.maxRateDegPerS) + " deg/s; lower the frequency or amplitude");
      const double peakAccel = w * w * amplitudeDeg;
      if (peakAccel > limits.maxAccelDegPerS2)
        add(Field::kFrequency, "peak acceleration " + num(peakAccel) + " deg/s^2 exceeds the table limit of " +
                                   num(limits.maxAccelDegPerS2) + " deg/s^2; lower the frequency or amplitude");
    }
    if (!durationOk)
      add(Field::kDuration, "duration must be a finite number of seconds, got " + num(durationS));
    else if (const std::string few = frequencyOk ? tooFewSwingPeriods(durationS * frequencyHz) : std::string();
             !few.empty())
      add(Field::kDuration, "duration " + num(durationS) + " s " + few + " (" +
                                num(kMinSwingPeriods * periodS()) + " s)");
  }
  if (durationOk && durationS > 24.0 * 3600.0)
    add(Field::kDuration, "duration " + num(durationS) + " s is over 24 h; split the test into points");
  if (!std::isfinite(settleS) || settleS < 0.0) add(Field::kSettle, "settle time must be >= 0 s, got " + num(settleS));
  if (!isStatic() && !std::isfinite(startPhaseDeg)) add(Field::kStartPhase, "start phase must be finite");
  return out;
}

Status TestPoint::validate(const TurntableLimits& limits) const {
  const auto found = problems(limits);
  return found.empty() ? Status::ok() : invalidArgument(found.front().message);
}

Status TestPlan::validate(const TurntableLimits& limits) const {
  if (points.empty()) return invalidArgument("the test plan has no test points");
  if (!std::isfinite(restBetweenS) || restBetweenS < 0.0)
    return invalidArgument("rest time between points must be >= 0 s");
  if (points.size() > kMaxPlanPoints)
    return invalidArgument("the test plan has " + std::to_string(points.size()) + " test points; at most " +
                           std::to_string(kMaxPlanPoints));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (Status s = points[i].validate(limits); !s.isOk())
      return invalidArgument("test point " + std::to_string(i + 1) + ": " + s.message());
  }
  // Moves between points: each axis that changes moves in its share of the
  // rest with a raised-cosine profile, peak rate pi/2 * d / T and peak
  // acceleration pi^2/2 * d / T^2.
  for (std::size_t i = 0; i <= points.size(); ++i) {
    const auto from = i == 0 ? std::array<double, kAxisCount>{} : endAnglesDeg(i - 1);
    const auto to = startAnglesDeg(i);
    int moving = 0;
    double largest = 0.0;
    for (int a = 0; a < kAxisCount; ++a)
      if (std::abs(to[a] - from[a]) > kMotionToleranceDeg) ++moving, largest = std::max(largest, std::abs(to[a] - from[a]));
    if (moving == 0) continue;
    const std::string where = i == points.size() ? std::string("the return to zero after the last point")
                                                 : "the move to test point " + std::to_string(i + 1);
    if (restBetweenS <= 0.0)
      return invalidArgument(where + " turns the table by " + num(largest) +
                             " deg with no rest time to move in; give rest_between_s > 0");
    const double t = restBetweenS / moving;
    const double rate = kPi / 2.0 * largest / t, accel = kPi * kPi / 2.0 * largest / (t * t);
    if (rate > limits.maxRateDegPerS || accel > limits.maxAccelDegPerS2) {
      const double need = moving * std::max(kPi / 2.0 * largest / limits.maxRateDegPerS,
                                            std::sqrt(kPi * kPi / 2.0 * largest / limits.maxAccelDegPerS2));
      return invalidArgument(where + " (" + num(largest) + " deg in " + num(t) + " s) exceeds the table's rate or " +
                             "acceleration limit; give rest_between_s >= " + num(std::ceil(need * 10.0) / 10.0) + " s");
    }
  }
  if (totalDurationS() > kMaxPlanDurationS)
    return invalidArgument("the test plan lasts " + num(totalDurationS() / 3600.0) + " h in all; at most " +
                           num(kMaxPlanDurationS / 3600.0) + " h (every sample is held in memory): split it into "
                           "several sessions");
  return Status::ok();
}

std::array<double, kAxisCount> TestPlan::startAnglesDeg(std::size_t index) const {
  if (index >= points.size()) return {};
  const TestPoint& p = points[index];
  auto angles = p.positionDeg;
  if (!p.isStatic()) angles[static_cast<int>(p.axis)] += p.amplitudeDeg * std::sin(p.startPhaseDeg * kRadPerDeg);
  return angles;
}

std::array<double, kAxisCount> TestPlan::endAnglesDeg(std::size_t index) const {
  const TestPoint& p = points[index];
  auto angles = p.positionDeg;
  if (!p.isStatic()) {
    const double t = p.settleS + p.durationS;
    angles[static_cast<int>(p.axis)] +=
        p.amplitudeDeg * std::sin(kTwoPi * p.frequencyHz * t + p.startPhaseDeg * kRadPerDeg);
  }
  return angles;
}

double TestPlan::totalDurationS() const {
  double total = 0.0;
  for (const auto& p : points) total += p.settleS + p.durationS + restBetweenS;
  return total;
}

TestPlan TestPlan::paperSlow() {
  TestPlan plan;
  plan.points.push_back({Axis::kX, 0.1, 10.0, 294.0, 5.0, 0.0});
  return plan;
}

TestPlan TestPlan::paperFast() {
  TestPlan plan;
  plan.points.push_back({Axis::kX, 1.0, 3.0, 60.0, 2.0, 0.0});
  return plan;
}

const std::vector<std::string>& presetPlanNames() {
  static const std::vector<std::string> names = {"paper", "paper-slow", "paper-fast", "quick", "noise",
                                                    "response", "response-third-octave"};
  return names;
}

Result<TestPlan> presetPlan(std::string_view name) {
  if (name == "paper-slow") return TestPlan::paperSlow();
  if (name == "paper-fast") return TestPlan::paperFast();
  if (name == "paper") {
    TestPlan plan = TestPlan::paperSlow();
    plan.points.push_back(TestPlan::paperFast().points.front());
    return plan;
  }
  if (name == "quick") {
    TestPlan plan = TestPlan::paperFast();
    plan.points.front().durationS = 20.0;
    return plan;
  }
  if (name == "noise") {
    // Gyro noise (docs/noise.md): 10 minutes at rest on X, then the paper's
    // fast swing so that the same run also gives a delay.
    TestPlan plan;
    plan.points.push_back(TestPoint::staticSegment(Axis::kX, 600.0));
    plan.points.push_back(TestPlan::paperFast().points.front());
    return plan;
  }
  if (isResponsePreset(name)) return responsePreset(name, Axis::kX);
  std::string known;
  for (const auto& n : presetPlanNames()) known += (known.empty() ? "" : ", ") + n;
  return invalidArgument("unknown preset '" + std::string(name) + "' (" + known + ")");
}

namespace {

Status checkResponseOptions(const ResponsePlanOptions& o) {
  if (!(o.lowestHz > 0.0) || o.frequencies < 2 || o.frequencies > 200 || !(o.minAmplitudeDeg > 0.0) ||
      !(o.maxAmplitudeDeg >= o.minAmplitudeDeg) || !(o.limitMargin > 0.0 && o.limitMargin <= 1.0) ||
      !(o.minPeriods >= 2.0) || !(o.minDurationS >= 0.0))
    return invalidArgument("response plan: needs a lowest frequency > 0, 2 .. 200 frequencies, amplitudes "
                           "0 < min <= max, a limit margin in (0, 1] and at least 2 periods per point");
  return Status::ok();
}

// The largest amplitude the margin allows at f: within limitMargin of the
// angle, rate and acceleration limits and at most maxAmplitudeDeg, rounded
// down to 0.001 deg.
double responseAmplitudeDeg(const TurntableLimits& limits, double maxAmplitudeDeg, double margin, double f) {
  const double w = kTwoPi * f;
  const double amplitude = std::min({maxAmplitudeDeg, margin * limits.maxAmplitudeDeg,
                                     margin * limits.maxRateDegPerS / w, margin * limits.maxAccelDegPerS2 / (w * w)});
  // A round figure, never above the margin by more than rounding.
  return std::floor(amplitude * 1000.0 + 1e-6) / 1000.0;
}

// One point of a response plan: whole periods, settle max(1 period, 1 s),
// record max(minPeriods, minDurationS).
TestPoint responsePoint(Axis axis, double f, double amplitudeDeg, const ResponsePlanOptions& o) {
  TestPoint p;
  p.axis = axis;
  p.frequencyHz = f;
  p.amplitudeDeg = amplitudeDeg;
  p.settleS = std::ceil(std::max(1.0, f) - 1e-9) / f;
  p.durationS = std::ceil(std::max(o.minPeriods, o.minDurationS * f) - 1e-9) / f;
  return p;
}

}  // namespace

Result<TestPlan> responsePlan(const TurntableLimits& limits, const ResponsePlanOptions& o) {
  FOG_RETURN_IF_ERROR(checkResponseOptions(o));
  const double rate = o.limitMargin * limits.maxRateDegPerS, accel = o.limitMargin * limits.maxAccelDegPerS2;
  // Highest frequency at which the margin still allows minAmplitudeDeg.
  const double highest = std::min({limits.maxFrequencyHz, rate / (kTwoPi * o.minAmplitudeDeg),
                                   std::sqrt(accel / o.minAmplitudeDeg) / kTwoPi});
  if (!(highest > o.lowestHz))
    return invalidArgument("response plan: the table's limits allow " + num(o.minAmplitudeDeg) + " deg only up to " +
                           num(highest) + " Hz, not above the lowest frequency " + num(o.lowestHz) + " Hz");
  TestPlan plan;
  for (int i = 0; i < o.frequencies; ++i) {
    const double f = o.lowestHz * std::pow(highest / o.lowestHz, static_cast<double>(i) / (o.frequencies - 1));
    plan.points.push_back(
        responsePoint(o.axis, f, responseAmplitudeDeg(limits, o.maxAmplitudeDeg, o.limitMargin, f), o));
  }
  if (Status s = plan.validate(limits); !s.isOk()) return invalidArgument("response plan: " + s.message());
  return plan;
}

const std::vector<double>& thirdOctaveNominalHz() {
  // ISO 266's R10 preferred numbers over two decades: IEC 61260-1's nominal
  // mid-band frequencies of the base-10 one-third-octave bands k = -10 .. 10
  // (exact: 10^(k/10) Hz).
  static const std::vector<double> grid = {0.1, 0.125, 0.16, 0.2, 0.25, 0.315, 0.4, 0.5, 0.63, 0.8, 1.0,
                                           1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0, 10.0};
  return grid;
}

Result<TestPlan> thirdOctaveResponsePlan(const TurntableLimits& limits, const ResponsePlanOptions& o) {
  FOG_RETURN_IF_ERROR(checkResponseOptions(o));
  TestPlan plan;
  for (const double f : thirdOctaveNominalHz()) {
    const std::string where = "one-third-octave response plan: at " + num(f) + " Hz ";
    if (f > limits.maxFrequencyHz)
      return invalidArgument(where + "the table's frequency limit (" + num(limits.maxFrequencyHz) +
                             " Hz) is exceeded; the standard grid reaches 10 Hz and no frequency of it is dropped");
    // The whole table: the angle limit within the margin, not the 10-deg cap.
    const double amplitude = responseAmplitudeDeg(limits, limits.maxAmplitudeDeg, o.limitMargin, f);
    if (!(amplitude >= o.minAmplitudeDeg))
      return invalidArgument(where + "the table's limits within " + num(o.limitMargin * 100.0) +
                             " % allow " + num(amplitude) + " deg, under the " + num(o.minAmplitudeDeg) +
                             " deg a point needs; the standard grid reaches 10 Hz and no frequency of it is dropped");
    plan.points.push_back(responsePoint(o.axis, f, amplitude, o));
  }
  if (Status s = plan.validate(limits); !s.isOk())
    return invalidArgument("one-third-octave response plan: " + s.message());
  return plan;
}

bool isResponsePreset(std::string_view name) { return name == "response" || name == "response-third-octave"; }

Result<TestPlan> responsePreset(std::string_view name, Axis axis) {
  ResponsePlanOptions options;
  options.axis = axis;
  if (name == "response") return responsePlan(TurntableLimits{}, options);
  if (name == "response-third-octave") return thirdOctaveResponsePlan(TurntableLimits{}, options);
  return invalidArgument("'" + std::string(name) + "' is not a frequency-response preset (response, "
                         "response-third-octave)");
}

Result<TestPlan> loadTestPlanFile(const std::string& path) {
  FOG_ASSIGN_OR_RETURN(auto text, readRegularTextFile(path, 16u << 20, "a plan file"));
  auto plan = testPlanFromJson(text);
  if (!plan) return Status(plan.status().code(), path + ": " + plan.status().message());
  return plan;
}

Result<TestPlan> testPlanFromJson(std::string_view text) {
  using nlohmann::json;
  json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return invalidArgument("the test plan is not valid JSON");
  if (!doc.is_object() || !doc.contains("points") || !doc["points"].is_array())
    return invalidArgument("the test plan needs a \"points\" array");
  TestPlan plan;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (it.key() == "points") continue;
    if (it.key() == "rest_between_s" && it->is_number() && std::isfinite(it->get<double>())) {
      plan.restBetweenS = it->get<double>();
      continue;
    }
    return invalidArgument("unknown or non-numeric key \"" + it.key() + "\" in the test plan");
  }
  if (doc["points"].size() > kMaxPlanPoints)
    return invalidArgument("the test plan has " + std::to_string(doc["points"].size()) + " points; at most " +
                           std::to_string(kMaxPlanPoints));
  int index = 0;
  for (const auto& p : doc["points"]) {
    ++index;
    const std::string where = "test point " + std::to_string(index) + ": ";
    if (!p.is_object()) return invalidArgument(where + "must be an object");
    TestPoint point;
    double periods = 0.0;
    bool gaveFrequency = false, gaveAmplitude = false;
    for (auto it = p.begin(); it != p.end(); ++it) {
      const std::string& key = it.key();
      if (key == "kind") {
        const std::string kind = it->is_string() ? it->get<std::string>() : "";
        if (kind == "static") point.kind = TestPointKind::kStatic;
        else if (kind == "swing") point.kind = TestPointKind::kSwing;
        else return invalidArgument(where + "\"kind\" must be \"swing\" or \"static\"");
        continue;
      }
      if (key == "axis") {
        if (!it->is_string()) return invalidArgument(where + "\"axis\" must be \"x\", \"y\" or \"z\"");
        auto axis = parseAxis(it->get<std::string>());
        if (!axis) return invalidArgument(where + axis.status().message());
        point.axis = *axis;
        continue;
      }
      if (key == "position_deg") {
        if (!it->is_array() || it->size() != kAxisCount)
          return invalidArgument(where + "\"position_deg\" must be [x, y, z] in degrees");
        for (int a = 0; a < kAxisCount; ++a) {
          if (!(*it)[a].is_number() || !std::isfinite((*it)[a].get<double>()))
            return invalidArgument(where + "\"position_deg\" must hold three finite numbers");
          point.positionDeg[a] = (*it)[a].get<double>();
        }
        continue;
      }
      if (!it->is_number()) return invalidArgument(where + "\"" + key + "\" must be a number");
      const double v = it->get<double>();
      // JSON has no infinity, but a literal beyond double's range parses to
      // one, and it would be written back as null.
      if (!std::isfinite(v)) return invalidArgument(where + "\"" + key + "\" is beyond any finite number");
      if (key == "frequency_hz") {
        point.frequencyHz = v;
        gaveFrequency = true;
      } else if (key == "amplitude_deg") {
        point.amplitudeDeg = v;
        gaveAmplitude = true;
      }
      else if (key == "duration_s") point.durationS = v;
      else if (key == "settle_s") point.settleS = v;
      else if (key == "start_phase_deg") point.startPhaseDeg = v;
      else if (key == "periods") periods = v;
      else return invalidArgument(where + "unknown key \"" + key + "\"");
    }
    if (point.isStatic()) {
      // A static segment has no swing: the defaults do not apply, and values
      // given are kept so that validation can say they do not belong.
      if (!gaveFrequency) point.frequencyHz = 0.0;
      if (!gaveAmplitude) point.amplitudeDeg = 0.0;
      if (periods != 0.0) return invalidArgument(where + "a static segment has no periods; give \"duration_s\"");
    }
    if (periods != 0.0) {
      if (!(point.frequencyHz > 0.0))
        return invalidArgument(where + "\"periods\" needs \"frequency_hz\" > 0 to give a duration");
      point.durationS = periods / point.frequencyHz;
      if (!std::isfinite(point.durationS))
        return invalidArgument(where + "\"periods\" / \"frequency_hz\" is beyond any finite duration");
    }
    plan.points.push_back(point);
  }
  return plan;
}

std::string testPlanToJson(const TestPlan& plan) {
  nlohmann::json doc;
  doc["rest_between_s"] = plan.restBetweenS;
  doc["points"] = nlohmann::json::array();
  for (const auto& p : plan.points) {
    nlohmann::json point;
    if (p.isStatic())
      point = {{"kind", "static"}, {"axis", axisName(p.axis)}, {"duration_s", p.durationS}, {"settle_s", p.settleS}};
    else
      point = {{"axis", axisName(p.axis)},       {"frequency_hz", p.frequencyHz}, {"amplitude_deg", p.amplitudeDeg},
               {"duration_s", p.durationS},      {"settle_s", p.settleS},         {"start_phase_deg", p.startPhaseDeg}};
    if (p.positionDeg != std::array<double, kAxisCount>{}) point["position_deg"] = p.positionDeg;
    doc["points"].push_back(std::move(point));
  }
  return doc.dump(2);
}

}  // namespace fog
