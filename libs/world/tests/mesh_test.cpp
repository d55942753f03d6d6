#include "coinspect/world/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coinspect/core/error.h"
#include "test_meshes.h"

namespace coinspect::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Runs validateMesh and returns the InputError message, or "" when the mesh is accepted.
std::string rejection(const TriangleMesh& mesh, const std::string& source) {
  try {
    validateMesh(mesh, source);
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), source);
    return error.what();
  }
  return "";
}

TEST(MeshTransform, ScaleRotateThenTranslate) {
  MeshTransform t;
  t.scale = 2.0;
  t.yaw = kPi / 2;
  t.translation = Vec3(1, 2, 3);
  // (1,0,0) -> scaled (2,0,0) -> yaw 90 deg (0,2,0) -> translated (1,4,3).
  EXPECT_TRUE(t.apply(Vec3(1, 0, 0)).isApprox(Vec3(1, 4, 3), 1e-12));
  EXPECT_FALSE(t.isIdentity());
  EXPECT_TRUE(MeshTransform{}.isIdentity());
}

TEST(MeshTransform, EulerOrderIsYawPitchRoll) {
  MeshTransform pitch;
  pitch.pitch = kPi / 2;  // about y: x -> -z
  EXPECT_TRUE(pitch.apply(Vec3(1, 0, 0)).isApprox(Vec3(0, 0, -1), 1e-12));
  MeshTransform roll;
  roll.roll = kPi / 2;  // about x: y -> z
  EXPECT_TRUE(roll.apply(Vec3(0, 1, 0)).isApprox(Vec3(0, 0, 1), 1e-12));
  // R = Rz(yaw) Ry(pitch) Rx(roll): roll acts first. z -> (roll) -y -> (yaw) +x.
  MeshTransform both;
  both.yaw = kPi / 2;
  both.roll = kPi / 2;
  EXPECT_TRUE(both.apply(Vec3(0, 0, 1)).isApprox(Vec3(1, 0, 0), 1e-12));
}

TEST(TriangleMesh, TransformMovesVerticesAndKeepsNormalsOutward) {
  TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  MeshTransform t;
  t.scale = -2.0;  // mirroring: winding must be flipped to keep normals outward
  t.translation = Vec3(10, 0, 0);
  box.transform(t);
  const Aabb b = box.bounds();
  EXPECT_TRUE(b.min.isApprox(Vec3(8, -2, -2), 1e-6));
  EXPECT_TRUE(b.max.isApprox(Vec3(10, 0, 0), 1e-6));
  const Vec3 centre(9, -1, -1);
  for (size_t i = 0; i < box.triangleCount(); ++i) {
    const auto& tri = box.triangles[i];
    const Vec3 facetCentre = (box.vertex(tri[0]) + box.vertex(tri[1]) + box.vertex(tri[2])) / 3.0;
    EXPECT_GT(box.facetNormal(i).dot(facetCentre - centre), 0.0) << "triangle " << i;
  }
}

TEST(TriangleMesh, BoxHelperNormalsPointOutward) {
  const TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (size_t i = 0; i < box.triangleCount(); ++i) {
    const auto& tri = box.triangles[i];
    const Vec3 facetCentre = (box.vertex(tri[0]) + box.vertex(tri[1]) + box.vertex(tri[2])) / 3.0;
    EXPECT_GT(box.facetNormal(i).dot(facetCentre - Vec3(0.5, 0.5, 0.5)), 0.0) << i;
    EXPECT_DOUBLE_EQ(box.facetArea(i), 0.5);
  }
}

TEST(TriangleMesh, AppendOffsetsIndices) {
  TriangleMesh a = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1), "a");
  const TriangleMesh b = test::boxMesh(Vec3(5, 0, 0), Vec3(6, 1, 1), "b");
  a.append(b);
  EXPECT_EQ(a.name, "a");
  ASSERT_EQ(a.vertices.size(), 16u);
  ASSERT_EQ(a.triangleCount(), 24u);
  for (size_t i = 0; i < 12; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(a.triangles[12 + i][k], b.triangles[i][k] + 8);
  EXPECT_TRUE(a.vertex(a.triangles[12][0]).isApprox(Vec3(5, 0, 0)));
  EXPECT_TRUE(a.bounds().max.isApprox(Vec3(6, 1, 1)));
}

TEST(TriangleMesh, FacetNormalAndArea) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {4, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 1}, {0, 1, 3}};
  EXPECT_TRUE(m.facetNormal(0).isApprox(Vec3(0, 0, 1)));
  EXPECT_DOUBLE_EQ(m.facetArea(0), 3.0);  // legs 2 and 3
  EXPECT_TRUE(m.facetNormal(1).isApprox(Vec3(0, 0, -1)));
  EXPECT_TRUE(m.facetNormal(2).isZero());  // collinear
  EXPECT_EQ(m.facetArea(2), 0.0);
}

