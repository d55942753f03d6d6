#include "coinspect/record/run_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "coinspect/testing/files.h"

namespace coinspect::record {

namespace {

RunReport sampleReport() {
  RunReport r;
  r.configFile = "config/quick.ini";
  r.config["mission"]["seed"] = "7";
  r.config["strategy"]["name"] = "demo";
  r.scenario = "slei-b";
  r.strategy = "demo";
  r.seed = 7;
  r.scoring = "caric";
  r.score = 12.5;
  r.detected = 20;
  r.totalPoints = 150;
  RunReportUnit unit;
  unit.name = "jurong";
  unit.role = "explorer";
  unit.alive = false;
  unit.deathCause = "collision";
  unit.distanceFlown = 42.25;
  unit.captures = 100;
  unit.detected = 15;
  unit.ownScore = 9.5;
  unit.rejectedCommands = 3;
  r.units.push_back(unit);
  r.collisions = 1;
  r.deaths = 1;
  r.messagesSent = 10;
  r.messagesDelivered = 8;
  r.messagesDropped = 2;
  r.keyFrames = 5;
  r.keyFramesDelivered = 4;
  r.started = true;
  r.startTime = 0.5;
  r.missionTime = 19.5;
  r.budget = 20;
  r.simTime = 20;
  r.timing.wallTime = 1.25;
  r.timing.realTimeFactor = 16;
  r.timing.stages["physics"] = 0.75;
  r.runMode = "realtime";
  r.realtimeFactor = 2;
  r.timing.decisions = 40;
  r.timing.threads = 2;
  r.timing.decisionTimeMean = 0.5e-3;
  r.timing.decisionTimeMax = 2e-3;
  return r;
}

}  // namespace

TEST(RunReport, HasEveryField) {
  const auto json = nlohmann::json::parse(runReportJson(sampleReport()));
  EXPECT_EQ(json["config"]["file"], "config/quick.ini");
  EXPECT_EQ(json["config"]["values"]["mission"]["seed"], "7");
  EXPECT_EQ(json["scenario"], "slei-b");
  EXPECT_EQ(json["strategy"], "demo");
  EXPECT_EQ(json["seed"], 7);
  EXPECT_EQ(json["scoring"], "caric");
  EXPECT_EQ(json["score"], 12.5);
  EXPECT_EQ(json["detected"], 20);
  EXPECT_EQ(json["total_points"], 150);
  ASSERT_EQ(json["units"].size(), 1u);
  const auto& unit = json["units"][0];
  EXPECT_EQ(unit["name"], "jurong");
  EXPECT_EQ(unit["role"], "explorer");
  EXPECT_EQ(unit["alive"], false);
  EXPECT_EQ(unit["death_cause"], "collision");
  EXPECT_EQ(unit["distance_flown"], 42.25);
  EXPECT_EQ(unit["captures"], 100);
  EXPECT_EQ(unit["detected"], 15);
  EXPECT_EQ(unit["own_score"], 9.5);
  EXPECT_EQ(unit["rejected_commands"], 3);
  EXPECT_EQ(json["collisions"], 1);
  EXPECT_EQ(json["deaths"], 1);
  EXPECT_EQ(json["messages"]["sent"], 10);
  EXPECT_EQ(json["messages"]["delivered"], 8);
  EXPECT_EQ(json["messages"]["dropped"], 2);
  EXPECT_EQ(json["messages"]["key_frames"], 5);
  EXPECT_EQ(json["messages"]["key_frames_delivered"], 4);
  EXPECT_EQ(json["clock"]["started"], true);
  EXPECT_EQ(json["clock"]["start_time"], 0.5);
  EXPECT_EQ(json["clock"]["mission_time"], 19.5);
  EXPECT_EQ(json["clock"]["budget"], 20.0);
  EXPECT_EQ(json["clock"]["sim_time"], 20.0);
  EXPECT_EQ(json["timing"]["wall_time"], 1.25);
  EXPECT_EQ(json["timing"]["real_time_factor"], 16.0);
  EXPECT_EQ(json["timing"]["stages"]["physics"], 0.75);
  EXPECT_EQ(json["run_mode"]["mode"], "realtime");
  EXPECT_EQ(json["run_mode"]["realtime_factor"], 2.0);
  EXPECT_EQ(json["timing"]["decisions"], 40);
  EXPECT_EQ(json["timing"]["threads"], 2);
  EXPECT_EQ(json["timing"]["decision_time_mean"], 0.5e-3);
  EXPECT_EQ(json["timing"]["decision_time_max"], 2e-3);
  EXPECT_EQ(json.size(), 15u);  // nothing else at the top level
}

TEST(RunReport, FeaturesOnlyWhenGivenWithANullFinishTimeWhenUnfinished) {
  RunReport r = sampleReport();
  EXPECT_FALSE(nlohmann::json::parse(runReportJson(r)).contains("features"));
  RunReportFeatures f;
  f.total = 150;
  f.discovered = 3;
  f.collected = 1;
  f.finishRate = 1.0 / 150.0;
  f.meetings = {{"gcs_explorer", 2}, {"explorer_inspector", 5}, {"other", 0}};
  f.punctuality = {{"on_time", 3}, {"early", 4}, {"late", 1}, {"missed", 0}, {"rescheduled", 2}};
  f.timeline = {{"discovered", {1.0, 2.5, 2.5}}, {"collected", {9.0}}};
  RunReportFeatureUnit unit;
  unit.name = "jurong";
  unit.activitySeconds = {{"exploring", 15.0}, {"waiting", 4.5}};
  unit.idleSeconds = 4.5;
  unit.held = 1;
  f.units.push_back(unit);
  r.features = f;
  auto json = nlohmann::json::parse(runReportJson(r)).at("features");
  EXPECT_EQ(json.at("total"), 150);
  EXPECT_TRUE(json.at("finish_time").is_null());
  EXPECT_EQ(json.at("meetings").at("explorer_inspector"), 5);
  EXPECT_EQ(json.at("punctuality").at("on_time"), 3);
  EXPECT_EQ(json.at("punctuality").at("rescheduled"), 2);
  EXPECT_EQ(json.at("timeline").at("discovered").size(), 3u);
  EXPECT_EQ(json.at("timeline").at("collected")[0], 9.0);
  EXPECT_EQ(json.at("units")[0].at("activity_seconds").at("waiting"), 4.5);
  EXPECT_EQ(json.at("units")[0].at("idle_seconds"), 4.5);
  r.features->finishTime = 812.5;
  json = nlohmann::json::parse(runReportJson(r)).at("features");
  EXPECT_EQ(json.at("finish_time"), 812.5);
}

TEST(RunReport, TextIsSortedAndEqualForEqualReports) {
  const auto text = runReportJson(sampleReport());
  EXPECT_EQ(text, runReportJson(sampleReport()));
  // Sorted keys: "clock" comes before "collisions", "scenario" before "score".
  EXPECT_LT(text.find("\"clock\""), text.find("\"collisions\""));
  EXPECT_LT(text.find("\"scenario\""), text.find("\"score\""));
  // Only the timing object differs between two runs of the same mission.
  auto other = sampleReport();
  other.timing.wallTime = 3.0;
  auto a = nlohmann::json::parse(text), b = nlohmann::json::parse(runReportJson(other));
  EXPECT_NE(a, b);
  a.erase("timing");
  b.erase("timing");
  EXPECT_EQ(a, b);
}

// A config file named in Latin-1 (or a value with such a byte) must not cost the report at the
// end of a mission: nlohmann::json throws on invalid UTF-8 unless told to replace it.
TEST(RunReport, BytesThatAreNotUtf8AreReplacedNotFatal) {
  auto r = sampleReport();
  r.configFile = "config/c\xF6nfig.ini";
  r.config["mission"]["note"] = "\x90";
  std::string text;
  ASSERT_NO_THROW(text = runReportJson(r));
  const auto json = nlohmann::json::parse(text);
  EXPECT_EQ(json["config"]["file"], "config/c\xEF\xBF\xBDnfig.ini");  // U+FFFD
  EXPECT_EQ(json["config"]["values"]["mission"]["note"], "\xEF\xBF\xBD");
}

TEST(RunReport, WritesTheFile) {
  const auto path = std::filesystem::temp_directory_path() / "coinspect_run_report_test.json";
  writeRunReportJson(path, sampleReport());
  EXPECT_EQ(testing::readFile(path), runReportJson(sampleReport()));
}

}  // namespace coinspect::record
