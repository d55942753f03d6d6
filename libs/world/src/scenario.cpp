#include "coinspect/world/scenario.h"

#include <cmath>
#include <cstring>
#include <set>

#include "coinspect/core/error.h"
#include "coinspect/core/hash.h"
#include "coinspect/core/text.h"

namespace coinspect::world {

size_t Scenario::triangleCount() const {
  size_t count = 0;
  for (const auto& mesh : meshes)
    count += mesh.triangleCount();
  return count;
}

Aabb Scenario::bounds() const {
  Aabb box;
  for (const auto& mesh : meshes) {
    const Aabb b = mesh.bounds();
    if (!b.empty()) {
      box.extend(b.min);
      box.extend(b.max);
    }
  }
  return box;
}

namespace {

// FNV-1a 64 (core::fnv1a) fed with a fixed little-endian serialisation.
class Fnv1a {
 public:
  void byte(uint8_t b) { hash_ = core::fnv1a(&b, 1, hash_); }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i)
      byte(static_cast<uint8_t>(v >> (8 * i)));
  }
  // Every real value enters at single precision: interest points are stored as float32 in PCD
  // files and meshes are float32, and angles written in degrees may come back one double ulp
  // away. Rounding to float makes the hash survive saveScenario/loadScenario. -0 becomes +0.
  void real(double v) {
    float f = static_cast<float>(v);
    if (f == 0.0f) f = 0.0f;
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    u32(bits);
  }
  void vec(const Vec3& v) {
    for (int k = 0; k < 3; ++k)
      real(v[k]);
  }
  void text(const std::string& s) {
    u32(static_cast<uint32_t>(s.size()));
    for (const char c : s)
      byte(static_cast<uint8_t>(c));
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = core::kFnv1aOffset;
};

}  // namespace

uint64_t Scenario::contentHash() const {
  Fnv1a h;
  h.text("coinspect-scenario-hash-1");
  // Meshes as triangle soups (vertex coordinates per triangle, in triangle order): independent of
  // how vertices are indexed, which changes when an STL file is read back and welded.
  h.u32(static_cast<uint32_t>(meshes.size()));
  for (const auto& mesh : meshes) {
    h.u32(static_cast<uint32_t>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles)
      for (const uint32_t v : t)
        h.vec(mesh.vertex(v));
  }
  // Box names are labels, not content; their geometry is.
  h.u32(static_cast<uint32_t>(boxes.size()));
  for (const auto& box : boxes) {
    h.vec(box.center);
    h.vec(box.size);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        h.real(box.rotation(r, c));
  }
  h.u32(static_cast<uint32_t>(interestPoints.size()));
  for (const auto& p : interestPoints.points()) {
    h.vec(p.position);
    h.vec(p.normal);
  }
  // Unit names are included: recorded data is labelled by them.
  h.u32(static_cast<uint32_t>(fleet.size()));
  for (const auto& unit : fleet) {
    h.text(unit.name);
    h.u32(static_cast<uint32_t>(unit.role));
    h.vec(unit.startPosition);
    h.real(unit.startYaw);
    h.real(unit.antennaOffset);
    const CameraSpec& c = unit.camera;
    h.real(c.horizontalFov);
    h.real(c.verticalFov);
    h.vec(c.positionInBody);
    h.real(c.exposureTime);
    h.real(c.triggerInterval);
    h.real(c.focalLength);
    h.real(c.pixelSize);
    h.real(c.desiredMmPerPixel);
    h.real(c.gimbalPitchMax);
    h.real(c.gimbalYawMax);
    h.real(c.gimbalRateMax);
  }
  h.real(groundZ);
  h.real(missionBudget);
  return h.value();
}

void validateScenario(const Scenario& scenario, const std::string& source) {
  for (const auto& mesh : scenario.meshes)
    validateMesh(mesh, source + " (mesh '" + mesh.name + "')");
  std::set<std::string> boxNames;
  for (const auto& box : scenario.boxes) {
    validateBox(box, source);
    if (!box.name.empty() && !boxNames.insert(toLower(box.name)).second)
      throw InputError(source, "box '" + box.name + "'", "duplicate box name");
  }
  validateInterestPoints(scenario.interestPoints.points(), source);
  validateFleet(scenario.fleet, source);
  if (!std::isfinite(scenario.groundZ)) throw InputError(source, "ground_z", "is not finite");
  if (!std::isfinite(scenario.missionBudget) || scenario.missionBudget <= 0.0)
    throw InputError(
        source, "mission_budget",
        "must be a positive number of seconds, got " + std::to_string(scenario.missionBudget));
}

}  // namespace coinspect::world
