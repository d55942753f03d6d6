#include "coinspect/agent/strategy.h"

#include "coinspect/core/error.h"

namespace coinspect::agent {

const char* toString(Role role) {
  switch (role) {
    case Role::GroundStation:
      return "gcs";
    case Role::Explorer:
      return "explorer";
    case Role::Photographer:
      return "photographer";
  }
  return "?";
}

const char* toString(Activity activity) {
  switch (activity) {
    case Activity::Unreported:
      return "unreported";
    case Activity::Exploring:
      return "exploring";
    case Activity::Inspecting:
      return "inspecting";
    case Activity::TravellingToMeeting:
      return "travelling-to-meeting";
    case Activity::Waiting:
      return "waiting";
    case Activity::Returning:
      return "returning";
  }
  return "?";
}

void StrategyRegistry::registerStrategy(const std::string& name, StrategyFactory factory) {
  if (name.empty()) throw InputError("strategy registry", "", "empty strategy name");
  if (!factory) throw InputError("strategy registry", name, "no factory");
  if (!factories_.emplace(name, std::move(factory)).second)
    throw InputError("strategy registry", name, "registered twice");
}

bool StrategyRegistry::has(const std::string& name) const {
  return factories_.count(name) != 0;
}

std::vector<std::string> StrategyRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& entry : factories_)
    out.push_back(entry.first);
  return out;
}

std::unique_ptr<Strategy> StrategyRegistry::create(const std::string& name,
                                                   const StrategyContext& context) const {
  const auto found = factories_.find(name);
  if (found == factories_.end()) {
    std::string known;
    for (const auto& entry : factories_)
      known += (known.empty() ? "" : ", ") + entry.first;
    throw InputError(
        context.config.source(), "[strategy] name",
        "unknown strategy '" + name + "' (known: " + (known.empty() ? "none" : known) + ")");
  }
  auto strategy = found->second(context);
  if (!strategy) throw InputError(context.config.source(), name, "factory returned nothing");
  return strategy;
}

}  // namespace coinspect::agent