TEST(ValidateMesh, AcceptsClosedBoxAndAFewDegenerateFacets) {
  TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_EQ(rejection(box, "box.stl"), "");
  box.triangles.push_back({0, 0, 1});
  EXPECT_EQ(rejection(box, "box.stl"), "");
  // A two-sided sheet (the same facet in both windings) is a legitimate thin surface.
  TriangleMesh sheet;
  sheet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_EQ(rejection(sheet, "sheet.obj"), "");
}

TEST(ValidateMesh, RejectsEmpty) {
  TriangleMesh empty;
  EXPECT_NE(rejection(empty, "empty.stl").find("empty.stl"), std::string::npos);
  TriangleMesh noTriangles = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  noTriangles.triangles.clear();
  EXPECT_NE(rejection(noTriangles, "none.stl").find("no triangles"), std::string::npos);
}

TEST(ValidateMesh, RejectsNonFiniteVertex) {
  TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.vertices[3].y() = std::nanf("");
  const std::string message = rejection(box, "nan.ply");
  EXPECT_NE(message.find("nan.ply"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 3"), std::string::npos) << message;
}

TEST(ValidateMesh, RejectsIndexOutOfRange) {
  TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.triangles[5][2] = 8;
  const std::string message = rejection(box, "index.obj");
  EXPECT_NE(message.find("index.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("triangle 5"), std::string::npos) << message;
}

TEST(ValidateMesh, RejectsOnlyDegenerateFacets) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  m.triangles = {{0, 1, 2}, {0, 0, 1}, {1, 2, 2}};
  const std::string message = rejection(m, "flat.stl");
  EXPECT_NE(message.find("flat.stl"), std::string::npos) << message;
  EXPECT_NE(message.find("degenerate"), std::string::npos) << message;
}

TEST(ValidateMesh, RejectsDuplicatedFacets) {
  // The same box stored twice over the same vertices: half of the facets are copies.
  TriangleMesh twice = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const auto triangles = twice.triangles;
  twice.triangles.insert(twice.triangles.end(), triangles.begin(), triangles.end());
  const std::string message = rejection(twice, "twice.dae");
  EXPECT_NE(message.find("twice.dae"), std::string::npos) << message;
  EXPECT_NE(message.find("repeat"), std::string::npos) << message;
  // Rotating the vertex order does not hide a copy.
  TriangleMesh rotated;
  rotated.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  rotated.triangles = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  EXPECT_NE(rejection(rotated, "rotated.stl").find("repeat"), std::string::npos);
}

TEST(ValidateMesh, RejectsMeshStackedOnItself) {
  // A box stored three times (twice as given, once with reversed facets): 12 of 36 facets repeat
  // another (under the 50% duplicate limit), but all 18 edges are shared by 6 facets.
  const TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  TriangleMesh stacked = box;
  stacked.append(box);
  TriangleMesh reversed = box;
  for (auto& t : reversed.triangles)
    std::swap(t[1], t[2]);
  stacked.append(reversed);
  const std::string message = rejection(stacked, "stacked.stl");
  EXPECT_NE(message.find("stacked.stl"), std::string::npos) << message;
  EXPECT_NE(message.find("non-manifold"), std::string::npos) << message;
  EXPECT_NE(message.find("18 of 18 edges"), std::string::npos) << message;
}

TEST(ValidateMesh, EdgesAreComparedByPositionNotIndex) {
  // The same stacked box with every facet on vertices of its own (as an STL file stores it) is
  // judged the same way.
  const TriangleMesh box = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  TriangleMesh soup;
  for (int copy = 0; copy < 3; ++copy)
    for (const auto& t : box.triangles) {
      const auto base = static_cast<uint32_t>(soup.vertices.size());
      for (const uint32_t i : t)
        soup.vertices.push_back(box.vertices[i]);
      // The third copy reversed, as in RejectsMeshStackedOnItself.
      if (copy == 2)
        soup.triangles.push_back({base, base + 2, base + 1});
      else
        soup.triangles.push_back({base, base + 1, base + 2});
    }
  EXPECT_NE(rejection(soup, "soup.stl").find("18 of 18 edges"), std::string::npos);
}

TEST(ValidateMesh, AcceptsFinsAndPartsTouchingAlongAnEdge) {
  // A box (18 edges) with one fin on an edge: 1 of 20 edges (5%) is shared by 3 facets.
  TriangleMesh finned = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  finned.vertices.emplace_back(-1.0f, -1.0f, 0.0f);
  finned.triangles.push_back({0, 1, 8});
  EXPECT_EQ(rejection(finned, "finned.stl"), "");
  // Two closed boxes touching along one vertical edge (walls of a generated hangar): at most a
  // few of their 35 distinct edges are shared by 4 facets.
  TriangleMesh touching = test::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  touching.append(test::boxMesh(Vec3(1, 1, 0), Vec3(2, 2, 1)));
  EXPECT_EQ(rejection(touching, "touching.stl"), "");
}

}  // namespace
}  // namespace coinspect::world
