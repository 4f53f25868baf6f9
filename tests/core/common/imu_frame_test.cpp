#include "core/common/imu_frame.h"

#include <gtest/gtest.h>

namespace fog {
namespace {

TEST(ImuFrame, EveryConventionStatesItsVerticalAndTheHeadingOfX) {
  struct Case {
    const char* text;
    bool zUp;
    std::optional<double> xHeading;
  } cases[] = {{"NED", false, 0.0},  {"enu", true, 90.0},    {"FRD", false, std::nullopt},
               {"FRD:30", false, 30.0}, {" rfu : -20 ", true, 70.0}, {"RFU", true, std::nullopt}};
  for (const auto& c : cases) {
    auto f = imuFrameFromText(c.text);
    ASSERT_TRUE(f.isOk()) << c.text << ": " << f.status().message();
    EXPECT_TRUE(f->stated());
    EXPECT_EQ(f->zUp(), c.zUp) << c.text;
    EXPECT_EQ(f->xHeadingDeg(), c.xHeading) << c.text;
    // The text form reads back to the same frame.
    EXPECT_EQ(*imuFrameFromText(imuFrameToText(*f)), *f) << c.text;
  }
  auto none = imuFrameFromText("");
  ASSERT_TRUE(none.isOk());
  EXPECT_FALSE(none->stated());
  EXPECT_EQ(imuFrameToText(*none), "");
  EXPECT_EQ(describeImuFrame(*none), "not stated");
  EXPECT_EQ(describeImuFrame(*imuFrameFromText("ENU")), "east-north-up (x east, y north, z up)");
}

TEST(ImuFrame, AnythingElseIsRefusedNamingTheAcceptedForms) {
  for (const char* bad : {"SWU", "NED:10", "ENU:0", "RFU:", "RFU:abc", "FRD:400", "FRD:nan", "FRD:1e400", "NEDX"}) {
    auto f = imuFrameFromText(bad);
    ASSERT_FALSE(f.isOk()) << bad;
    EXPECT_EQ(f.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(f.status().message().find("NED, ENU, FRD[:HEADING] or RFU[:HEADING]"), std::string::npos)
        << f.status().message();
  }
}

}  // namespace
}  // namespace fog
