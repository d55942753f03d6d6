#include "coinspect/world/scenario_files.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "coinspect/world/caric_formats.h"
#include "coinspect/world/mesh_io.h"
#include "file_utils.h"

namespace coinspect::world {
namespace {

namespace fs = std::filesystem;

// One expression for degrees -> radians everywhere (also CameraSpec's defaults), so that a
// value written in degrees by saveScenario reads back as the same double.
double toRadians(double degrees) {
  return degrees * M_PI / 180.0;
}

std::string format(double value, int precision) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
  return buffer;
}

// Shortest decimal text that reads back as a value accepted by `same`, without an exponent for
// ordinary magnitudes ("80", not "8e+01"). Empty when no precision up to 17 digits works.
template <class Same>
std::string shortestText(double value, Same&& same) {
  for (int precision = 1; precision <= 17; ++precision) {
    const std::string text = format(value, precision);
    if (!same(std::strtod(text.c_str(), nullptr))) continue;
    const double magnitude = std::abs(value);
    if (magnitude >= 1.0 && magnitude < 1e15) {
      const int digits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
      if (digits > precision) return format(value, digits);
    }
    return text;
  }
  return "";
}

// Shortest decimal text that reads back as exactly `value`.
std::string formatReal(double value) {
  return shortestText(value, [&](double back) { return back == value; });
}

// Degrees text whose toRadians() is exactly `radians` when such a number exists (it does for
// every value that came from degrees, e.g. CARIC's "80"); otherwise the closest text, at most
// one ulp off. The content hash works at float precision, so either way it is unchanged.
std::string formatDegrees(double radians) {
  const double degrees = radians * 180.0 / M_PI;
  const auto exact = [&](double candidate) { return toRadians(candidate) == radians; };
  for (int step = 0; step <= 4; ++step)
    for (const double direction : {1.0, -1.0}) {
      double candidate = degrees;
      for (int k = 0; k < step; ++k)
        candidate = std::nextafter(candidate, direction * INFINITY);
      if (exact(candidate)) return shortestText(candidate, exact);
    }
  return formatReal(degrees);
}

std::string formatVec(const Vec3& v) {
  return formatReal(v.x()) + " " + formatReal(v.y()) + " " + formatReal(v.z());
}

struct Section {
  std::string name;
  int line = 0;
};

// Sections in file order. MRPT's getAllSections() returns them sorted by name (SimpleIni's map),
// and boxes and units must keep the order the author gave them (a section given twice is
// Config's error, before this runs).
std::vector<Section> sectionsInFileOrder(const std::string& text, const std::string& source) {
  std::vector<Section> sections;
  std::istringstream lines(text);
  std::string raw;
  for (int line = 1; std::getline(lines, raw); ++line) {
    const auto content = trim(raw);
    if (content.empty() || content.front() == ';' || content.front() == '#') continue;
    if (content.front() != '[') {
      if (sections.empty())
        throw InputError(source, "line " + std::to_string(line), "key outside any [section]");
      continue;
    }
    sections.push_back({std::string(trim(content.substr(1, content.size() - 2))), line});
  }
  return sections;
}

// "<prefix><name>" -> name (prefix compared case-insensitively, like the INI reader's names).
std::string suffixAfter(const std::string& section, const std::string& prefix) {
  return toLower(section.substr(0, prefix.size())) == prefix ? section.substr(prefix.size()) : "";
}

double readDegrees(const Config& config, const std::string& section, const std::string& key,
                   double fallbackRadians) {
  return config.has(section, key) ? toRadians(config.getDouble(section, key)) : fallbackRadians;
}

TriangleMesh readMeshSection(const Config& config, const std::string& section,
                             const fs::path& folder) {
  const std::string file = config.getString(section, "file");
  const fs::path path = fs::path(file).is_relative() ? folder / file : fs::path(file);
  std::error_code error;
  if (!fs::is_regular_file(path, error))
    throw InputError(config.source(), "[" + section + "] file", "no such mesh file '" + file + "'");
  MeshTransform transform;
  transform.scale = config.getDouble(section, "scale", 1.0);
  if (transform.scale == 0.0)
    throw InputError(config.source(), "[" + section + "] scale", "must not be zero");
  transform.translation = config.getVector3(section, "translation", Vec3::Zero());
  transform.yaw = readDegrees(config, section, "yaw", 0.0);
  transform.pitch = readDegrees(config, section, "pitch", 0.0);
  transform.roll = readDegrees(config, section, "roll", 0.0);
  return loadMesh(path, transform);
}

OrientedBox readBoxSection(const Config& config, const std::string& section) {
  OrientedBox box;
  box.center = config.getVector3(section, "center");
  box.size = config.getVector3(section, "size");
  if (config.has(section, "yaw") && config.has(section, "rotation"))
    throw InputError(config.source(), "[" + section + "]", "give either yaw or rotation, not both");
  if (config.has(section, "rotation")) {
    const auto m = config.getDoubles(section, "rotation");
    if (m.size() != 9)
      throw InputError(config.source(), "[" + section + "] rotation",
                       "expected 9 numbers (row-major 3x3), got " + std::to_string(m.size()));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        box.rotation(r, c) = m[3 * r + c];
  } else {
    box.rotation = Eigen::AngleAxisd(readDegrees(config, section, "yaw", 0.0), Vec3::UnitZ())
                       .toRotationMatrix();
  }
  return box;
}

UnitSpec readUnitSection(const Config& config, const std::string& section) {
  UnitSpec unit;
  unit.role =
      parseUnitRole(config.getString(section, "role"), config.source() + ": [" + section + "]");
  unit.startPosition = config.getVector3(section, "start");
  unit.startYaw = readDegrees(config, section, "yaw", 0.0);
  // The reference's antennas: 0.2 m on explorers, 0.1 m on the others.
  unit.antennaOffset =
      config.getDouble(section, "antenna_offset", unit.role == UnitRole::Explorer ? 0.2 : 0.1);
  CameraSpec& c = unit.camera;
  c.horizontalFov = readDegrees(config, section, "hfov", c.horizontalFov);
  c.verticalFov = readDegrees(config, section, "vfov", c.verticalFov);
  c.positionInBody = config.getVector3(section, "camera_position", c.positionInBody);
  c.exposureTime = config.getDouble(section, "exposure_time", c.exposureTime);
  c.triggerInterval = config.getDouble(section, "trigger_interval", c.triggerInterval);
  c.focalLength = config.getDouble(section, "focal_length", c.focalLength);
  c.pixelSize = config.getDouble(section, "pixel_size", c.pixelSize);
  c.desiredMmPerPixel = config.getDouble(section, "desired_mm_per_pixel", c.desiredMmPerPixel);
  c.gimbalPitchMax = readDegrees(config, section, "gimbal_pitch_max", c.gimbalPitchMax);
  c.gimbalYawMax = readDegrees(config, section, "gimbal_yaw_max", c.gimbalYawMax);
  c.gimbalRateMax = readDegrees(config, section, "gimbal_rate_max", c.gimbalRateMax);
  return unit;
}

}  // namespace

