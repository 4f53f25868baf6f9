#include "core/analysis/report_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/analysis/decision_rule.h"
#include "core/analysis/uncertainty_bound.h"
#include "core/common/gyro_signs.h"
#include "core/common/text.h"

namespace fog::analysis {

namespace {

std::string f(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string upper(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(ch >= 'a' && ch <= 'z' ? ch - 'a' + 'A' : ch);
  return s;
}

// An uncertainty with two significant digits, however small.
std::string sd(double v) { return f("%.2g", v); }

std::string fixed(double v, int decimals, int width = 0) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%*.*f", width, decimals, v);
  return buf;
}

void fitRow(std::ostringstream& o, const char* name, const SineFit& s, bool frequencyFree) {
  o << "    " << name << "  period " << f("%12.4f", s.periodMs)
    << (frequencyFree ? " ± " + sd(s.periodStdMs) : std::string(" (nominal)")) << " ms   phase "
    << f("%11.4f", s.phaseMs) << " ± " << sd(s.phaseStdMs) << " ms   amplitude " << f("%.5f", s.amplitudeDeg)
    << " deg\n";
}

nlohmann::json fitJson(const SineFit& s) {
  return {{"period_ms", s.periodMs},         {"period_std_ms", s.periodStdMs},
          {"phase_ms", s.phaseMs},           {"phase_std_ms", s.phaseStdMs},
          {"amplitude_deg", s.amplitudeDeg}, {"amplitude_std_deg", s.amplitudeStdDeg},
          {"frequency_hz", s.frequencyHz},   {"offset_deg", s.offsetDeg},
          {"trend_deg_per_s", s.trendDegPerS}, {"residual_rms_deg", s.residualRmsDeg},
          {"chi2_per_dof", s.chiSquarePerDof}, {"samples", s.samples}};
}

// Why a point carries no risk number ("" when it does): its delay is refused
// (INVALID), or the run stopped early (every point INCOMPLETE).
std::string riskRefusal(const PointVerdict& v, const ReportContext& context) {
  if (v.verdict == Verdict::kInvalid) return "no false-accept probability: the delay is refused (INVALID)";
  if (!context.incompleteReason.empty())
    return "no false-accept probability: the run stopped before its plan ended (INCOMPLETE)";
  return {};
}

// "risk: guard band k·σ = 0.0030 ms; probability that the true delay is at
// or above the limit 1e-6 %" or why there is none.
std::string pointRiskText(const PointVerdict& v, const ReportContext& context) {
  if (const std::string why = riskRefusal(v, context); !why.empty()) return why;
  return "guard band " + coverageFactorText(context.coverageK) + "σ = " + f("%.4g", v.guardBandMs) +
         " ms; probability that the true delay is at or above the limit: " + probabilityText(v.falseAcceptProbability);
}

}  // namespace

std::string incompleteRunText(const ReportContext& context) {
  if (context.incompleteReason.empty()) return {};
  if (!(context.recordedS > 0.0)) return context.incompleteReason;
  std::string s = "run stopped after " + f("%.1f", context.recordedS) + " s";
  if (context.plannedS > 0.0) s += " of " + f("%.1f", context.plannedS) + " s";
  return s + ": " + context.incompleteReason;
}

std::string formatReportText(const DelayReport& report, const ReportContext& context) {
  std::ostringstream o;
  const auto& c = report.constants;
  const auto& h = report.health;
  const ReportVerdict verdict = judgeReport(report, context.imuDelayLimitMs, context.coverageK);
  o << "fogbench delay report\n";
  if (!context.source.empty()) o << "source: " << context.source << "\n";
  if (!context.incompleteReason.empty())
    // Never a bare PASS for a run that did not finish its plan.
    o << "verdict: INCOMPLETE (" << incompleteRunText(context) << "); the data recorded give "
      << upper(verdictName(verdict.verdict)) << "\n";
  else
    o << "verdict: " << upper(verdictName(verdict.verdict)) << "\n";
  for (const auto& why : verdict.reasons) o << "  " << why << "\n";
  // ISO/IEC 17025 §7.8.6: a statement of conformity states its rule and risk.
  o << decisionRuleStatement(context.coverageK, context.imuDelayLimitMs) << "\n";
  o << "stream: " << h.tableFrames << " table, " << h.imuFrames << " IMU, " << h.statusFrames
    << " status frames; " << h.checksumFailures << " checksum failures, " << h.lostFrames << " lost, "
    << h.duplicateFrames << " duplicated, " << h.bytesSkipped << " bytes skipped\n";
  o << "bench constants: table read delay " << f("%.4f", c.tableReadDelayMs) << " ± "
    << f("%.4f", c.tableReadDelayStdMs) << " ms, board delay " << f("%.4f", c.boardDelayMs) << " ± "
    << f("%.4f", c.boardDelayStdMs) << " ms\n";
  // The conventions the numbers depend on, stated with them.
  o << "gyro signs: " << describeGyroSigns(c.gyroSign) << " (-1: the gyro axis counts against the table's); IMU frame: "
    << describeImuFrame(c.imuFrame) << "\n";

  for (std::size_t pi = 0; pi < report.points.size(); ++pi) {
    const auto& p = report.points[pi];
    const PointVerdict& pv = verdict.points[pi];
    o << "\nTest point " << p.index + 1 << ": " << axisLabel(p.axis) << " axis, " << f("%g", p.nominalFrequencyHz)
      << " Hz / " << f("%.3f", p.tableFit.amplitudeDeg) << " deg, " << f("%.1f", p.durationS) << " s ("
      << f("%.1f", p.periods) << " periods)\n";
    o << "  fits (angle = A sin(2 pi (t - t0) / T); t0 is the phase):\n";
    fitRow(o, "table 3-parameter", p.tableNominal, false);
    fitRow(o, "gyro  3-parameter", p.gyroNominal, false);
    fitRow(o, "table 4-parameter", p.tableFit, true);
    fitRow(o, "gyro  4-parameter", p.gyroFit, true);
    o << "    joint fit: frequency " << f("%.9f", p.joint.frequencyHz) << " Hz, gyro/table amplitude "
      << f("%.6f", p.magnitudeRatio) << ", trend " << f("%.3e", p.joint.trendDegPerS) << " deg/s ("
      << f("%.3f", p.joint.trendDegPerS * 3600.0) << " deg/h), chi2/dof " << f("%.3f", p.joint.chiSquarePerDof)
      << "\n";
    o << "  delay:\n";
    const int d = decimalsFor(p.lagStdMs);
    o << "    measured lag (gyro behind table) " << fixed(p.lagMs, d, 9) << " ± " << fixed(p.lagStdMs, d)
      << " ms   (CRLB " << sd(p.crlbMs) << " ms, std/CRLB " << f("%.2f", p.stdOverCrlb)
      << (sigmaBelowBound(p) ? ": BELOW THE BOUND, the σ is understated (uncertainty_below_bound)" : "") << ")\n";
    if (p.lagStdSource != "fit")
      o << "    uncertainty from " << p.lagStdSource << " (fit alone " << fixed(p.fitLagStdMs, d)
        << " ms, per-period scatter " << fixed(p.trackLagStdMs, d) << " ms)\n";
    o << "  + table read delay                 " << fixed(c.tableReadDelayMs, d, 9) << " ms\n";
    o << "  = IMU delay                        " << fixed(p.imuDelayMs, d, 9) << " ± " << fixed(p.imuDelayStdMs, d)
      << " ms\n";
    o << "  - processing board delay           " << fixed(c.boardDelayMs, d, 9) << " ms\n";
    o << "  = gyro's own delay                 " << fixed(p.gyroDelayMs, d, 9) << " ± "
      << fixed(p.gyroDelayStdMs, d) << " ms\n";
    if (static_cast<std::size_t>(p.index) < context.trueLagMs.size()) {
      const double truth = context.trueLagMs[static_cast<std::size_t>(p.index)];
      o << "    simulator truth: lag " << fixed(truth, d) << " ms (error " << (p.lagMs >= truth ? "+" : "")
        << fixed(p.lagMs - truth, d) << " ms = " << f("%+.1f", (p.lagMs - truth) / p.lagStdMs) << " std)\n";
    }
    o << "  per-period delay: " << p.periodTrack.size() << " periods, mean " << f("%.4f", p.periodMeanLagMs)
      << " ms, scatter " << f("%.4f", p.periodScatterMs) << " ms\n";
    o << "  noise: encoder " << f("%.2e", p.noise.tableNoiseDeg) << " deg, pulse output "
      << f("%.2e", p.noise.gyroQuantisationDeg) << " deg, angle random walk "
      << f("%.4f", p.noise.gyroArwDegPerSqrtH) << " deg/sqrt(h) (near the swing frequency "
      << f("%.4f", p.noise.gyroSwingBandArwDegPerSqrtH) << ")\n";
    if (p.lostImuFrames) o << "  lost IMU frames: " << p.lostImuFrames << "\n";
    if (p.lostImuFrames || p.lostTableFrames || p.damage.duplicateFrames || p.damage.checksumFailures ||
        p.damage.bytesSkipped)
      o << "  affected: " << p.lostTableFrames << " table and " << p.lostImuFrames << " IMU frames lost, "
        << p.damage.duplicateFrames << " duplicated, " << p.damage.checksumFailures << " checksum failures, "
        << p.damage.bytesSkipped << " bytes skipped; data cover " << f("%.2f", p.coveredS) << " of "
        << f("%.2f", p.durationS) << " s (" << f("%.2f", p.durationS > 0 ? 100.0 * p.coveredS / p.durationS : 0.0)
        << " %), longest gap " << f("%.1f", p.largestGapS * 1e3) << " ms\n";
    for (const auto& w : p.warnings) o << "  warning: " << w << "\n";
    o << "  checks:\n";
    for (const auto& check : p.checks)
      o << "    " << (!check.judged ? "n/a     " : check.passed ? "ok      " : "FAILED  ") << check.id << ": " << check.detail << "\n";
    o << "  verdict: " << upper(verdictName(pv.verdict)) << (pv.verdict == Verdict::kInvalid ? " (delay refused)" : "")
      << "\n";
    for (const auto& why : pv.reasons) o << "    " << why << "\n";
    o << "    " << pointRiskText(pv, context) << "\n";
  }
  for (const auto& s : report.staticSegments)
    o << "\nTest point " << s.index + 1 << ": static segment, " << axisLabel(s.axis) << " axis, "
      << f("%.1f", s.durationS) << " s at rest: no delay to measure (gyro noise: fogbench-cli noise)\n";
  for (const auto& fp : report.failedPoints) o << "\nno delay from " << fp << "\n";
  for (const auto& cc : report.consistency) {
    o << "\nDelay against frequency, " << axisLabel(cc.axis) << " axis (" << cc.points
      << " frequencies"
      << (cc.leftOutPoints > 0 ? "; " + std::to_string(cc.leftOutPoints) + " test point(s) left out: their checks failed"
                               : std::string())
      << "): weighted lag " << fixed(cc.weightedLagMs, decimalsFor(cc.weightedLagStdMs)) << " ± "
      << fixed(cc.weightedLagStdMs, decimalsFor(cc.weightedLagStdMs))
      << " ms, chi2 " << f("%.2f", cc.chiSquare) << " on " << cc.dof << " dof, p = " << f("%.3f", cc.pValue)
      << ": "
      << (cc.consistentWithPureDelay ? "consistent with a pure delay"
                                     : "NOT a pure delay (frequency-dependent: lag, filtering or dynamics)")
      << "\n";
  }
  return o.str();
}

std::string formatReportJson(const DelayReport& report, const ReportContext& context) {
  using nlohmann::json;
  const ReportVerdict verdict = judgeReport(report, context.imuDelayLimitMs, context.coverageK);
  json doc;
  doc["report_format"] = 1;  // bump on any incompatible change (docs/report.md)
  doc["verdict"] = verdictName(verdict.verdict);
  doc["verdict_reasons"] = verdict.reasons;
  if (!context.incompleteReason.empty()) {
    doc["verdict"] = "incomplete";
    doc["data_verdict"] = verdictName(verdict.verdict);
    doc["run"] = {{"complete", false},
                  {"incomplete_reason", toValidUtf8(context.incompleteReason)},
                  {"recorded_s", context.recordedS},
                  {"planned_s", context.plannedS}};
  }
  doc["imu_delay_limit_ms"] = verdict.limitMs;
  doc["decision_rule"] = {{"rule", kDecisionRuleName},
                          {"coverage_factor_k", verdict.coverageK},
                          {"limit_ms", verdict.limitMs},
                          {"max_false_accept_probability", maxFalseAcceptProbability(verdict.coverageK)},
                          {"statement", decisionRuleStatement(verdict.coverageK, verdict.limitMs)}};
  doc["software"] = "fogbench";
  doc["source"] = context.source;
  const auto& c = report.constants;
  doc["constants"] = {{"table_read_delay_ms", c.tableReadDelayMs},
                      {"table_read_delay_std_ms", c.tableReadDelayStdMs},
                      {"board_delay_ms", c.boardDelayMs},
                      {"board_delay_std_ms", c.boardDelayStdMs},
                      {"gain_tolerance", c.gainToleranceFraction}};
  const auto& h = report.health;
  doc["stream"] = {{"table_frames", h.tableFrames},         {"imu_frames", h.imuFrames},
                   {"status_frames", h.statusFrames},       {"checksum_failures", h.checksumFailures},
                   {"bytes_skipped", h.bytesSkipped},       {"lost_frames", h.lostFrames},
                   {"duplicate_frames", h.duplicateFrames}, {"out_of_order_frames", h.outOfOrderFrames},
                   {"counter_wraps", h.counterWraps}};
  doc["test_points"] = json::array();
  for (std::size_t pi = 0; pi < report.points.size(); ++pi) {
    const auto& p = report.points[pi];
    json tp = {{"index", p.index},
               {"verdict", verdictName(verdict.points[pi].verdict)},
               {"verdict_reasons", verdict.points[pi].reasons},
               {"guard_band_ms", nullptr},
               {"false_accept_probability", nullptr},
               {"axis", axisName(p.axis)},
               {"frequency_hz", p.nominalFrequencyHz},
               {"amplitude_deg", p.tableFit.amplitudeDeg},
               {"duration_s", p.durationS},
               {"periods", p.periods},
               {"table_fit", fitJson(p.tableFit)},
               {"gyro_fit", fitJson(p.gyroFit)},
               {"table_fit_nominal", fitJson(p.tableNominal)},
               {"gyro_fit_nominal", fitJson(p.gyroNominal)},
               {"joint_fit",
                {{"frequency_hz", p.joint.frequencyHz},
                 {"frequency_std_hz", p.joint.frequencyStdHz},
                 {"magnitude_ratio", p.magnitudeRatio},
                 {"magnitude_ratio_std", p.gainStd},
                 {"fit_magnitude_ratio_std", p.joint.gainStd},
                 {"magnitude_ratio_lag_cov_ms", p.gainLagCovMs},
                 {"periodic_gain_inflation", p.periodicGainInflation},
                 {"phase_deg", p.phaseDeg},
                 {"trend_deg_per_s", p.joint.trendDegPerS},
                 {"chi2_per_dof", p.joint.chiSquarePerDof}}},
               {"lag_ms", p.lagMs},
               {"lag_std_ms", p.lagStdMs},
               {"lag_std_source", p.lagStdSource},
               {"fit_lag_std_ms", p.fitLagStdMs},
               {"track_lag_std_ms", p.trackLagStdMs},
               {"periodic_inflation", p.periodicInflation},
               {"lag_std_before_cancelling_ms", p.lagStdBeforeCancellingMs},
               {"gyro_sign", p.gyroSign},
               {"timing",
                {{"rate_error_ppm", p.rateErrorPpm},
                 {"rate_error_std_ppm", p.rateErrorStdPpm},
                 {"lag_drift_ppm", p.lagDriftPpm},
                 {"lag_drift_std_ppm", p.lagDriftStdPpm}}},
               {"adequacy",
                {{"table_misfit_fraction", p.tableMisfitFraction},
                 {"gyro_misfit_fraction", p.gyroMisfitFraction},
                 {"harmonic_fraction", p.harmonicFraction},
                 {"amplitude_change_fraction", p.amplitudeChangeFraction}}},
               {"crlb_ms", p.crlbMs},
               {"lag_std_over_crlb", p.stdOverCrlb},
               {"imu_delay_ms", p.imuDelayMs},
               {"imu_delay_std_ms", p.imuDelayStdMs},
               {"gyro_delay_ms", p.gyroDelayMs},
               {"gyro_delay_std_ms", p.gyroDelayStdMs},
               {"noise",
                {{"table_noise_deg", p.noise.tableNoiseDeg},
                 {"gyro_quantisation_deg", p.noise.gyroQuantisationDeg},
                 {"gyro_arw_deg_per_sqrt_h", p.noise.gyroArwDegPerSqrtH},
                 {"gyro_swing_band_arw_deg_per_sqrt_h", p.noise.gyroSwingBandArwDegPerSqrtH}}},
               {"lost_imu_frames", p.lostImuFrames},
               {"affected",
                {{"lost_table_frames", p.lostTableFrames},
                 {"lost_imu_frames", p.lostImuFrames},
                 {"duplicate_frames", p.damage.duplicateFrames},
                 {"checksum_failures", p.damage.checksumFailures},
                 {"bytes_skipped", p.damage.bytesSkipped},
                 {"out_of_order_frames", p.damage.outOfOrderFrames},
                 {"covered_s", p.coveredS},
                 {"time_covered", p.durationS > 0 ? p.coveredS / p.durationS : 0.0},
                 {"largest_gap_s", p.largestGapS}}},
               {"warnings", p.warnings}};
    json track = json::array();
    for (const auto& d : p.periodTrack)
      track.push_back({{"time_s", d.timeS}, {"lag_ms", d.lagMs}, {"table_amplitude_deg", d.tableAmplitudeDeg}});
    tp["period_track"] = track;
    // Only a vouched delay carries a risk number (shown_verdict.h).
    if (const std::string why = riskRefusal(verdict.points[pi], context); why.empty()) {
      tp["guard_band_ms"] = verdict.points[pi].guardBandMs;
      tp["false_accept_probability"] = verdict.points[pi].falseAcceptProbability;
    } else {
      tp["false_accept_note"] = why;
    }
    tp["period_mean_lag_ms"] = p.periodMeanLagMs;
    tp["period_scatter_ms"] = p.periodScatterMs;
    json checks = json::array();
    for (const auto& check : p.checks)
      checks.push_back(
          {{"id", check.id}, {"passed", check.passed}, {"judged", check.judged}, {"detail", check.detail}});
    tp["checks"] = checks;
    if (p.damped)
      tp["damped_fit"] = {{"lag_ms", p.damped->lagMs},
                          {"lag_std_ms", p.damped->lagStdMs},
                          {"frequency_hz", p.damped->frequencyHz},
                          {"decay_time_s", p.damped->decayTimeS},
                          {"table_residual_rms_deg", p.damped->tableResidualRmsDeg},
                          {"magnitude_ratio", p.damped->gain}};
    if (static_cast<std::size_t>(p.index) < context.trueLagMs.size())
      tp["true_lag_ms"] = context.trueLagMs[static_cast<std::size_t>(p.index)];
    doc["test_points"].push_back(tp);
  }
  doc["frequency_consistency"] = json::array();
  for (const auto& cc : report.consistency)
    doc["frequency_consistency"].push_back({{"axis", axisName(cc.axis)},
                                            {"points", cc.points},
                                            {"left_out_points", cc.leftOutPoints},
                                            {"weighted_lag_ms", cc.weightedLagMs},
                                            {"weighted_lag_std_ms", cc.weightedLagStdMs},
                                            {"chi2", cc.chiSquare},
                                            {"dof", cc.dof},
                                            {"p_value", cc.pValue},
                                            {"consistent_with_pure_delay", cc.consistentWithPureDelay}});
  doc["failed_points"] = report.failedPoints;
  doc["static_segments"] = json::array();
  for (const auto& s : report.staticSegments)
    doc["static_segments"].push_back({{"index", s.index},
                                      {"axis", axisName(s.axis)},
                                      {"duration_s", s.durationS},
                                      {"imu_samples", s.imuSamples}});
  return doc.dump(2);
}

}  // namespace fog::analysis
