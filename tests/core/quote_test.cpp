#include "animkit/core/quote.h"

#include <gtest/gtest.h>

#include <string>

namespace animkit {
namespace {

TEST(QuoteInput, PlainTextIsQuotedAsItIs) {
  EXPECT_EQ(quote_input("circle"), "'circle'");
  EXPECT_EQ(quote_input(""), "''");
}

TEST(QuoteInput, TerminalEscapesAndControlBytesAreShownNotSent) {
  EXPECT_EQ(quote_input("a\x1b[2Jb"), "'a\\x1b[2Jb'");
  EXPECT_EQ(quote_input("x\ny\tz\r"), "'x\\ny\\tz\\r'");
  EXPECT_EQ(quote_input(std::string("a\0b", 3)), "'a\\x00b'");
  EXPECT_EQ(quote_input("\x7f"), "'\\x7f'");
  // U+009B (CSI as a C1 control) is well-formed UTF-8 but escaped all the same.
  EXPECT_EQ(quote_input("\xc2\x9b"), "'\\u009b'");
}

TEST(QuoteInput, WellFormedUtf8IsKeptBrokenUtf8IsEscaped) {
  EXPECT_EQ(quote_input("Zoë 中"), "'Zoë 中'");
  EXPECT_EQ(quote_input("\xff\xfe"), "'\\xff\\xfe'");
  EXPECT_EQ(quote_input("\xc0\xaf"), "'\\xc0\\xaf'");           // overlong '/'
  EXPECT_EQ(quote_input("\xed\xa0\x80"), "'\\xed\\xa0\\x80'");  // a surrogate
  EXPECT_EQ(quote_input("\xe4\xb8"), "'\\xe4\\xb8'");           // cut short
}

TEST(QuoteInput, LongInputIsCutWithItsSize) {
  const std::string line(10'000'000, 'a');
  const std::string quoted = quote_input(line);
  EXPECT_EQ(quoted, "'" + std::string(kQuotedInputChars, 'a') + "...' (10000000 bytes)");
  EXPECT_EQ(quote_input("abcdef", 3), "'abc...' (6 bytes)");
  EXPECT_EQ(quote_input("abc", 3), "'abc'");
}

TEST(SanitizeMessage, KeepsTextEscapesControlsAndCuts) {
  EXPECT_EQ(sanitize_message("bad value\x1b]0;pwned\x07"), "bad value\\x1b]0;pwned\\x07");
  EXPECT_EQ(sanitize_message("abcdef", 4), "abcd... (cut)");
}

// An escape counts as the characters it shows: a budget of N characters is never exceeded,
// whatever the bytes (300 DEL bytes used to show as 1,200 characters).
TEST(SanitizeMessage, EscapesCountAgainstTheBudget) {
  const std::string dels(300, '\x7f');
  EXPECT_EQ(sanitize_message(dels, 10), "\\x7f\\x7f... (cut)");
  EXPECT_EQ(quote_input(dels, 12), "'\\x7f\\x7f\\x7f...' (300 bytes)");
  // A UTF-8 character counts as one.
  EXPECT_EQ(quote_input("\xc3\xa9\xc3\xa9\xc3\xa9", 3), "'\xc3\xa9\xc3\xa9\xc3\xa9'");
  EXPECT_EQ(quote_input("\xc3\xa9\xc3\xa9\xc3\xa9", 2), "'\xc3\xa9\xc3\xa9...' (6 bytes)");
}

// A long path keeps its start and its file name; escapes count against the budget there too.
TEST(ShownPath, ShortPathsAsTheyAreLongOnesKeepBothEnds) {
  EXPECT_EQ(shown_path("/tmp/scene.json"), "/tmp/scene.json");
  EXPECT_EQ(shown_path("/tmp/a\nb.obj"), "/tmp/a\\nb.obj");
  const std::string long_path = "/home/" + std::string(200, 'x') + "/drape.json";
  const std::string shown = shown_path(long_path, 30);
  EXPECT_EQ(shown, "/home/xxxx...xxxxxx/drape.json");
  EXPECT_LE(shown.size(), 30u);
  // 300 C1 controls would show as 1,800 characters; 4-byte characters count one each.
  std::string controls;
  for (int i = 0; i < 300; ++i) controls += "\xc2\x85";
  EXPECT_EQ(shown_path(controls, 13), "...\\u0085");
  std::string emoji;
  for (int i = 0; i < 300; ++i) emoji += "\xf0\x9f\x98\x80";
  EXPECT_EQ(shown_path(emoji, 30).size(), 4u * 27 + 3);
}

}  // namespace
}  // namespace animkit
