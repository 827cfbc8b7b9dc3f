#include "animkit/core/utf8.h"

#include <gtest/gtest.h>

namespace animkit {
namespace {

TEST(Utf8, DecodesEveryLength) {
  const auto decoded = decode_utf8("A\xc3\xa9\xe4\xb8\xad\xf0\x9f\x98\x80");
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, (std::vector<char32_t>{U'A', U'\u00e9', U'\u4e2d', U'\U0001F600'}));
  EXPECT_EQ(encode_utf8(*decoded), "A\xc3\xa9\xe4\xb8\xad\xf0\x9f\x98\x80");
  EXPECT_EQ(decode_utf8("")->size(), 0u);
}

TEST(Utf8, RefusesMalformedBytes) {
  for (const std::string bad :
       {"\xff", "\x80", "\xc0\x8a", "\xe0\x80\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80",
        "\xf5\x80\x80\x80", "\xe4\xb8", "A\xc3", "\xf0\x9f\x98"}) {
    EXPECT_FALSE(decode_utf8(bad)) << testing::PrintToString(bad);
  }
}

}  // namespace
}  // namespace animkit
