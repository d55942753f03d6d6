// `coinspect scenario`: list the built-in generators, generate a scenario into a folder, describe
// any scenario source, export its geometry and interest points for other tools, and estimate the
// score that views keeping a clearance from its structure can reach (bound).
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "coinspect/eval/view_bound.h"
#include "coinspect/world/caric_formats.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/mesh_io.h"
#include "coinspect/world/ray_caster.h"
#include "coinspect/world/scenario_files.h"
#include "coinspect/world/scenario_source.h"
#include "commands.h"
#include "option_checks.h"

namespace coinspect::app {
namespace {

namespace fs = std::filesystem;

struct ScenarioOptions {
  std::string name;
  std::string source;
  uint64_t seed = 1;
  std::string out;
  std::string mesh;
  std::string points;
  std::string clearances = "0,1,2,3";
  std::string csv;
  std::string mode = "caric";
};

const char* const kSourceHelp =
    "Scenario: a generator name (see `coinspect scenario list`), a scenario.ini file or its "
    "folder, or a reference CARIC folder (holding box_description.yaml)";

std::string lowerExtension(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

double medianNearestNeighbour(const world::InterestPointSet& points) {
  if (points.size() < 2) return std::nan("");
  std::vector<double> distances(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    distances[i] = points.nearestNeighbourDistance(i);
  const auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), middle, distances.end());
  return *middle;
}

void runList() {
  for (const auto& info : world::scenarioGenerators())
    std::printf("%-14s %-6s %s\n", info.name.c_str(), info.family.c_str(),
                info.description.c_str());
}

void runGenerate(const ScenarioOptions& options) {
  const world::Scenario scenario = world::generateScenario(options.name, options.seed);
  world::saveScenario(scenario, options.out);
  std::printf("wrote %s (%zu triangles, %zu boxes, %zu interest points, hash %016" PRIx64 ")\n",
              (fs::path(options.out) / "scenario.ini").string().c_str(), scenario.triangleCount(),
              scenario.boxes.size(), scenario.interestPoints.size(), scenario.contentHash());
}

void runInfo(const ScenarioOptions& options) {
  const world::Scenario s = world::loadScenarioSource(options.source, options.seed);
  std::printf("name: %s\n", s.name.c_str());
  if (!s.description.empty()) std::printf("description: %s\n", s.description.c_str());
  std::printf("triangles: %zu in %zu meshes\n", s.triangleCount(), s.meshes.size());
  const world::Aabb bounds = s.bounds();
  if (!bounds.empty()) {
    const world::Vec3 size = bounds.size();
    std::printf("extent: %.1f x %.1f x %.1f m, from (%.1f, %.1f, %.1f) to (%.1f, %.1f, %.1f)\n",
                size.x(), size.y(), size.z(), bounds.min.x(), bounds.min.y(), bounds.min.z(),
                bounds.max.x(), bounds.max.y(), bounds.max.z());
  }
  std::printf("ground: z = %.2f m\n", s.groundZ);
  std::printf("boxes: %zu\n", s.boxes.size());
  for (const auto& box : s.boxes) {
    const double yaw = std::atan2(box.rotation(1, 0), box.rotation(0, 0)) * 180.0 / M_PI;
    std::printf("  %-14s center (%.2f, %.2f, %.2f)  size (%.2f, %.2f, %.2f)  yaw %.1f deg\n",
                box.name.c_str(), box.center.x(), box.center.y(), box.center.z(), box.size.x(),
                box.size.y(), box.size.z(), yaw);
  }
  std::printf("interest points: %zu, median nearest-neighbour spacing %.3f m\n",
              s.interestPoints.size(), medianNearestNeighbour(s.interestPoints));
  std::printf("fleet: %zu units\n", s.fleet.size());
  for (const auto& unit : s.fleet)
    std::printf("  %-12s %-12s start (%.2f, %.2f, %.2f)  r_des %.2f mm/px\n", unit.name.c_str(),
                world::toString(unit.role), unit.startPosition.x(), unit.startPosition.y(),
                unit.startPosition.z(), unit.camera.desiredMmPerPixel);
  std::printf("budget: %.0f s\n", s.missionBudget);
  std::printf("content hash: %016" PRIx64 "\n", s.contentHash());
}

void runExport(const ScenarioOptions& options) {
  if (options.mesh.empty() && options.points.empty())
    throw InputError("scenario export", "", "nothing to export: give --mesh and/or --points");
  // Check both extensions before the (possibly slow) load, so a typo fails at once.
  const std::string meshExtension = lowerExtension(options.mesh);
  const std::string pointsExtension = lowerExtension(options.points);
  if (!options.mesh.empty() && meshExtension != ".stl" && meshExtension != ".ply")
    throw InputError(options.mesh, "--mesh", "unknown mesh format (use .stl or .ply)");
  if (!options.points.empty() && pointsExtension != ".pcd" && pointsExtension != ".csv")
    throw InputError(options.points, "--points", "unknown point format (use .pcd or .csv)");

  const world::Scenario s = world::loadScenarioSource(options.source, options.seed);
  if (!options.mesh.empty()) {
    world::TriangleMesh all;
    all.name = s.name;
    for (const auto& mesh : s.meshes)
      all.append(mesh);
    if (meshExtension == ".stl")
      world::writeStl(all, options.mesh);
    else
      world::writePly(all, options.mesh);
    std::printf("wrote %s (%zu triangles)\n", options.mesh.c_str(), all.triangleCount());
  }
  if (!options.points.empty()) {
    if (pointsExtension == ".pcd")
      world::writeCaricInterestPoints(s.interestPoints.points(), options.points);
    else
      world::exportInterestPointsCsv(s.interestPoints, options.points);
    std::printf("wrote %s (%zu interest points)\n", options.points.c_str(),
                s.interestPoints.size());
  }
}

std::vector<double> parseClearances(const std::string& text) {
  std::vector<double> values;
  for (const std::string& field : splitTokens(text, ",")) {
    const auto value = parseFiniteDouble(field);
    if (!value || *value < 0.0)
      throw InputError("scenario bound", "--clearance",
                       "'" + field + "' is not a distance >= 0 (metres, comma-separated)");
    values.push_back(*value);
  }
  if (values.empty()) throw InputError("scenario bound", "--clearance", "needs at least one value");
  return values;
}

// idx,x,y,z,best_<clearance>...: each point's best score over the views of each clearance.
void writeBoundCsv(std::FILE* out, const std::string& path, const world::InterestPointSet& points,
                   const std::vector<double>& clearances,
                   const std::vector<std::vector<double>>& best) {
  std::fprintf(out, "idx,x,y,z");
  for (const double c : clearances)
    std::fprintf(out, ",best_%g", c);
  std::fprintf(out, "\n");
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i].position;
    std::fprintf(out, "%zu,%.4f,%.4f,%.4f", i, p.x(), p.y(), p.z());
    for (const auto& column : best)
      std::fprintf(out, ",%.4f", column[i]);
    std::fprintf(out, "\n");
  }
  if (std::fclose(out) != 0) throw InputError(path, "--csv", "could not be written completely");
}

