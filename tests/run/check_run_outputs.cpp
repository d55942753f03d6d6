// Checks the side outputs of `coinspect run --out DIR` against each other and the printed
// summary: score.csv rows and total, one 20 Hz TUM file per unit, report.json.
// Usage: check_run_outputs <out folder> <printed log>; exit 1 with a message on the first problem.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "coinspect/record/score_csv.h"
#include "coinspect/record/tum_trajectory.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "check_run_outputs: %s\n", message.c_str());
  return 1;
}

std::string firstLine(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// The Q of the printed summary line "score       Q = 37.70".
double printedScore(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    const auto at = line.find("Q = ");
    if (line.rfind("score", 0) == 0 && at != std::string::npos)
      return std::stod(line.substr(at + 4));
  }
  return std::nan("");
}

// Feature missions: the counts, the timeline curves, the finish rate and the units' activity
// seconds agree with each other and with the mission clock. Returns an error or "".
std::string checkFeatures(const nlohmann::json& report) {
  const auto& f = report.at("features");
  const size_t total = f.at("total");
  for (const char* stage : {"discovered", "assigned", "inspected", "collected"}) {
    const auto& times = f.at("timeline").at(stage);
    if (times.size() != f.at(stage).get<size_t>() || times.size() > total)
      return std::string("features timeline of ") + stage + " disagrees with its count";
    for (size_t i = 1; i < times.size(); ++i)
      if (times[i].get<double>() < times[i - 1].get<double>())
        return std::string("features timeline of ") + stage + " not ascending";
  }
  for (const char* outcome : {"on_time", "early", "late", "missed", "rescheduled"})
    if (!f.at("punctuality").at(outcome).is_number_unsigned())
      return std::string("features punctuality lacks ") + outcome;
  const double collected = f.at("collected");
  if (std::abs(f.at("finish_rate").get<double>() - collected / static_cast<double>(total)) > 1e-12)
    return "features finish_rate is not collected / total";
  if (f.at("finish_time").is_null() != (collected < static_cast<double>(total)))
    return "features finish_time present without every feature collected, or missing";
  // Every unit alive to the end spent the whole mission clock in some activity.
  const double missionTime = report.at("clock").at("mission_time");
  for (size_t i = 0; i < f.at("units").size(); ++i) {
    if (!report.at("units")[i].at("alive").get<bool>()) continue;
    double seconds = 0.0;
    for (const auto& [activity, s] : f.at("units")[i].at("activity_seconds").items())
      seconds += s.get<double>();
    if (std::abs(seconds - missionTime) > 1e-6)
      return "activity seconds of unit " + std::to_string(i) + " sum to " +
             std::to_string(seconds) + ", not the mission time " + std::to_string(missionTime);
  }
  return "";
}

int check(const std::filesystem::path& folder, const std::filesystem::path& log) {
  std::ifstream reportFile(folder / "report.json");
  const auto report = nlohmann::json::parse(reportFile);
  const double score = report.at("score");
  const size_t detected = report.at("detected");
  const size_t totalPoints = report.at("total_points");
  const double simTime = report.at("clock").at("sim_time");

  // The summary prints Q to 2 decimals.
  const double printed = printedScore(log);
  if (!(std::abs(printed - score) <= 0.005 + 1e-9))
    return fail("report.json score " + std::to_string(score) + " vs printed Q " +
                std::to_string(printed));

  if (firstLine(folder / "score.csv") != "x, y, z, nx, ny, nz, score, idx")
    return fail("score.csv header");
  const auto rows = coinspect::record::readCaricScoreCsv(folder / "score.csv");
  if (rows.size() != detected)
    return fail("score.csv has " + std::to_string(rows.size()) + " rows, " +
                std::to_string(detected) + " points detected");
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].index >= totalPoints || (i > 0 && rows[i].index <= rows[i - 1].index))
      return fail("score.csv idx not ascending within the point count at row " + std::to_string(i));
    if (!(rows[i].score > 0.0f && rows[i].score <= 1.0f))
      return fail("score.csv score outside (0, 1] at row " + std::to_string(i));
  }
  if (!(std::abs(coinspect::record::totalScore(rows) - score) <= 1e-3))
    return fail("score.csv total " + std::to_string(coinspect::record::totalScore(rows)) +
                " vs Q " + std::to_string(score));

  // Poses at every controller tick, t = 0, 0.05, ... up to the simulated time.
  const size_t expectedPoses = static_cast<size_t>(std::floor(simTime / 0.05 + 1e-6)) + 1;
  const auto& units = report.at("units");
  if (units.empty()) return fail("report.json has no units");
  for (const auto& unit : units) {
    const std::string name = unit.at("name");
    const auto poses = coinspect::record::readTumTrajectory(folder / (name + ".tum"));
    if (poses.size() != expectedPoses)
      return fail(name + ".tum has " + std::to_string(poses.size()) + " poses, expected " +
                  std::to_string(expectedPoses));
    for (size_t i = 0; i < poses.size(); ++i) {
      const double norm = std::sqrt(poses[i].qx * poses[i].qx + poses[i].qy * poses[i].qy +
                                    poses[i].qz * poses[i].qz + poses[i].qw * poses[i].qw);
      if (std::abs(poses[i].time - 0.05 * static_cast<double>(i)) > 1e-6 ||
          std::abs(norm - 1.0) > 1e-6)
        return fail(name + ".tum line " + std::to_string(i + 1) + ": time or quaternion");
    }
  }
  if (report.contains("features"))
    if (const auto problem = checkFeatures(report); !problem.empty()) return fail(problem);
  std::printf("outputs ok: %zu score rows, total %.6f, %zu units x %zu poses\n", rows.size(), score,
              units.size(), expectedPoses);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: check_run_outputs <out folder> <printed log>");
  try {
    return check(argv[1], argv[2]);
  } catch (const std::exception& error) {
    return fail(error.what());
  }
}