Scenario loadScenario(const fs::path& iniPath) {
  const std::string source = iniPath.string();
  const std::string text = detail::readWholeFile(iniPath, "scenario file");
  const fs::path folder = iniPath.parent_path();

  // The INI reader first: it rejects malformed lines before the section scan looks at them.
  const Config config = Config::fromText(text, source);
  const auto sections = sectionsInFileOrder(text, source);

  Scenario scenario;
  // absolute("") throws: a bare file name (read from inside its folder) has an empty parent.
  const fs::path normal = fs::absolute(folder.empty() ? fs::path(".") : folder).lexically_normal();
  scenario.name = (normal.has_filename() ? normal : normal.parent_path()).filename().string();
  for (const Section& s : sections) {
    const std::string& section = s.name;
    std::string name;
    if (toLower(section) == "scenario") {
      scenario.name = config.getString(section, "name", scenario.name);
      scenario.description = config.getString(section, "description", "");
      scenario.groundZ = config.getDouble(section, "ground_z", 0.0);
      scenario.missionBudget = config.getDouble(section, "mission_budget", 600.0);
      if (config.has(section, "interest_points")) {
        const std::string file = config.getString(section, "interest_points");
        const fs::path path = fs::path(file).is_relative() ? folder / file : fs::path(file);
        std::error_code error;
        if (!fs::is_regular_file(path, error))
          throw InputError(source, "[" + section + "] interest_points",
                           "no such interest point file '" + file + "'");
        scenario.interestPoints = InterestPointSet(readCaricInterestPoints(path));
      }
    } else if (!(name = suffixAfter(section, "mesh.")).empty()) {
      TriangleMesh mesh = readMeshSection(config, section, folder);
      mesh.name = name;
      scenario.meshes.push_back(std::move(mesh));
    } else if (!(name = suffixAfter(section, "box.")).empty()) {
      OrientedBox box = readBoxSection(config, section);
      box.name = name;
      scenario.boxes.push_back(box);
    } else if (!(name = suffixAfter(section, "unit.")).empty()) {
      UnitSpec unit = readUnitSection(config, section);
      unit.name = name;
      scenario.fleet.push_back(unit);
    } else {
      throw InputError(source, "line " + std::to_string(s.line),
                       "unknown section [" + section +
                           "] (expected [scenario], [mesh.<name>], [box.<name>], [unit.<name>])");
    }
  }
  config.requireAllKeysUsed();
  validateScenario(scenario, source);
  return scenario;
}

namespace {

// A name usable inside "[prefix.<name>]" that reads back unchanged.
bool isSectionSafe(const std::string& name) {
  if (name.empty() || trim(name).size() != name.size()) return false;
  for (const char c : name)
    if (c == '[' || c == ']' || c == '\n' || c == '\r' || c == '#' || c == ';') return false;
  return true;
}

std::string fileSafe(const std::string& name) {
  std::string out;
  for (const char c : name)
    out.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_');
  return out;
}

}  // namespace