void runBound(const ScenarioOptions& options) {
  const sensing::ScoringMode mode = sensing::parseScoringMode(options.mode, "--mode");
  eval::ViewBoundOptions bound;
  bound.clearances = parseClearances(options.clearances);
  const world::Scenario s = world::loadScenarioSource(options.source, options.seed);
  // The first photographer's camera, else the first UAV's (all CARIC cameras are the same).
  auto chosen = std::find_if(s.fleet.begin(), s.fleet.end(), [](const auto& unit) {
    return unit.role == world::UnitRole::Photographer;
  });
  if (chosen == s.fleet.end())
    chosen = std::find_if(s.fleet.begin(), s.fleet.end(), [](const auto& unit) {
      return unit.role != world::UnitRole::GroundStation;
    });
  const world::UnitSpec* photographer = chosen == s.fleet.end() ? nullptr : &*chosen;
  if (photographer == nullptr)
    throw InputError(options.source, "fleet", "has no unit with a camera to look with");
  const world::RayCaster caster(s.meshes, s.groundZ);
  // Open the CSV first: a bad path fails before the (half-minute) computation.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> csv(nullptr, std::fclose);
  if (!options.csv.empty()) {
    csv.reset(std::fopen(options.csv.c_str(), "w"));
    if (!csv) throw InputError(options.csv, "--csv", "cannot be written");
  }
  std::vector<std::vector<double>> best;
  const auto rows = eval::staticViewBound(s, caster, photographer->camera, mode, bound, &best);
  if (csv) writeBoundCsv(csv.release(), options.csv, s.interestPoints, bound.clearances, best);
  std::printf("scenario %s: %zu interest points, camera of %s, %s scoring\n", s.name.c_str(),
              s.interestPoints.size(), photographer->name.c_str(), sensing::toString(mode));
  std::printf("static views: %zu distances x %zu directions x 2 sides of each point's normal\n",
              bound.distances.size(), 1 + 4 * bound.tilts.size());
  std::printf("%-12s %10s %10s %12s %8s\n", "clearance_m", "views", "detected", "Q", "Q_%");
  for (const auto& row : rows)
    std::printf("%-12.2f %10zu %10zu %12.2f %7.1f%%\n", row.clearance, row.views, row.detected,
                row.score,
                s.interestPoints.size() ? 100.0 * row.score / s.interestPoints.size() : 0.0);
}

}  // namespace

