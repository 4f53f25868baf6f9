#include "core/analysis/gain_check.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/frequency_response.h"
#include "core/common/text.h"

namespace fog::analysis {

namespace {

// "1 %", "0.5 %", "0.01 %": the tolerance as the user gave it.
std::string percentText(double fraction) { return printfNumber("%g", 100.0 * fraction) + " %"; }

// How far the gyro reads from the table, in words: "2.00 % more than",
// "500× ", "1/500 of".
std::string howFar(double scale) {
  if (scale >= 2.0) return printfNumber(scale >= 10.0 ? "%.0f" : "%.2f", scale) + "× the table";
  if (scale > 0.0 && scale <= 0.1) return "1/" + printfNumber("%.0f", 1.0 / scale) + " of the table";
  if (scale < 0.5) return printfNumber("%.3f", scale) + "× the table";
  return fixed(100.0 * std::abs(scale - 1.0), 2) + " % " + (scale > 1.0 ? "more" : "less") + " than the table";
}

// A gyro/table ratio this far from 1 (or its inverse) is a wrong constant or
// unit, never a scale error of a gyro.
constexpr double kGrossScale = 1.5;

}  // namespace

ValidityCheck gainCheck(const TestPointResult& point, const PointDynamics& dynamics, double toleranceFraction) {
  ValidityCheck c{"gain", true, ""};
  const double ratio = std::abs(point.magnitudeRatio);
  const bool withDynamics = !dynamics.model.empty() && dynamics.dynamicGain != 1.0;
  const double scale = withDynamics ? ratio / dynamics.dynamicGain : ratio;
  const std::string band = "1 ± " + percentText(toleranceFraction);
  const std::string frequency = printfNumber("%.4g", point.joint.frequencyHz);
  const std::string measured =
      "gyro/table ratio " + fixed(ratio, 4) +
      (withDynamics ? " at " + frequency + " Hz, where the fitted " + dynamics.model + " response's own gain is " +
                          fixed(dynamics.dynamicGain, 4) + ": scale " + fixed(scale, 4)
                    : std::string());
  if (!std::isfinite(scale)) {
    c.judged = false;
    c.detail = "not judged: the gyro/table ratio is not a finite number";
    return c;
  }
  c.passed = std::abs(scale - 1.0) <= toleranceFraction;
  if (c.passed) {
    c.detail = "the gyro's amplitude matches the table's (" + measured + ", within " + band + ")";
    return c;
  }
  // A factor of 1.5 or more is no scale error a gyro has: a constant or a
  // unit is wrong (a frame period of 1000 ms for 2 ms frames reads 500x).
  if (scale >= kGrossScale || scale <= 1.0 / kGrossScale) {
    c.detail = "the gyro reads " + howFar(scale) + " (" + measured + ", outside " + band +
               "): the pulse equivalent or the frame period is wrong. An increment is its pulse count times the "
               "pulse equivalent, or its rate times the IMU's frame period: check both (bench.pulse_equivalent_deg; "
               "for imported rates bench.gyro_frame_period_ms or import --frame-period-ms) and analyse again; the "
               "delay is refused";
    return c;
  }
  c.detail = "the gyro reads " + howFar(scale) + " (" + measured + ", outside " + band +
             "): its scale is not the one the bench states. A pulse equivalent or frame period slightly off "
             "(rounded, or for another gyro) or a gyro outside its scale tolerance: check them and analyse again; "
             "the delay is refused";
  if (dynamics.model.empty() && scale < 1.0)
    c.detail += ". If the gyro's own dynamics lower its gain at " + frequency +
                " Hz, measure its frequency response (run --preset response): the check takes out the dynamics "
                "fitted there";
  c.detail += ". If the gyro's scale is known to be off by this much, state its tolerance (--gain-tolerance)";
  return c;
}

void addGainChecks(DelayReport& report, double toleranceFraction) {
  for (int a = 0; a < kAxisCount; ++a) {
    const Axis axis = static_cast<Axis>(a);
    // The axis' frequency response, from the points every other check
    // passed (the gain check is not there yet), when they span two or more
    // frequencies (0.1 % apart, as the frequency test counts them).
    std::optional<ResponseModelFit> chosen;
    auto points = responsePoints(report, axis);
    const bool spans = points.size() >= 2 &&
                       points.back().frequencyHz > points.front().frequencyHz * (1.0 + 1e-3);
    // The shape of the gain only (its scale K is divided out): the chosen
    // model's, else, when no model is adequate and admissible, the one that
    // fits the points best (lowest chi^2) — a model too rough to report a
    // delay still describes how the gain falls or rises to well within the
    // tolerance, and a scale error is K, which is taken out either way.
    if (spans)
      if (auto response = analyzeResponse(std::move(points), axis, kDefaultGroupDelayAtHz,
                                                report.constants.tableReadDelayMs);
          response) {
        if (response->chosen >= 0) {
          chosen = response->models[static_cast<std::size_t>(response->chosen)];
        } else {
          for (const auto& m : response->models)
            if (m.values.size() > 0 && std::isfinite(m.chiSquare) && (!chosen || m.chiSquare < chosen->chiSquare))
              chosen = m;
        }
      }
    for (auto& p : report.points) {
      if (p.axis != axis) continue;
      PointDynamics dynamics;
      if (chosen) {
        dynamics.model = responseModelName(chosen->kind);
        const double k = chosen->values.size() > 0 ? chosen->values[0] : 0.0;
        const double d = chosen->magnitudeAt(p.joint.frequencyHz) / k;
        if (chosen->kind != ResponseModelKind::kDelay && std::isfinite(d) && d > 0.0) dynamics.dynamicGain = d;
      }
      const auto at = std::find_if(p.checks.begin(), p.checks.end(), [](const ValidityCheck& c) {
        return c.id == "axis_sign";
      });
      p.checks.insert(at == p.checks.end() ? p.checks.begin() : at + 1, gainCheck(p, dynamics, toleranceFraction));
    }
  }
}

}  // namespace fog::analysis
