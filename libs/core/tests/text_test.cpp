#include "coinspect/core/text.h"

#include <gtest/gtest.h>

namespace coinspect {

TEST(Text, ParsesOnlyWholeFiniteNumbers) {
  EXPECT_EQ(parseFiniteDouble(" 1.5 "), 1.5);
  EXPECT_EQ(parseFiniteDouble("-2e3"), -2000.0);
  EXPECT_FALSE(parseFiniteDouble("1.5m"));
  EXPECT_FALSE(parseFiniteDouble(""));
  EXPECT_FALSE(parseFiniteDouble("nan"));
  EXPECT_FALSE(parseFiniteDouble("inf"));
  EXPECT_FALSE(parseFiniteDouble("1e999"));
}

TEST(Text, ParsesIntegersAndBooleans) {
  EXPECT_EQ(parseInteger("42"), 42);
  EXPECT_EQ(parseInteger("+7"), 7);
  EXPECT_FALSE(parseInteger("4.2"));
  EXPECT_FALSE(parseInteger("x"));
  EXPECT_EQ(parseBool("Yes"), true);
  EXPECT_EQ(parseBool("off"), false);
  EXPECT_FALSE(parseBool("maybe"));
}

TEST(Text, SplitsAndTrims) {
  const auto tokens = splitTokens(" a, b ,,c  d ");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0], "a");
  EXPECT_EQ(tokens[3], "d");
}

TEST(Text, PrintableTextKeepsUtf8AndEscapesTheRest) {
  EXPECT_EQ(printableText("class 'CPose3D'\tok"), "class 'CPose3D'\tok");
  EXPECT_EQ(printableText("\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\x81"),
            "\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\x81");  // été € and a helicopter
  EXPECT_EQ(printableText(std::string("a\0b\n\x7f", 5)), "a\\x00b\\x0A\\x7F");
  // Stray continuation byte, truncated sequence, overlong form, surrogate, above U+10FFFF.
  EXPECT_EQ(printableText("\x90x"), "\\x90x");
  EXPECT_EQ(printableText("\xE2\x82"), "\\xE2\\x82");
  EXPECT_EQ(printableText("\xC0\xAF"), "\\xC0\\xAF");
  EXPECT_EQ(printableText("\xE0\x80\xAF"), "\\xE0\\x80\\xAF");
  EXPECT_EQ(printableText("\xED\xA0\x80"), "\\xED\\xA0\\x80");
  EXPECT_EQ(printableText("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");
  EXPECT_EQ(printableText(""), "");
}

}  // namespace coinspect
