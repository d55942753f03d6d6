// `coinspect scenario`: list the built-in generators, generate a scenario into a folder, describe
// any scenario source, and export its geometry and interest points for other tools.
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/world/caric_formats.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/mesh_io.h"
#include "coinspect/world/scenario_files.h"
#include "commands.h"
#include "scenario_source.h"

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
  const world::Scenario s = loadScenarioSource(options.source, options.seed);
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

  const world::Scenario s = loadScenarioSource(options.source, options.seed);
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

}  // namespace

void addScenarioCommand(CLI::App& root) {
  auto options = std::make_shared<ScenarioOptions>();
  CLI::App* scenario =
      root.add_subcommand("scenario", "List, generate, describe and export scenarios");
  scenario->require_subcommand(1);

  CLI::App* list = scenario->add_subcommand(
      "list", "List the built-in scenario generators: name, family, description");
  list->callback([]() { runList(); });

  CLI::App* generate = scenario->add_subcommand(
      "generate", "Generate a built-in scenario into a folder (scenario.ini, STL meshes, PCD)");
  generate->add_option("name", options->name, "Generator name (see `coinspect scenario list`)")
      ->required();
  generate->add_option("--seed", options->seed, "Seed: varies details, not the shape")
      ->capture_default_str();
  generate->add_option("--out", options->out, "Output folder (created if missing)")->required();
  generate->callback([options]() { runGenerate(*options); });

  CLI::App* info = scenario->add_subcommand(
      "info", "Describe a scenario: extent, boxes, interest points, fleet, budget, hash");
  info->add_option("source", options->source, kSourceHelp)->required();
  info->add_option("--seed", options->seed, "Seed (generator names only)")->capture_default_str();
  info->callback([options]() { runInfo(*options); });

  CLI::App* exporter = scenario->add_subcommand(
      "export", "Export a scenario's meshes (one STL or PLY) and interest points (PCD or CSV)");
  exporter->add_option("source", options->source, kSourceHelp)->required();
  exporter->add_option("--seed", options->seed, "Seed (generator names only)")
      ->capture_default_str();
  exporter->add_option("--mesh", options->mesh, "Mesh output: .stl (binary) or .ply");
  exporter->add_option("--points", options->points,
                       "Interest point output: .pcd (CARIC binary) or .csv "
                       "(x,y,z,nx,ny,nz,idx)");
  exporter->callback([options]() { runExport(*options); });
}

}  // namespace coinspect::app
