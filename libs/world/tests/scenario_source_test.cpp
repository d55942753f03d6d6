#include "coinspect/world/scenario_source.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/scenario_files.h"

namespace coinspect::world {
namespace {

namespace fs = std::filesystem;
using coinspect::testing::messageOf;
using coinspect::testing::scratchDir;

// Runs the test body from `folder` (relative sources are looked up from the working folder) and
// goes back, whatever happens.
class InFolder {
 public:
  explicit InFolder(const fs::path& folder) : previous_(fs::current_path()) {
    fs::current_path(folder);
  }
  ~InFolder() { fs::current_path(previous_); }

 private:
  fs::path previous_;
};

TEST(ScenarioSource, AGeneratorNameIsTheGeneratorEvenBesideAFolderOfThatName) {
  // `coinspect run mission.ini --out slei-a` leaves a folder named slei-a: the next run, or a
  // replay, from the same folder must still fly the generated slei-a.
  const fs::path dir = scratchDir("scenario_source_shadow");
  fs::create_directories(dir / "slei-a");
  const InFolder here(dir);
  EXPECT_TRUE(isGeneratorName("slei-a"));
  EXPECT_EQ(loadScenarioSource("slei-a", 2).contentHash(),
            generateScenario("slei-a", 2).contentHash());
  // The folder itself is reached with a path, and it holds no scenario.
  const std::string message = messageOf([] { loadScenarioSource("./slei-a", 2); });
  EXPECT_MENTIONS(message, "./slei-a");
  EXPECT_MENTIONS(message, "holds neither box_description.yaml (CARIC) nor scenario.ini");
}

TEST(ScenarioSource, AFolderOrItsScenarioFileIsOurFormat) {
  const fs::path dir = scratchDir("scenario_source_files");
  const Scenario generated = generateScenario("slei-a", 1);
  saveScenario(generated, dir / "scene");
  EXPECT_FALSE(isGeneratorName((dir / "scene").string()));
  EXPECT_EQ(loadScenarioSource((dir / "scene").string(), 7).contentHash(), generated.contentHash());
  EXPECT_EQ(loadScenarioSource((dir / "scene" / "scenario.ini").string(), 7).contentHash(),
            generated.contentHash());
  // A fleet size resizes a generated scene; the files are what they are.
  const std::string fleet = messageOf([&] {
    loadScenarioSource((dir / "scene").string(), 1, SleiFleet{1, 1, 1});
  });
  EXPECT_MENTIONS(fleet, "only for a generated slei-* scenario");
}

TEST(ScenarioSource, NeitherAPathNorAGeneratorNamesTheOriginAndTheKnownNames) {
  const std::string message =
      messageOf([] { loadScenarioSource("slei-z", 1, {}, "mission.ini", "[mission] scenario"); });
  EXPECT_MENTIONS(message, "mission.ini");
  EXPECT_MENTIONS(message, "[mission] scenario");
  EXPECT_MENTIONS(message, "slei-z is neither a file, a folder nor a generator");
  EXPECT_MENTIONS(message, "slei-c");
}

}  // namespace
}  // namespace coinspect::world
