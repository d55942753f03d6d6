#include "coinspect/eval/scene_render.h"

#include <gtest/gtest.h>

namespace coinspect::eval {

namespace {
// An axis-aligned 10 m cube centred at (0, 0, 5), resting on the ground.
world::TriangleMesh cube() {
  world::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back((i & 1) ? 5.f : -5.f, (i & 2) ? 5.f : -5.f, (i & 4) ? 10.f : 0.f);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}
}  // namespace

TEST(ViewCamera, ProjectionAndRayThroughAreInverse) {
  ViewCamera camera;
  camera.eye = {-40, -30, 20};
  camera.target = {0, 0, 5};
  const Vec3 p(3, -2, 7);
  double x, y, depth;
  ASSERT_TRUE(camera.project(p, x, y, depth));
  const Vec3 direction = camera.rayThrough(x - 0.5, y - 0.5);
  EXPECT_NEAR(direction.dot((p - camera.eye).normalized()), 1.0, 1e-9);
  // The target projects to the image centre; a point behind the eye does not project.
  ASSERT_TRUE(camera.project(camera.target, x, y, depth));
  EXPECT_NEAR(x, camera.width / 2.0, 1e-9);
  EXPECT_NEAR(y, camera.height / 2.0, 1e-9);
  EXPECT_FALSE(camera.project(2 * camera.eye - camera.target, x, y, depth));
}

TEST(RenderScene, StructureAtCentreSkyAtTopVisibleMarkersOnly) {
  const world::RayCaster caster({cube()}, 0.0);
  ViewCamera camera;
  camera.width = 160;
  camera.height = 90;
  camera.eye = {-40, 0, 5};
  camera.target = {0, 0, 5};
  SceneOverlay overlay;
  const Rgb visible{1, 250, 1}, hidden{250, 1, 250};
  overlay.points.push_back({Vec3(-5, 0, 5), visible, 2.0});  // on the face toward the camera
  overlay.points.push_back({Vec3(5, 0, 5), hidden, 2.0});    // on the far face: occluded
  const RgbImage image = renderScene(caster, camera, overlay);
  const Rgb centre = image.at(80, 45);
  EXPECT_EQ(centre, visible);  // the visible marker sits exactly at the image centre
  // The sky at the top row is bluish (b > r), the cube's face next to the marker is grey.
  EXPECT_GT(image.at(80, 0).b, image.at(80, 0).r);
  const Rgb face = image.at(80, 60);
  EXPECT_LT(std::abs(int(face.r) - int(face.g)), 20);
  int hiddenPixels = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      hiddenPixels += image.at(x, y) == hidden;
  EXPECT_EQ(hiddenPixels, 0);
}

}  // namespace coinspect::eval
