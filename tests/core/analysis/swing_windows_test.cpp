// Windows given by the user (`import --segment START-END,...`): every number
// is read whole, so an exponent's dash is never taken for the separator.

#include <gtest/gtest.h>

#include "core/analysis/swing_windows.h"

namespace fog::analysis {
namespace {

TEST(ParseSwingWindows, ReadsPlainWindows) {
  auto w = parseSwingWindows("4-32,44.5-70");
  ASSERT_TRUE(w.isOk()) << w.status().toString();
  ASSERT_EQ(w->size(), 2u);
  EXPECT_EQ((*w)[0].startS, 4.0);
  EXPECT_EQ((*w)[0].endS, 32.0);
  EXPECT_EQ((*w)[1].startS, 44.5);
  EXPECT_EQ((*w)[1].endS, 70.0);
}

// "1e-300-2e-300" was read as 1-300 s: from_chars stopped at the "e" of "1e".
TEST(ParseSwingWindows, ExponentsAndNegativeTimesAreReadWhole) {
  auto tiny = parseSwingWindows("1e-300-2e-300");
  ASSERT_TRUE(tiny.isOk()) << tiny.status().toString();
  EXPECT_EQ(tiny->at(0).startS, 1e-300);
  EXPECT_EQ(tiny->at(0).endS, 2e-300);
  auto exp = parseSwingWindows("1e1-2.5E1");
  ASSERT_TRUE(exp.isOk());
  EXPECT_EQ(exp->at(0).startS, 10.0);
  EXPECT_EQ(exp->at(0).endS, 25.0);
  auto negative = parseSwingWindows("-5--2,-1-3");
  ASSERT_TRUE(negative.isOk()) << negative.status().toString();
  EXPECT_EQ(negative->at(0).startS, -5.0);
  EXPECT_EQ(negative->at(0).endS, -2.0);
  EXPECT_EQ(negative->at(1).startS, -1.0);
  EXPECT_EQ(negative->at(1).endS, 3.0);
}

TEST(ParseSwingWindows, AnythingNotReadWholeIsRefused) {
  for (const char* bad : {"1e-5", "1e", "1-2x", "1-2,", "5-4", "1-3,2-4", "nan-2", "1-inf", "0-1e300", "1 - 2", ""}) {
    auto w = parseSwingWindows(bad);
    EXPECT_FALSE(w.isOk()) << "'" << bad << "' read as " << (w.isOk() && !w->empty() ? w->at(0).startS : 0.0);
    if (!w.isOk()) {
      EXPECT_NE(w.status().message().find("--segment takes"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace fog::analysis
