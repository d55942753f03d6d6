#include "feature_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "coinspect/core/error.h"

namespace coinspect::app {

namespace {

using nlohmann::json;

// Errors name the file and the dotted key, e.g. "out/a/report.json: features.total: missing".
class ReportReader {
 public:
  explicit ReportReader(std::filesystem::path file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_.string(), key, what);
  }

  json parse() const {
    std::ifstream in(file_, std::ios::binary);
    if (!in) fail("", "cannot read the file");
    json root;
    try {
      root = json::parse(in);
    } catch (const json::parse_error& error) {
      fail("", std::string("not JSON (") + error.what() + ")");
    }
    if (!root.is_object()) fail("", "not a JSON object: not a report.json of coinspect run");
    return root;
  }

  // The value at `key` (dotted, from the root), nullptr when a part of it is missing.
  static const json* find(const json& root, const std::string& key) {
    const json* node = &root;
    size_t start = 0;
    while (start <= key.size()) {
      const size_t dot = std::min(key.find('.', start), key.size());
      const std::string part = key.substr(start, dot - start);
      if (!node->is_object() || !node->contains(part)) return nullptr;
      node = &(*node)[part];
      start = dot + 1;
    }
    return node;
  }

  const json& require(const json& root, const std::string& key, const std::string& why) const {
    const json* node = find(root, key);
    if (node == nullptr) fail(key, "missing" + why);
    return *node;
  }

  std::string optionalString(const json& root, const std::string& key) const {
    const json* node = find(root, key);
    return node != nullptr && node->is_string() ? node->get<std::string>() : std::string();
  }

 private:
  std::filesystem::path file_;
};

// A folder's name, also for "." or a path ending in '/'.
std::string folderName(const std::filesystem::path& folder) {
  std::filesystem::path normal = std::filesystem::absolute(folder).lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  return normal.filename().string();
}

}  // namespace

const std::vector<std::string>& featureStages() {
  static const std::vector<std::string> kStages = {"discovered", "assigned", "inspected",
                                                   "collected", "priority"};
  return kStages;
}

FeatureRunReport readFeatureRunReport(const std::filesystem::path& run, const std::string& stage) {
  FeatureRunReport report;
  std::error_code error;
  if (std::filesystem::is_directory(run, error)) {
    report.file = run / "report.json";
    report.folder = folderName(run);
    if (!std::filesystem::exists(report.file, error))
      throw InputError(report.file.string(), "",
                       "no report.json in the run folder (coinspect run --out writes it)");
  } else if (std::filesystem::exists(run, error)) {
    report.file = run;
    report.folder = folderName(run.parent_path().empty() ? "." : run.parent_path());
  } else {
    throw InputError(run.string(), "", "no such run folder or report.json");
  }

  const ReportReader reader(report.file);
  const json root = reader.parse();
  const json& timeline =
      reader.require(root, "features.timeline",
                     ": not the report of a feature mission (a CARIC mission has none)");
  if (!timeline.is_object()) reader.fail("features.timeline", "not an object of stages");
  const std::string timesKey = "features.timeline." + stage;
  const json& times = reader.require(root, timesKey, "");
  if (!times.is_array()) reader.fail(timesKey, "not an array of times (s)");
  for (size_t i = 0; i < times.size(); ++i) {
    // A NaN time is written as null by the JSON writer: it fails here too.
    const bool valid = times[i].is_number() && std::isfinite(times[i].get<double>()) &&
                       times[i].get<double>() >= 0.0;
    if (!valid)
      reader.fail(timesKey + "[" + std::to_string(i) + "]",
                  times[i].dump() + " is not a time: a finite number of seconds >= 0 expected");
    report.times.push_back(times[i].get<double>());
  }
  std::sort(report.times.begin(), report.times.end());

  // The high-priority features' curve counts up to their own total.
  const std::string totalKey = stage == "priority" ? "features.priority.total" : "features.total";
  const json& total = reader.require(root, totalKey, "");
  if (!total.is_number_unsigned())
    reader.fail(totalKey, total.dump() + " is not a count of features (an integer >= 0)");
  report.total = total.get<uint64_t>();
  const json& budget = reader.require(root, "clock.budget", "");
  if (!budget.is_number() || !std::isfinite(budget.get<double>()) || !(budget.get<double>() > 0.0))
    reader.fail("clock.budget", budget.dump() + " is not a mission budget: seconds > 0 expected");
  report.budget = budget.get<double>();

  report.strategy = reader.optionalString(root, "strategy");
  if (report.strategy.empty())
    report.strategy = reader.optionalString(root, "config.values.strategy.name");
  report.scenario = reader.optionalString(root, "scenario");
  return report;
}

}  // namespace coinspect::app
