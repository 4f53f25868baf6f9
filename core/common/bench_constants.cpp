#include "core/common/bench_constants.h"

#include <cmath>

#include "core/common/text.h"

namespace fog {

namespace {

using Field = BenchConstantProblem::Field;

std::string num(double v) { return printfNumber("%g", v); }

// A delay constant or its uncertainty: finite, 0 .. kMaxBenchDelayMs.
void checkDelay(std::vector<BenchConstantProblem>& out, Field field, const char* what, double ms, bool uncertainty) {
  if (std::isfinite(ms) && ms >= 0.0 && ms <= kMaxBenchDelayMs) return;
  std::string why = std::string(what) + " must be within 0 .. " + num(kMaxBenchDelayMs) + " ms, not " + num(ms);
  if (!std::isfinite(ms))
    why += ": it is not a number";
  else if (ms < 0.0)
    why += uncertainty ? ": an uncertainty is never negative" : ": a delay is never negative (a stamp cannot precede "
                                                                "what it stamps); check its sign and what it is measured from";
  else
    why += ": bench delays are a fraction of a frame or a few frames; check the value and that it is in milliseconds";
  out.push_back({field, std::move(why)});
}

}  // namespace

std::vector<BenchConstantProblem> benchConstantProblems(const BenchConstants& c) {
  std::vector<BenchConstantProblem> out;
  checkDelay(out, Field::kTableReadDelay, "the table read delay", c.tableReadDelayMs, false);
  checkDelay(out, Field::kTableReadDelayStd, "the table read delay's uncertainty", c.tableReadDelayStdMs, true);
  checkDelay(out, Field::kBoardDelay, "the processing-board delay", c.boardDelayMs, false);
  checkDelay(out, Field::kBoardDelayStd, "the processing-board delay's uncertainty", c.boardDelayStdMs, true);
  if (!(std::isfinite(c.latitudeDeg) && std::abs(c.latitudeDeg) <= 90.0))
    out.push_back({Field::kLatitude, "the latitude must be within -90 .. 90 deg, not " + num(c.latitudeDeg)});
  const double pulse = c.pulseEquivalentDeg;
  if (!(pulse == 0.0 || (pulse >= kMinPulseEquivalentDeg && pulse <= kMaxPulseEquivalentDeg)))
    out.push_back({Field::kPulseEquivalent,
                   "the pulse equivalent must be within 1e-9 .. 1 deg per pulse (or 0: not set, the stream states "
                   "it), not " + num(pulse) + ": check its unit (degrees per pulse, not arcseconds or radians)"});
  if (!(c.counterHz > 0.0 && c.counterHz <= kMaxCounterHz))
    out.push_back({Field::kCounterHz, "the sampling board's counter frequency must be above 0 and at most 1e12 Hz, not " +
                                          num(c.counterHz) + " Hz"});
  if (c.counterBits < 1 || c.counterBits > 64)
    out.push_back({Field::kCounterBits,
                   "the sampling board's counter width must be 1 .. 64 bits, not " + std::to_string(c.counterBits)});
  for (std::size_t a = 0; a < c.gyroSign.size(); ++a)
    if (c.gyroSign[a] != 1 && c.gyroSign[a] != -1)
      out.push_back({Field::kGyroSign, std::string("the gyro sign of axis ") + axisLabel(static_cast<Axis>(a)) +
                                           " must be 1 or -1, not " + std::to_string(c.gyroSign[a])});
  const double tol = c.gainToleranceFraction;
  if (!(tol >= kMinGainToleranceFraction && tol < kMaxGainToleranceFraction))
    out.push_back({Field::kGainTolerance,
                   "the gain tolerance must be a fraction from 1e-6 up to (not including) 1, not " + num(tol) +
                       ": it is the gyro's stated scale tolerance (0.01 = 1 %); the gyro/table amplitude ratio must "
                       "lie within 1 +- it, and 1 or more would pass a gyro that reads nothing"});
  return out;
}

Status checkBenchConstants(const BenchConstants& constants) {
  const auto problems = benchConstantProblems(constants);
  return problems.empty() ? Status::ok() : invalidArgument(problems.front().message);
}

const char* benchConstantOption(BenchConstantProblem::Field field) {
  switch (field) {
    case Field::kTableReadDelay: return "--read-delay-ms";
    case Field::kTableReadDelayStd: return "--read-delay-std-ms";
    case Field::kBoardDelay: return "--board-delay-ms";
    case Field::kBoardDelayStd: return "--board-delay-std-ms";
    case Field::kPulseEquivalent: return "--pulse-equivalent-deg";
    case Field::kGyroSign: return "--gyro-sign";
    case Field::kGainTolerance: return "--gain-tolerance";
    case Field::kLatitude:
    case Field::kCounterHz:
    case Field::kCounterBits: break;
  }
  return "";
}

const char* benchConstantKey(BenchConstantProblem::Field field) {
  switch (field) {
    case Field::kTableReadDelay: return "table_read_delay_ms";
    case Field::kTableReadDelayStd: return "table_read_delay_std_ms";
    case Field::kBoardDelay: return "board_delay_ms";
    case Field::kBoardDelayStd: return "board_delay_std_ms";
    case Field::kLatitude: return "latitude_deg";
    case Field::kPulseEquivalent: return "pulse_equivalent_deg";
    case Field::kCounterHz: return "counter_hz";
    case Field::kCounterBits: return "counter_bits";
    case Field::kGyroSign: return "gyro_sign";
    case Field::kGainTolerance: return "gain_tolerance";
  }
  return "";
}

}  // namespace fog
