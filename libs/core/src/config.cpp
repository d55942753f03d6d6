#include "coinspect/core/config.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"

namespace coinspect {

struct Config::Impl {
  mrpt::config::CConfigFileMemory ini;
};

Config::Config() : impl_(std::make_unique<Impl>()) {}
Config::Config(Config&&) noexcept = default;
Config& Config::operator=(Config&&) noexcept = default;
Config::~Config() = default;

Config Config::fromFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open configuration file");
  std::ostringstream text;
  text << in.rdbuf();
  return fromText(text.str(), path.string(), path.parent_path());
}

Config Config::fromText(const std::string& text, const std::string& source,
                        const std::filesystem::path& folder) {
  Config config;
  config.source_ = source;
  config.folder_ = folder;
  // Reject lines the INI parser would silently drop or merge, so that typos surface: a key or
  // a section given twice would let the last value win unseen (found by fuzzing).
  std::istringstream lines(text);
  std::string line;
  std::string section;
  std::map<std::string, int> sectionLines;                      // lowercase name -> first line
  std::map<std::pair<std::string, std::string>, int> keyLines;  // lowercase -> first line

  for (int number = 1; std::getline(lines, line); ++number) {
    const auto content = trim(line);
    const std::string where = "line " + std::to_string(number);
    if (content.empty() || content.front() == ';' || content.front() == '#') continue;
    if (content.front() == '[') {
      if (content.back() != ']' || content.size() < 3)
        throw InputError(source, where, "malformed section header '" + std::string(content) + "'");
      section = std::string(trim(content.substr(1, content.size() - 2)));
      const auto [at, added] = sectionLines.emplace(toLower(section), number);
      if (!added)
        throw InputError(source, where,
                         "section [" + section + "] given twice (first on line " +
                             std::to_string(at->second) + "): write its keys in one");
      continue;
    }
    const auto equals = content.find('=');
    if (equals == std::string_view::npos)
      throw InputError(source, where, "expected 'key = value', got '" + std::string(content) + "'");
    const std::string key(trim(content.substr(0, equals)));
    const auto [at, added] =
        keyLines.emplace(std::make_pair(toLower(section), toLower(key)), number);
    if (!added)
      throw InputError(source, where,
                       "[" + section + "] " + key + " given twice (first on line " +
                           std::to_string(at->second) + ")");
  }
  config.impl_->ini.setContent(text);
  return config;
}

std::vector<std::string> Config::sections() const {
  std::vector<std::string> result;
  impl_->ini.getAllSections(result);
  return result;
}

std::vector<std::string> Config::keys(const std::string& section) const {
  std::vector<std::string> result;
  impl_->ini.getAllKeys(section, result);
  return result;
}

bool Config::hasSection(const std::string& section) const {
  return impl_->ini.sectionExists(section);
}

bool Config::has(const std::string& section, const std::string& key) const {
  return impl_->ini.keyExists(section, key);
}

std::optional<std::string> Config::raw(const std::string& section, const std::string& key) const {
  if (!has(section, key)) return std::nullopt;
  used_.emplace(section, key);
  return std::string(trim(impl_->ini.read_string(section, key, "", false)));
}

void Config::fail(const std::string& section, const std::string& key,
                  const std::string& what) const {
  throw InputError(source_, "[" + section + "] " + key, what);
}

std::string Config::required(const std::string& section, const std::string& key) const {
  auto value = raw(section, key);
  if (!value) fail(section, key, "missing required key");
  return *value;
}

namespace {
double toDouble(const Config& config, const std::string& section, const std::string& key,
                const std::string& text) {
  const auto value = parseFiniteDouble(text);
  if (!value)
    throw InputError(config.source(), "[" + section + "] " + key,
                     "'" + text + "' is not a finite number");
  return *value;
}
}  // namespace

std::string Config::getString(const std::string& section, const std::string& key) const {
  return required(section, key);
}

double Config::getDouble(const std::string& section, const std::string& key) const {
  return toDouble(*this, section, key, required(section, key));
}

long long Config::getInt(const std::string& section, const std::string& key) const {
  const std::string text = required(section, key);
  const auto value = parseInteger(text);
  if (!value) fail(section, key, "'" + text + "' is not an integer");
  return *value;
}

bool Config::getBool(const std::string& section, const std::string& key) const {
  const std::string text = required(section, key);
  const auto value = parseBool(text);
  if (!value) fail(section, key, "'" + text + "' is not a boolean (true/false)");
  return *value;
}

std::vector<double> Config::getDoubles(const std::string& section, const std::string& key) const {
  std::vector<double> values;
  for (const auto& token : splitTokens(required(section, key)))
    values.push_back(toDouble(*this, section, key, token));
  return values;
}

Eigen::Vector3d Config::getVector3(const std::string& section, const std::string& key) const {
  const auto values = getDoubles(section, key);
  if (values.size() != 3)
    fail(section, key, "expected 3 numbers, got " + std::to_string(values.size()));
  return {values[0], values[1], values[2]};
}

std::string Config::getString(const std::string& section, const std::string& key,
                              const std::string& fallback) const {
  return has(section, key) ? getString(section, key) : fallback;
}

double Config::getDouble(const std::string& section, const std::string& key,
                         double fallback) const {
  return has(section, key) ? getDouble(section, key) : fallback;
}

long long Config::getInt(const std::string& section, const std::string& key,
                         long long fallback) const {
  return has(section, key) ? getInt(section, key) : fallback;
}

bool Config::getBool(const std::string& section, const std::string& key, bool fallback) const {
  return has(section, key) ? getBool(section, key) : fallback;
}

Eigen::Vector3d Config::getVector3(const std::string& section, const std::string& key,
                                   const Eigen::Vector3d& fallback) const {
  return has(section, key) ? getVector3(section, key) : fallback;
}

std::filesystem::path Config::getPath(const std::string& section, const std::string& key) const {
  const std::filesystem::path path = getString(section, key);
  return path.is_relative() && !folder_.empty() ? folder_ / path : path;
}

void Config::markUsed(const std::string& section, const std::string& key) const {
  used_.emplace(section, key);
}

void Config::set(const std::string& section, const std::string& key, const std::string& value) {
  impl_->ini.write(section, key, value);
}

void Config::applyOverride(const std::string& assignment) {
  const auto equals = assignment.find('=');
  const auto dot = assignment.substr(0, equals).rfind('.');
  if (equals == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == equals)
    throw InputError("--set", assignment, "expected section.key=value");
  set(std::string(trim(assignment.substr(0, dot))),
      std::string(trim(assignment.substr(dot + 1, equals - dot - 1))),
      std::string(trim(assignment.substr(equals + 1))));
}

void Config::requireAllKeysUsed(const std::vector<std::string>& sectionsToCheck) const {
  std::string unknown;
  for (const auto& section : sectionsToCheck.empty() ? sections() : sectionsToCheck)
    for (const auto& key : keys(section))
      if (!used_.count({section, key}))
        unknown += (unknown.empty() ? "" : ", ") + ("[" + section + "] " + key);
  if (!unknown.empty()) throw InputError(source_, "", "unknown key(s): " + unknown);
}

std::string Config::toText() const {
  return impl_->ini.getContent();
}

}  // namespace coinspect
