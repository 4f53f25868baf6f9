// Text that enters the bench is made valid UTF-8 (common/text.h).

#include "core/common/text.h"

#include <gtest/gtest.h>

namespace fog {
namespace {

TEST(Text, ValidUtf8IsKeptAsItIs) {
  for (const char* s : {"", "plain", "Müller", "温度", "\xF0\x9F\x98\x80"}) {
    EXPECT_TRUE(isValidUtf8(s)) << s;
    EXPECT_EQ(toValidUtf8(s), s);
  }
}

TEST(Text, Latin1BytesAreConverted) {
  EXPECT_FALSE(isValidUtf8("M\xFCller"));
  EXPECT_EQ(toValidUtf8("M\xFCller"), "Müller");
  EXPECT_EQ(toValidUtf8("caf\xE9"), "café");
}

TEST(Text, MalformedSequencesBecomeValid) {
  // Overlong "/", a surrogate, beyond U+10FFFF, a cut sequence, a lone continuation byte.
  for (const char* s : {"\xC0\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80", "ab\xE2\x82", "\x80x"}) {
    EXPECT_FALSE(isValidUtf8(s)) << s;
    EXPECT_TRUE(isValidUtf8(toValidUtf8(s))) << s;
  }
}

}  // namespace
}  // namespace fog

namespace fog {
namespace {

TEST(Text, EscapeSequencesFromFilesNeverReachTheTerminal) {
  // An operator name that would retitle the window and clear the screen.
  EXPECT_EQ(forTerminal("A\x1b]0;owned\x07 B\x1b[2J"), "A\\x1B]0;owned\\x07 B\\x1B[2J");
  EXPECT_EQ(forTerminal("line 1\n\tline 2 ± 0.1 ms"), "line 1\n\tline 2 ± 0.1 ms");  // newline, tab, UTF-8 kept
  EXPECT_EQ(forTerminal("carriage\rreturn\x7f"), "carriage\\x0Dreturn\\x7F");
}

}  // namespace
}  // namespace fog
