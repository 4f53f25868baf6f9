// formatDiagnosisText() / formatDiagnosisJson() (diagnosis.h).
#include "core/diagnosis/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace fog::diagnosis {

std::string formatDiagnosisJson(const Diagnosis& d) {
  using nlohmann::json;
  json j;
  j["verdict"] = d.verdict;
  j["verdict_effects"] = d.verdictEffects;
  j["verdict_reason"] = d.verdictReason;
  json gap = json::object();
  for (int c = 0; c < kChannelCount; ++c) {
    const auto& b = d.gapBefore[static_cast<std::size_t>(c)];
    const auto& a = d.gapAfter[static_cast<std::size_t>(c)];
    const auto& h = d.heldOut[static_cast<std::size_t>(c)];
    gap[channelName(static_cast<Channel>(c))] = {
        {"cells", b.cells},          {"before", b.rmsZ},           {"after", a.rmsZ},
        {"max_abs_z_before", b.maxAbsZ}, {"max_abs_z_after", a.maxAbsZ}, {"heldout_excess_chi2_before", h.before},
        {"heldout_excess_chi2_after", h.after}, {"heldout_shrink", h.shrink}};
  }
  j["gap"] = gap;
  j["gap_significant"] = d.gapSignificant;
  j["chi2"] = d.chiSquare;
  j["cells"] = d.cells;
  json effects = json::array();
  for (const auto& e : d.effects) {
    json params = json::object();
    json order = json::array();  // the library's order (an object's keys have none)
    for (std::size_t p = 0; p < e.parameters.size(); ++p) order.push_back(e.parameters[p].name);
    for (std::size_t p = 0; p < e.parameters.size(); ++p)
      params[e.parameters[p].name] = {{"value", e.values[p]},
                                      {"std", e.standardErrors[p]},
                                      {"unit", e.parameters[p].unit},
                                      {"definition", e.parameters[p].definition},
                                      {"standard", e.parameters[p].standard},
                                      {"detection_threshold",
                                       p < e.detectionThresholds.size() ? e.detectionThresholds[p] : 0.0}};
    json per = json::object();
    for (const auto& s : e.perChannel) per[channelName(s.channel)] = s.shrink;
    effects.push_back({{"name", e.name},
                       {"description", e.description},
                       {"parameters", params},
                       {"parameter_order", order},
                       {"heldout_shrink", e.heldOutShrink},
                       {"heldout_shrink_per_channel", per},
                       {"score", e.score ? json(*e.score) : json(nullptr)},  // null: no signature
                       {"train_delta_chi2", e.trainDeltaChi2},
                       {"heldout_delta_chi2", e.heldOutDeltaChi2},
                       {"exact", e.exact},
                       {"kept", e.kept},
                       {"note", e.note}});
  }
  j["effects"] = effects;
  json aliases = json::array();
  for (const auto& a : d.aliasGroups)
    aliases.push_back({{"name", a.name}, {"members", a.members}, {"value", a.value}, {"separating_test", a.separatingTest}});
  j["alias_groups"] = aliases;
  auto timing = [](const TimingAudit& t) {
    auto s = [](const StreamTiming& x) {
      return json{{"samples", x.samples}, {"interval_mean_ppm", x.intervalMeanPpm}, {"interval_std_us", x.intervalStdUs},
                  {"gaps", x.gaps}, {"duplicates", x.duplicates}};
    };
    return json{{"table", s(t.table)}, {"imu", s(t.imu)}, {"lost_frames", t.lostFrames},
                {"duplicate_frames", t.duplicateFrames}, {"counter_wraps", t.counterWraps},
                {"checksum_failures", t.checksumFailures}, {"out_of_order_frames", t.outOfOrderFrames}};
  };
  j["timing"] = {{"real", timing(d.realTiming)}, {"simulated", timing(d.simTiming)}};
  const auto& c = d.calibration;
  j["calibration"] = {{"lag_ms", c.lagMs},
                      {"table_frequency_error_ppm", c.tableFrequencyErrorPpm},
                      {"heading_deg", c.headingDeg},
                      {"heading_std_deg", c.headingStdDeg},
                      {"imu_frame",
                       {{"stated", imuFrameToText(c.frame.stated)},
                        {"checked", c.frame.checked},
                        {"vertical_ratio", c.frame.verticalRatio},
                        {"vertical_ratio_std", c.frame.verticalRatioStd},
                        {"chi2_z_down", c.frame.chiSquareDown},
                        {"chi2_z_up", c.frame.chiSquareUp},
                        {"decisive", c.frame.decisive},
                        {"z_up", c.frame.zUp},
                        {"contradicted", c.frame.contradicted}}},
                      {"table_period_ms", c.config.encoder.samplePeriodS * 1e3},
                      {"imu_period_ms", c.config.imuBoard.framePeriodS * 1e3},
                      {"encoder_noise_deg", c.encoderNoiseDeg},
                      {"arw_deg_sqrt_h", c.arwDegPerSqrtH},
                      {"bias_deg_h", c.biasDegPerH},
                      {"bias_instability_deg_h", c.config.fog.biasInstabilityDegPerH},
                      {"bias_correlation_s", c.config.fog.biasCorrelationS},
                      {"bias_instability_stated", c.biasInstabilityStated},
                      {"bias_instability_definition",
                       "1-sigma of a first-order Gauss-Markov bias wander with correlation time bias_correlation_s "
                       "(what the replay simulates), not IEEE Std 952-1997's bias instability coefficient B (the "
                       "Allan-deviation floor, sigma_min = 0.664 B); a Gauss-Markov's Allan deviation peaks at "
                       "0.617 sigma at 1.89 correlation times (so B = 0.93 sigma for it)"}};
  json cells = json::array();
  for (const auto& g : d.gapMap)
    cells.push_back({{"channel", channelName(g.key.channel)}, {"quantity", quantityName(g.key)}, {"unit", unitName(g.key.unit)},
                     {"harmonic", g.key.harmonic}, {"axis", g.key.axis}, {"point", g.key.point},
                     {"segment", g.key.segment}, {"real", g.real}, {"sim_mean", g.simMean}, {"sim_std", g.simStd},
                     {"z", g.z}, {"z_after", g.zAfter}, {"heldout", g.heldOut},
                     {"informative", g.informative}});
  j["gap_map"] = cells;
  j["notes"] = d.notes;
  j["elapsed_s"] = d.elapsedS;
  return j.dump(2);
}

