#include "coinspect/core/config.h"

#include <gtest/gtest.h>

#include "coinspect/core/error.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect {

namespace {
using coinspect::testing::messageOf;
}  // namespace

TEST(Config, ReadsTypedValues) {
  const auto config = Config::fromText(
      "[mission]\nbudget = 600\nname = mbs\nrecord = yes\nstart = 1, 2.5, -3\n", "test.ini");
  EXPECT_EQ(config.getDouble("mission", "budget"), 600.0);
  EXPECT_EQ(config.getInt("mission", "budget"), 600);
  EXPECT_EQ(config.getString("mission", "name"), "mbs");
  EXPECT_TRUE(config.getBool("mission", "record"));
  EXPECT_EQ(config.getVector3("mission", "start"), Eigen::Vector3d(1, 2.5, -3));
  EXPECT_EQ(config.getDouble("mission", "absent", 4.0), 4.0);
  EXPECT_NO_THROW(config.requireAllKeysUsed());
}

TEST(Config, MalformedValueNamesFileSectionKeyAndText) {
  const auto config = Config::fromText("[mission]\nbudget = 6OO\n", "mission.ini");
  const auto message = messageOf([&] { config.getDouble("mission", "budget"); });
  EXPECT_NE(message.find("mission.ini"), std::string::npos) << message;
  EXPECT_NE(message.find("[mission] budget"), std::string::npos) << message;
  EXPECT_NE(message.find("6OO"), std::string::npos) << message;
  // A present but malformed value is an error even when a fallback exists.
  EXPECT_THROW(config.getDouble("mission", "budget", 1.0), InputError);
}

TEST(Config, MissingRequiredKeyAndNonFiniteNumbersAreErrors) {
  const auto config = Config::fromText("[a]\nx = nan\n", "a.ini");
  EXPECT_THROW(config.getDouble("a", "y"), InputError);
  EXPECT_THROW(config.getDouble("a", "x"), InputError);
  EXPECT_THROW(config.getVector3("a", "x"), InputError);
}

TEST(Config, UnknownKeysAreReported) {
  const auto config = Config::fromText("[mission]\nbudget = 600\nbugdet = 700\n", "m.ini");
  config.getDouble("mission", "budget");
  const auto message = messageOf([&] { config.requireAllKeysUsed(); });
  EXPECT_NE(message.find("[mission] bugdet"), std::string::npos) << message;
}

TEST(Config, LinesWithoutAssignmentAreRejectedWithTheirLineNumber) {
  const auto message = messageOf([] { Config::fromText("[a]\nx = 1\nthis is wrong\n", "f.ini"); });
  EXPECT_NE(message.find("f.ini: line 3"), std::string::npos) << message;
}

// The INI parser merges a repeated section and lets a repeated key's last value win, unseen
// (fuzzing: `budget = 5` then `budget = 7` flew 7 s). Both are errors naming both lines.
TEST(Config, KeysAndSectionsGivenTwiceAreRejectedWithBothLines) {
  const auto key = messageOf(
      [] { Config::fromText("[mission]\nbudget = 5\nscenario = x\nbudget = 7\n", "d.ini"); });
  EXPECT_NE(key.find("d.ini: line 4"), std::string::npos) << key;
  EXPECT_NE(key.find("[mission] budget given twice (first on line 2)"), std::string::npos) << key;
  const auto section = messageOf([] {
    Config::fromText("[mission]\nbudget = 5\n[strategy]\nname = a\n[ mission ]\n", "s.ini");
  });
  EXPECT_NE(section.find("s.ini: line 5"), std::string::npos) << section;
  EXPECT_NE(section.find("section [mission] given twice (first on line 1)"), std::string::npos)
      << section;
  // The same key in two sections, and keys before any section, stay fine.
  EXPECT_NO_THROW(Config::fromText("top = 1\n[a]\nx = 1\n[b]\nx = 2\n", "ok.ini"));
}

TEST(Config, OverridesReplaceAndAddValues) {
  auto config = Config::fromText("[mission]\nbudget = 600\n", "m.ini");
  config.applyOverride("mission.budget=120");
  config.applyOverride("scenario.name = crane");
  EXPECT_EQ(config.getDouble("mission", "budget"), 120.0);
  EXPECT_EQ(config.getString("scenario", "name"), "crane");
  EXPECT_THROW(config.applyOverride("budget=1"), InputError);
  EXPECT_THROW(config.applyOverride("mission.budget"), InputError);
}

TEST(Config, MissingFileIsAnInputError) {
  EXPECT_THROW(Config::fromFile("no/such/file.ini"), InputError);
}

}  // namespace coinspect
