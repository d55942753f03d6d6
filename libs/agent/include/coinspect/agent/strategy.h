// The strategy interface and the registry that builds strategies by name from a config.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/agent/commands.h"
#include "coinspect/core/config.h"

namespace coinspect::agent {

// One instance per unit. decide() is called at decisionRate() in simulated time; it must be
// deterministic (no wall clock, randomness only from a seeded coinspect::Rng).
class Strategy {
 public:
  virtual ~Strategy() = default;
  virtual AgentCommand decide(const AgentView& view) = 0;
  virtual double decisionRate() const { return 10.0; }  // Hz
};

// What a strategy factory receives: the run's config (to read its own keys strictly, which marks
// them used), the unit it drives, and a seed for its own Rng; plus what the robot's owner knows
// before take-off: the fleet roster (fleet order), its own camera and its collision radius.
struct StrategyContext {
  const Config& config;
  std::string strategyName;
  std::string unitName;
  Role role = Role::Photographer;
  size_t unitIndex = 0;
  uint64_t seed = 0;
  std::vector<FleetMember> fleet;
  CameraInfo camera;
  double collisionRadius = 0.0;  // m; 0 for a ground station
};

using StrategyFactory = std::function<std::unique_ptr<Strategy>(const StrategyContext&)>;

class StrategyRegistry {
 public:
  // Throws InputError when the name is empty or already registered.
  void registerStrategy(const std::string& name, StrategyFactory factory);
  bool has(const std::string& name) const;
  std::vector<std::string> names() const;  // sorted
  // Throws InputError("[strategy] name", name, ...) listing the known names for an unknown one.
  std::unique_ptr<Strategy> create(const std::string& name, const StrategyContext& context) const;

 private:
  std::map<std::string, StrategyFactory> factories_;
};

}  // namespace coinspect::agent