void addScenarioCommand(CLI::App& root) {
  auto options = std::make_shared<ScenarioOptions>();
  CLI::App* scenario =
      root.add_subcommand("scenario", "List, generate, describe, export and bound scenarios");
  scenario->require_subcommand(1);

  CLI::App* list = scenario->add_subcommand(
      "list", "List the built-in scenario generators: name, family, description");
  list->callback([]() { runList(); });

  CLI::App* generate = scenario->add_subcommand(
      "generate", "Generate a built-in scenario into a folder (scenario.ini, STL meshes, PCD)");
  generate->add_option("name", options->name, "Generator name (see `coinspect scenario list`)")
      ->required();
  generate->add_option("--seed", options->seed, "Seed: varies details, not the shape")
      ->check(seedNumber())
      ->capture_default_str();
  generate->add_option("--out", options->out, "Output folder (created if missing)")
      ->check(nonEmptyPath())
      ->required();
  generate->callback([options]() { runGenerate(*options); });

  CLI::App* info = scenario->add_subcommand(
      "info", "Describe a scenario: extent, boxes, interest points, fleet, budget, hash");
  info->add_option("source", options->source, kSourceHelp)->required();
  info->add_option("--seed", options->seed, "Seed (generator names only)")
      ->check(seedNumber())
      ->capture_default_str();
  info->callback([options]() { runInfo(*options); });

  CLI::App* exporter = scenario->add_subcommand(
      "export", "Export a scenario's meshes (one STL or PLY) and interest points (PCD or CSV)");
  exporter->add_option("source", options->source, kSourceHelp)->required();
  exporter->add_option("--seed", options->seed, "Seed (generator names only)")
      ->check(seedNumber())
      ->capture_default_str();
  exporter->add_option("--mesh", options->mesh, "Mesh output: .stl (binary) or .ply");
  exporter->add_option("--points", options->points,
                       "Interest point output: .pcd (CARIC binary) or .csv "
                       "(x,y,z,nx,ny,nz,idx)");
  exporter->callback([options]() { runExport(*options); });

  CLI::App* bound = scenario->add_subcommand(
      "bound",
      "Estimate the best score reachable by static views whose body keeps a clearance from the "
      "structure (doc/scoring.md)");
  bound->add_option("source", options->source, kSourceHelp)->required();
  bound->add_option("--seed", options->seed, "Seed (generator names only)")
      ->check(seedNumber())
      ->capture_default_str();
  bound
      ->add_option("--clearance", options->clearances,
                   "Clearances from the mesh to evaluate, m, comma-separated")
      ->capture_default_str();
  bound->add_option("--mode", options->mode, "Scoring mode: caric (reference) or strict")
      ->capture_default_str();
  bound->add_option("--csv", options->csv,
                    "Also write each point's best score per clearance: idx,x,y,z,best_<c>...");
  bound->callback([options]() { runBound(*options); });
}

}  // namespace coinspect::app
