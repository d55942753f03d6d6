// A small recorded run for the picture tests: a 10 m cube on the ground with interest points on
// its roof and on its +x face, one inspection box, a ground station and two UAVs ("alpha" circles
// the cube above its roof, "bravo" crosses in front of it and is lost at t = 8 s), tally updates
// and events. Also a reader for the PNG files our encoder writes.
#pragma once

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "coinspect/eval/image.h"
#include "coinspect/record/observations.h"
#include "coinspect/record/rawlog_writer.h"
#include "coinspect/testing/files.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval::test {

inline constexpr double kEndTime = 12.0;   // s, last pose sample
inline constexpr double kBravoLost = 8.0;  // s
inline constexpr double kPoseRate = 20.0;  // Hz

// Cube -5 <= x, y <= 5, 0 <= z <= 10. Points 0..8: roof, a 3 x 3 grid at z = 10; points 9..11:
// the +x face at z = 5. Units: gcs (ground station), alpha (explorer), bravo (photographer).
inline world::Scenario pictureScenario() {
  world::Scenario scenario;
  scenario.name = "cube";
  world::TriangleMesh mesh;
  mesh.name = "cube";
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? 5.0f : -5.0f, i & 2 ? 5.0f : -5.0f, i & 4 ? 10.0f : 0.0f);
  // Outward normals by the right-hand rule.
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  scenario.meshes.push_back(mesh);
  std::vector<world::InterestPoint> points;
  for (int ix = -1; ix <= 1; ++ix)
    for (int iy = -1; iy <= 1; ++iy) {
      world::InterestPoint p;
      p.position = world::Vec3(3.0 * ix, 3.0 * iy, 10.0);
      p.normal = world::Vec3(0, 0, 1);
      points.push_back(p);
    }
  for (int iy = -1; iy <= 1; ++iy) {
    world::InterestPoint p;
    p.position = world::Vec3(5.0, 3.0 * iy, 5.0);
    p.normal = world::Vec3(1, 0, 0);
    points.push_back(p);
  }
  scenario.interestPoints = world::InterestPointSet(points);
  world::OrientedBox box;
  box.name = "cube";
  box.center = world::Vec3(0, 0, 5.5);
  box.size = world::Vec3(12, 12, 11);
  scenario.boxes.push_back(box);
  for (const auto& [name, role] : {std::pair{"gcs", world::UnitRole::GroundStation},
                                   std::pair{"alpha", world::UnitRole::Explorer},
                                   std::pair{"bravo", world::UnitRole::Photographer}}) {
    world::UnitSpec unit;
    unit.name = name;
    unit.role = role;
    scenario.fleet.push_back(unit);
  }
  return scenario;
}

// alpha: a circle of radius 12 m at z = 14 around the cube, one turn in kEndTime.
inline world::Vec3 alphaAt(double t) {
  const double angle = 2.0 * M_PI * t / kEndTime;
  return {12.0 * std::cos(angle), 12.0 * std::sin(angle), 14.0};
}
// bravo: along y = -9 at z = 5, from x = -12 at 1 m/s, until it is lost (then it lies on the
// ground where it fell).
inline world::Vec3 bravoAt(double t) {
  if (t >= kBravoLost) return {-12.0 + kBravoLost, -9.0, 0.0};
  return {-12.0 + t, -9.0, 5.0};
}
inline const world::Vec3 kGcsPosition{-15.0, -15.0, 0.0};

// Tally: point 4 (roof centre) scores 1.0 at t = 2, point 0 0.5 at t = 4, point 10 (face
// centre) 0.25 at t = 6, point 4 is never lowered. Final Q = 1.75, detected 3.
inline void writePictureRun(const std::filesystem::path& path) {
  using record::MissionEventKind;
  record::RawlogWriter writer(path, {"0.1.0", 7, "0", "[mission]\nscenario = cube\n"});
  const int samples = static_cast<int>(std::lround(kEndTime * kPoseRate));
  for (int k = 0; k <= samples; ++k) {
    const double t = k / kPoseRate;
    const auto pose = [](const world::Vec3& p, double yaw) {
      Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
      out.translation() = p;
      out.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      return out;
    };
    writer.writeGroundTruth("gcs", t, pose(kGcsPosition, 0.0), {0, 0, 0}, {0, 0, 0});
    writer.writeGroundTruth("alpha", t, pose(alphaAt(t), 2.0 * M_PI * t / kEndTime + M_PI / 2),
                            {0, 0, 0}, {0, 0, 0});
    writer.writeGroundTruth("bravo", t, pose(bravoAt(t), 0.0), {0, 0, 0}, {0, 0, 0});
    if (k == 10) writer.writeEvent(t, MissionEventKind::Start, "", "takeoff");
    if (k == 40) writer.writeTally(t, {{4, 1.0}}, 1, 12, 1.0);
    if (k == 80) writer.writeTally(t, {{0, 0.5}}, 2, 12, 1.5);
    if (k == 120) writer.writeTally(t, {{10, 0.25}}, 3, 12, 1.75);
    if (t == kBravoLost) {
      writer.writeEvent(t, MissionEventKind::Collision, "bravo", "hit the cube");
      writer.writeEvent(t, MissionEventKind::Death, "bravo", "collision");
    }
  }
  writer.writeEvent(kEndTime, MissionEventKind::End, "", "budget");
  writer.close();
}

// A PNG as written by encodePng (8-bit RGB, filter 0 on every row): its size and pixels.
// Returns an empty image (width 0) when the bytes are not such a PNG.
struct DecodedPng {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
  Rgb at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

inline uint32_t bigEndian32(const std::string& bytes, size_t at) {
  uint32_t value = 0;
  for (size_t i = 0; i < 4; ++i)
    value = (value << 8) | static_cast<uint8_t>(bytes[at + i]);
  return value;
}

// Width and height from the IHDR chunk (0, 0 when the file is not a PNG).
inline std::pair<int, int> pngSize(const std::filesystem::path& path) {
  const std::string bytes = testing::readFile(path);
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      bytes.compare(12, 4, "IHDR") != 0)
    return {0, 0};
  return {static_cast<int>(bigEndian32(bytes, 16)), static_cast<int>(bigEndian32(bytes, 20))};
}

inline DecodedPng decodePng(const std::filesystem::path& path) {
  const std::string bytes = testing::readFile(path);
  DecodedPng png;
  const auto [width, height] = pngSize(path);
  if (width == 0) return png;
  std::string compressed;
  for (size_t at = 8; at + 8 <= bytes.size();) {
    const uint32_t length = bigEndian32(bytes, at);
    if (bytes.compare(at + 4, 4, "IDAT") == 0) compressed += bytes.substr(at + 8, length);
    at += 12 + length;
  }
  std::vector<uint8_t> raw(static_cast<size_t>(height) * (1 + 3 * width));
  uLongf rawSize = raw.size();
  if (uncompress(raw.data(), &rawSize, reinterpret_cast<const Bytef*>(compressed.data()),
                 compressed.size()) != Z_OK ||
      rawSize != raw.size())
    return png;
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = raw.data() + static_cast<size_t>(y) * (1 + 3 * width);
    if (row[0] != 0) return DecodedPng{};
    for (int x = 0; x < width; ++x)
      png.pixels.push_back({row[1 + 3 * x], row[2 + 3 * x], row[3 + 3 * x]});
  }
  png.width = width;
  png.height = height;
  return png;
}

}  // namespace coinspect::eval::test