std::string formatDiagnosisText(const Diagnosis& d) {
  std::string s;
  char b[512];
  std::snprintf(b, sizeof b, "Sim-to-real diagnosis: %d gap-map cells, chi2 %.1f (%s)\n", d.cells, d.chiSquare,
                d.gapSignificant ? "significant gap" : "no significant gap");
  s += b;
  const auto& c = d.calibration;
  std::snprintf(b, sizeof b,
                "  replay calibrated to: lag %.4f ms, table frequency %+.2f ppm, encoder noise %.2g deg, ARW %.4f "
                "deg/sqrt(h), bias %+.3f/%+.3f/%+.3f deg/h,\n  z %s, heading %.1f +- %.1f deg, "
                "table every %.4f ms, IMU every %.4f ms, bias instability %.3g deg/h over %.0f s (%s)\n",
                c.lagMs, c.tableFrequencyErrorPpm, c.encoderNoiseDeg, c.arwDegPerSqrtH, c.biasDegPerH[0],
                c.biasDegPerH[1], c.biasDegPerH[2], c.frame.zUp ? "up" : "down", c.headingDeg, c.headingStdDeg, c.config.encoder.samplePeriodS * 1e3,
                c.config.imuBoard.framePeriodS * 1e3, c.config.fog.biasInstabilityDegPerH,
                c.config.fog.biasCorrelationS, c.biasInstabilityStated ? "stated" : "assumed");
  s += b;
  s += "\nTiming audit            real                         replay\n";
  auto line = [&](const char* name, const StreamTiming& r, const StreamTiming& m) {
    std::snprintf(b, sizeof b, "  %-6s interval  %+9.3f ppm, std %7.3f us, gaps %zu, dup %zu | %+9.3f ppm, std %7.3f us, gaps %zu\n",
                  name, r.intervalMeanPpm, r.intervalStdUs, r.gaps, r.duplicates, m.intervalMeanPpm, m.intervalStdUs, m.gaps);
    s += b;
  };
  line("table", d.realTiming.table, d.simTiming.table);
  line("imu", d.realTiming.imu, d.simTiming.imu);
  std::snprintf(b, sizeof b, "  lost %llu / %llu, duplicates %llu / %llu, wraps %llu / %llu, checksum failures %llu / %llu\n",
                (unsigned long long)d.realTiming.lostFrames, (unsigned long long)d.simTiming.lostFrames,
                (unsigned long long)d.realTiming.duplicateFrames, (unsigned long long)d.simTiming.duplicateFrames,
                (unsigned long long)d.realTiming.counterWraps, (unsigned long long)d.simTiming.counterWraps,
                (unsigned long long)d.realTiming.checksumFailures, (unsigned long long)d.simTiming.checksumFailures);
  s += b;
  s += "\nGap per channel (rms z; 1 = within the simulator's spread)    before   after   held-out shrink\n";
  for (int ch = 0; ch < kChannelCount; ++ch) {
    std::snprintf(b, sizeof b, "  %-12s %4d cells                                   %7.2f %7.2f   %5.0f %%\n",
                  channelName(static_cast<Channel>(ch)), d.gapBefore[static_cast<std::size_t>(ch)].cells,
                  d.gapBefore[static_cast<std::size_t>(ch)].rmsZ, d.gapAfter[static_cast<std::size_t>(ch)].rmsZ,
                  100.0 * d.heldOut[static_cast<std::size_t>(ch)].shrink);
    s += b;
  }
  std::vector<const GapCell*> worst;
  for (const auto& g : d.gapMap) worst.push_back(&g);
  std::sort(worst.begin(), worst.end(), [](const GapCell* a, const GapCell* b2) { return std::abs(a->z) > std::abs(b2->z); });
  s += "  largest cells:\n";
  for (std::size_t i = 0; i < std::min<std::size_t>(5, worst.size()); ++i) {
    const auto& g = *worst[i];
    std::snprintf(b, sizeof b, "    point %d segment %d %-10s %-30s axis %2d: real %.4g, replay %.4g +- %.3g %s (z %+.1f)\n",
                  g.key.point + 1, g.key.segment + 1, channelName(g.key.channel), quantityTitle(g.key).c_str(), g.key.axis,
                  g.real, g.simMean, g.simStd, unitName(g.key.unit), g.z);
    s += b;
  }
  s += "\nEffects, ranked (score = training delta chi2 - k ln n)\n";
  for (const auto& e : d.effects) {
    std::string params;
    for (std::size_t p = 0; p < e.parameters.size(); ++p) {
      std::snprintf(b, sizeof b, "%s%s %.4g +- %.2g %s", p ? ", " : "", e.parameters[p].name.c_str(), e.values[p],
                    e.standardErrors[p], e.parameters[p].unit.c_str());
      params += b;
    }
    char score[32] = "        -";  // no signature in this session
    if (e.score) std::snprintf(score, sizeof score, "%9.1f", *e.score);
    std::snprintf(b, sizeof b, "  %-26s score %s  held-out shrink %5.0f %%%s  %s\n", effectTitle(e.name).c_str(), score,
                  100.0 * e.heldOutShrink, e.kept ? "  KEPT" : "", params.c_str());
    s += b;
  }
  s += "\nAlias groups (swing data cannot separate these)\n";
  for (const auto& a : d.aliasGroups) {
    std::string m;
    for (const auto& x : a.members) m += (m.empty() ? "" : ", ") + x;
    s += "  " + a.name + ": " + m + "\n    " + a.value + "\n    to separate: " + a.separatingTest + "\n";
  }
  for (const auto& n : d.notes) s += "note: " + n + "\n";
  s += "\nVerdict: " + effectTitle(d.verdict);
  if (d.verdictEffects.size() > 1) s += " (+ " + effectTitle(d.verdictEffects[1]) + ")";
  s += " - " + d.verdictReason + "\n";
  std::snprintf(b, sizeof b, "(diagnosis took %.2f s)\n", d.elapsedS);
  s += b;
  return s;
}

}  // namespace fog::diagnosis