void saveScenario(const Scenario& scenario, const fs::path& folder) {
  const std::string source = "scenario '" + scenario.name + "'";
  validateScenario(scenario, source);
  for (const std::string* value : {&scenario.name, &scenario.description})
    if (value->find_first_of("\r\n") != std::string::npos || trim(*value).size() != value->size())
      throw InputError(source, "", "name and description must be one line without outer spaces");
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw InputError(folder.string(), "", "cannot create folder: " + error.message());

  std::ostringstream ini;
  ini << "# coinspect scenario: keys are documented in doc/config.md, \"Scenario files\".\n";
  ini << "[scenario]\n";
  if (!scenario.name.empty()) ini << "name = " << scenario.name << "\n";
  if (!scenario.description.empty()) ini << "description = " << scenario.description << "\n";
  ini << "ground_z = " << formatReal(scenario.groundZ) << "\n";
  ini << "mission_budget = " << formatReal(scenario.missionBudget) << "\n";
  if (!scenario.interestPoints.empty()) {
    writeCaricInterestPoints(scenario.interestPoints.points(), folder / "interest_points.pcd");
    ini << "interest_points = interest_points.pcd\n";
  }

  // Section names compare case-insensitively in the INI reader.
  std::set<std::string> used;
  const auto sectionName = [&](const std::string& prefix, const std::string& name, size_t index,
                               bool mustKeep) {
    std::string chosen = name;
    if (!isSectionSafe(chosen) || used.count(toLower(prefix + chosen))) {
      if (mustKeep)
        throw InputError(source, prefix + name,
                         "name cannot be written as a unique INI section [" + prefix + name + "]");
      chosen = prefix.substr(0, prefix.size() - 1) + std::to_string(index);
    }
    used.insert(toLower(prefix + chosen));
    return chosen;
  };

  std::set<std::string> files;
  for (size_t i = 0; i < scenario.meshes.size(); ++i) {
    const TriangleMesh& mesh = scenario.meshes[i];
    const std::string name = sectionName("mesh.", mesh.name, i, false);
    std::string file = fileSafe(name) + ".stl";
    if (!files.insert(toLower(file)).second) file = "mesh" + std::to_string(i) + ".stl";
    files.insert(toLower(file));
    // Meshes are stored already placed (identity transform); STL keeps float vertices and the
    // triangle order exactly, which is what contentHash covers.
    writeStl(mesh, folder / file);
    ini << "\n[mesh." << name << "]\nfile = " << file << "\n";
  }
  for (size_t i = 0; i < scenario.boxes.size(); ++i) {
    const OrientedBox& box = scenario.boxes[i];
    ini << "\n[box." << sectionName("box.", box.name, i, false) << "]\n";
    ini << "center = " << formatVec(box.center) << "\n";
    ini << "size = " << formatVec(box.size) << "\n";
    // The matrix itself, not a yaw: exact, and boxes may be tilted.
    ini << "rotation =";
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        ini << " " << formatReal(box.rotation(r, c));
    ini << "\n";
  }
  for (size_t i = 0; i < scenario.fleet.size(); ++i) {
    const UnitSpec& unit = scenario.fleet[i];
    const CameraSpec& c = unit.camera;
    ini << "\n[unit." << sectionName("unit.", unit.name, i, true) << "]\n";
    ini << "role = " << toString(unit.role) << "\n";
    ini << "start = " << formatVec(unit.startPosition) << "\n";
    ini << "yaw = " << formatDegrees(unit.startYaw) << "\n";
    ini << "antenna_offset = " << formatReal(unit.antennaOffset) << "\n";
    ini << "hfov = " << formatDegrees(c.horizontalFov) << "\n";
    ini << "vfov = " << formatDegrees(c.verticalFov) << "\n";
    ini << "camera_position = " << formatVec(c.positionInBody) << "\n";
    ini << "exposure_time = " << formatReal(c.exposureTime) << "\n";
    ini << "trigger_interval = " << formatReal(c.triggerInterval) << "\n";
    ini << "focal_length = " << formatReal(c.focalLength) << "\n";
    ini << "pixel_size = " << formatReal(c.pixelSize) << "\n";
    ini << "desired_mm_per_pixel = " << formatReal(c.desiredMmPerPixel) << "\n";
    ini << "gimbal_pitch_max = " << formatDegrees(c.gimbalPitchMax) << "\n";
    ini << "gimbal_yaw_max = " << formatDegrees(c.gimbalYawMax) << "\n";
    ini << "gimbal_rate_max = " << formatDegrees(c.gimbalRateMax) << "\n";
  }
  detail::writeWholeFile(folder / "scenario.ini", ini.str());
}

void exportInterestPointsCsv(const InterestPointSet& points, const fs::path& path) {
  std::ostringstream csv;
  csv << "x,y,z,nx,ny,nz,idx\n";
  // "+ 0.0" writes -0 as 0.
  for (const auto& p : points.points()) {
    for (int k = 0; k < 3; ++k)
      csv << formatReal(p.position[k] + 0.0) << ",";
    for (int k = 0; k < 3; ++k)
      csv << formatReal(p.normal[k] + 0.0) << ",";
    csv << p.index << "\n";
  }
  detail::writeWholeFile(path, csv.str());
}

}  // namespace coinspect::world
