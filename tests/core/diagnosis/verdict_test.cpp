// The verdict rule on a gap map made by hand: what a kept model must close
// before it is named, alone or as a partial explanation.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/diagnosis/diagnosis_stages.h"
#include "core/diagnosis/effects.h"

namespace fog::diagnosis::detail {
namespace {

// 100 training and 100 held-out cells of the gyro channel, every one at
// z = 4 before: a held-out excess chi2 of 100 * 16 - 100 = 1500.
struct Case {
  Diagnosis d;
  std::vector<double> z0;
  std::vector<Candidate> cands;
  VerdictModel chosen;
};

Case caseWhereTheModelLeaves(double zAfter) {
  Case c;
  for (int i = 0; i < 200; ++i) {
    GapCell cell;
    cell.key.channel = Channel::kGyro;
    cell.key.segment = i % 2;
    cell.heldOut = i % 2 == 1;
    cell.z = 4.0;
    c.d.gapMap.push_back(cell);
    c.z0.push_back(4.0);
  }
  c.d.gapSignificant = true;
  Candidate cand;
  cand.lib = 0;
  cand.fit.name = "table_harmonic_distortion";
  cand.fit.values = {1.0};
  cand.fit.kept = true;
  c.cands.push_back(cand);
  c.chosen.members = {0};
  c.chosen.z.assign(200, zAfter);
  return c;
}

// z 4 -> 3.9: 1421 left of 1500, 5 % closed. Its held-out delta chi2 (79)
// kept it; it explains nothing.
TEST(Verdict, AKeptModelThatClosesLittleIsNotNamed) {
  auto c = caseWhereTheModelLeaves(3.9);
  decideVerdict(c.chosen, c.cands, c.z0, DiagnosisOptions{}, c.d);
  EXPECT_EQ(c.d.verdict, "unexplained");
  EXPECT_TRUE(c.d.verdictEffects.empty());
  EXPECT_NE(c.d.verdictReason.find("the best, table harmonic distortion, closes only 5 % of the held-out gap"),
            std::string::npos)
      << c.d.verdictReason;
  ASSERT_EQ(c.d.effects.size(), 1u);
  EXPECT_NE(c.d.effects[0].note.find("not named as a partial explanation"), std::string::npos);
}

// z 4 -> 1.5: 125 left of 1500 (92 % closed), still 6.3 sigma over 100
// cells: a partial explanation, named.
TEST(Verdict, AKeptModelThatClosesMostIsAPartialExplanation) {
  auto c = caseWhereTheModelLeaves(1.5);
  decideVerdict(c.chosen, c.cands, c.z0, DiagnosisOptions{}, c.d);
  EXPECT_EQ(c.d.verdict, "unexplained");
  ASSERT_EQ(c.d.verdictEffects.size(), 1u);
  EXPECT_EQ(c.d.verdictEffects[0], "table_harmonic_distortion");
  EXPECT_NE(c.d.verdictReason.find("closes 92 % of the held-out gap but leaves a significant remainder in the gyro"),
            std::string::npos)
      << c.d.verdictReason;
}

// z 4 -> 1: nothing left: the effect is the verdict.
TEST(Verdict, AKeptModelThatLeavesNoiseIsTheVerdict) {
  auto c = caseWhereTheModelLeaves(1.0);
  decideVerdict(c.chosen, c.cands, c.z0, DiagnosisOptions{}, c.d);
  EXPECT_EQ(c.d.verdict, "table_harmonic_distortion");
  EXPECT_EQ(c.d.verdictReason, "closes 100 % of the held-out gap");
}

// Blind check 1/98 (a flicker bias): the gyro channel's excess chi2 is 110
// over 80 cells (8.7 sigma), all 270 cells' only 91 (3.9 sigma: the table
// channel under-dispersed, -33): the gap is significant, in the gyro channel.
TEST(Verdict, AGapInOneChannelIsSignificantThoughTheOthersDiluteIt) {
  std::vector<ChannelGap> channels(3);
  channels[0].channel = Channel::kTable, channels[0].cells = 100, channels[0].chiSquare = 67.0;
  channels[1].channel = Channel::kGyro, channels[1].cells = 80, channels[1].chiSquare = 190.0;
  channels[2].channel = Channel::kGyroMinusTable, channels[2].cells = 90, channels[2].chiSquare = 104.0;
  const double all = 67.0 + 190.0 + 104.0;  // 361 over 270: excess 91, 3.9 sigma
  EXPECT_TRUE(gapIsSignificant(all, 270, channels, 5.0));
  channels[1].chiSquare = 130.0;  // excess 50: 4.0 sigma in the channel, 1.3 over all
  EXPECT_FALSE(gapIsSignificant(67.0 + 130.0 + 104.0, 270, channels, 5.0));
  EXPECT_TRUE(gapIsSignificant(400.0, 270, {}, 5.0));  // 130 over 270: 5.6 sigma
  EXPECT_FALSE(gapIsSignificant(0.0, 0, {}, 5.0));
}

// Paper 1/98 (a flicker bias): its 24 gyro trend cells carry an excess
// chi2 of 36 (5.2 sigma), the gyro channel's 40 other cells none, so the
// channel's 64 read 2.9 sigma and all cells less: significant only in the
// trend cells on their own.
TEST(Verdict, AWanderInTheGyroTrendsIsSignificantThoughTheChannelDilutesIt) {
  std::vector<GapCell> cells;
  auto add = [&](Channel channel, Quantity quantity, int n, double z) {
    for (int i = 0; i < n; ++i) {
      GapCell cell;
      cell.key.channel = channel;
      cell.key.quantity = quantity;
      cell.z = z;
      cells.push_back(cell);
    }
  };
  add(Channel::kGyro, Quantity::kTrend, 24, std::sqrt(60.0 / 24.0));
  add(Channel::kGyro, Quantity::kCrossInPhase, 40, std::sqrt(37.0 / 40.0));
  add(Channel::kTable, Quantity::kInPhase, 72, 1.0);
  const std::vector<ChannelGap> channels = channelGaps(cells, false);
  double all = 0.0;
  for (const auto& c : cells) all += c.z * c.z;
  const int n = static_cast<int>(cells.size());
  EXPECT_FALSE(gapIsSignificant(all, n, channels, 5.0));  // gyro channel: excess 33 over 64, 2.9 sigma
  const std::vector<ChannelGap> groups = significanceGroups(cells, channels);
  ASSERT_EQ(groups.size(), channels.size() + 1);
  EXPECT_EQ(groups.back().cells, 24);
  EXPECT_NEAR(groups.back().chiSquare, 60.0, 1e-9);
  EXPECT_TRUE(gapIsSignificant(all, n, groups, 5.0));
  // At 4 sigma in the trends (excess 28) it stays quiet.
  for (auto& c : cells)
    if (c.key.quantity == Quantity::kTrend) c.z = std::sqrt(52.0 / 24.0);
  EXPECT_FALSE(gapIsSignificant(all - 8.0, n, significanceGroups(cells, channelGaps(cells, false)), 5.0));
}

}  // namespace
}  // namespace fog::diagnosis::detail
