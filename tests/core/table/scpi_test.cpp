#include "core/table/scpi.h"

#include <gtest/gtest.h>

namespace fog::table::scpi {
namespace {

TEST(Scpi, ParsesACommandWithArguments) {
  auto c = parseLine("axis:x:swing 0.1, 10 ,0\r\n");
  ASSERT_TRUE(c.isOk()) << c.status().message();
  EXPECT_EQ(c->keywords, (std::vector<std::string>{"AXIS", "X", "SWING"}));
  EXPECT_FALSE(c->query);
  EXPECT_EQ(c->args, (std::vector<std::string>{"0.1", "10", "0"}));
  EXPECT_TRUE(matches(*c, "AXIS:#:SWING"));
  EXPECT_FALSE(matches(*c, "AXIS:#:POSition"));
}

TEST(Scpi, ParsesQueriesCommonCommandsAndShortForms) {
  auto idn = parseLine("*IDN?");
  ASSERT_TRUE(idn.isOk());
  EXPECT_TRUE(idn->query);
  EXPECT_TRUE(matches(*idn, "*IDN"));
  auto err = parseLine("SYST:ERR?");
  ASSERT_TRUE(err.isOk());
  EXPECT_TRUE(matches(*err, "SYSTem:ERRor[:NEXT]"));
  auto longForm = parseLine(":system:error:next?");
  ASSERT_TRUE(longForm.isOk());
  EXPECT_TRUE(matches(*longForm, "SYSTem:ERRor[:NEXT]"));
  auto wrong = parseLine("SYS:ERR?");  // neither the long nor the short form
  ASSERT_TRUE(wrong.isOk());
  EXPECT_FALSE(matches(*wrong, "SYSTem:ERRor[:NEXT]"));
  auto axisW = parseLine("AXIS:W:POS?");
  ASSERT_TRUE(axisW.isOk());
  EXPECT_FALSE(matches(*axisW, "AXIS:#:POSition"));
}

TEST(Scpi, RefusesMalformedLines) {
  EXPECT_FALSE(parseLine("").isOk());
  EXPECT_FALSE(parseLine("   ").isOk());
  EXPECT_FALSE(parseLine("AXIS::X?").isOk());
  EXPECT_FALSE(parseLine("AXIS:X?:POS").isOk());
  EXPECT_FALSE(parseLine("AXIS:X:SWING 1,,2").isOk());
  EXPECT_FALSE(parseLine(std::string("AXIS\x01:X")).isOk());
  EXPECT_FALSE(parseLine(std::string(300, 'A')).isOk());
  EXPECT_FALSE(parseLine("AX$S:X").isOk());
}

TEST(Scpi, NumbersAreDecimalAndFinite) {
  EXPECT_DOUBLE_EQ(number("-1.5e-3").value(), -1.5e-3);
  EXPECT_FALSE(number("inf").isOk());
  EXPECT_FALSE(number("nan").isOk());
  EXPECT_FALSE(number("0x10").isOk());
  EXPECT_FALSE(number("1.0abc").isOk());
  EXPECT_FALSE(number("").isOk());
  EXPECT_FALSE(number("1e999").isOk());
}

TEST(Scpi, ErrorRepliesRoundTrip) {
  const auto text = formatError(-113, "Undefined header; say \"hi\"");
  EXPECT_EQ(text, "-113,\"Undefined header; say \"\"hi\"\"\"");
  auto e = parseError(text);
  ASSERT_TRUE(e.isOk()) << e.status().message();
  EXPECT_EQ(e->code, -113);
  EXPECT_EQ(e->text, "Undefined header; say \"hi\"");
  EXPECT_EQ(parseError("0,\"No error\"")->code, 0);
  EXPECT_FALSE(parseError("garbage").isOk());
  EXPECT_FALSE(parseError("1.5,\"x\"").isOk());
  EXPECT_FALSE(parseError("-113,Undefined").isOk());
}

TEST(Scpi, NumbersReplyNeedsTheRightCount) {
  auto v = numbers("45,20,400,3000,180", 5);
  ASSERT_TRUE(v.isOk());
  EXPECT_DOUBLE_EQ((*v)[4], 180.0);
  EXPECT_FALSE(numbers("45,20,400", 5).isOk());
  EXPECT_FALSE(numbers("45,20,x,3000,180", 5).isOk());
}

}  // namespace
}  // namespace fog::table::scpi
