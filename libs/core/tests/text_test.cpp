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

}  // namespace coinspect
