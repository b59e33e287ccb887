// Depth complexity on the CPU: counts derived by hand for nested cubes seen face on, the near and
// far planes, front and back faces, and the edge rule of compareCounts; RayScene::allHits against
// a loop over every triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/depth_complexity.h"
#include "geometry/raycast.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

// Looking down -z from z = 5 at the origin, 60 degrees, square 41x41 image.
glm::mat4 frontView(float nearPlane = 0.5f, float farPlane = 20.0f) {
  return glm::perspective(glm::radians(60.0f), 1.0f, nearPlane, farPlane) *
         glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
}

// A pixel near the middle, off the centre: the centre's ray runs along the diagonal each cube face
// is split on, and crosses both of its triangles.
std::uint32_t middle(const std::vector<std::uint32_t>& counts) {
  return counts[18 * 41 + 21];
}

}  // namespace

TEST(DepthComplexity, NestedCubesCountTwoFacesEachThroughTheMiddle) {
  const Mesh big = makeCube(1.0f), mid = makeCube(0.6f), small = makeCube(0.3f);
  const std::vector<OracleObject> cubes = {{&big, glm::mat4(1), false, false},
                                           {&mid, glm::mat4(1), false, false},
                                           {&small, glm::mat4(1), false, false}};
  const glm::ivec2 size(41, 41);
  EXPECT_EQ(middle(depthComplexity(cubes, frontView(), size)), 6u);  // in and out of each
  EXPECT_EQ(middle(depthComplexity(cubes, frontView(), size, FacesCounted::Front)), 3u);
  EXPECT_EQ(middle(depthComplexity(cubes, frontView(), size, FacesCounted::Back)), 3u);
  // The corner pixel's ray passes by every cube: the big cube's half-size 1 at distance 4 to 6 is
  // well inside a 60 degree view's middle, far from its corner.
  EXPECT_EQ(depthComplexity(cubes, frontView(), size)[0], 0u);
  // All = front + back at every pixel.
  const auto all = depthComplexity(cubes, frontView(), size);
  const auto front = depthComplexity(cubes, frontView(), size, FacesCounted::Front);
  const auto back = depthComplexity(cubes, frontView(), size, FacesCounted::Back);
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], front[i] + back[i]) << i;
}

TEST(DepthComplexity, OnlyWhatLiesBetweenTheNearAndTheFarPlane) {
  const Mesh cube = makeCube(1.0f);  // faces at z = 1 and -1: 4 and 6 units from the eye
  const std::vector<OracleObject> scene = {{&cube, glm::mat4(1), false, false}};
  const glm::ivec2 size(41, 41);
  EXPECT_EQ(middle(depthComplexity(scene, frontView(4.5f, 20.0f), size)), 1u);  // the front face clipped
  EXPECT_EQ(middle(depthComplexity(scene, frontView(0.5f, 5.0f), size)), 1u);   // the back face clipped
  EXPECT_EQ(middle(depthComplexity(scene, frontView(4.5f, 5.0f), size)), 0u);
  // A far plane at infinity clips nothing behind.
  const glm::mat4 infinite = glm::infinitePerspective(glm::radians(60.0f), 1.0f, 0.5f) *
                             glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
  EXPECT_EQ(middle(depthComplexity(scene, infinite, size)), 2u);
}

TEST(DepthComplexity, ASphereObjectIsRefused) {
  const std::vector<OracleObject> scene = {{nullptr, glm::mat4(1), false, false, glm::vec4(0, 0, 0, 1)}};
  EXPECT_THROW(depthComplexity(scene, frontView(), {4, 4}), std::invalid_argument);
}

TEST(DepthComplexity, CompareForgivesOnlyEdgesOfTheExpectedPicture) {
  const glm::ivec2 size(5, 5);
  std::vector<std::uint32_t> expected(25, 1);
  for (int y = 0; y < 5; ++y)
    expected[static_cast<std::size_t>(y * 5 + 4)] = 2;  // a column of 2 at the right
  std::vector<std::uint32_t> actual = expected;
  actual[3] = 2;   // beside the column: an edge, forgiven
  actual[12] = 0;  // the middle, all 1s around: wrong
  const CountReport r = compareCounts(expected, actual, size);
  EXPECT_EQ(r.disagreements, 2u);
  EXPECT_EQ(r.onEdges, 1u);
  EXPECT_FALSE(r.passed());
  EXPECT_EQ(r.expectedTotal, 30u);
  EXPECT_EQ(r.actualTotal, 30u);
  EXPECT_THROW(compareCounts(expected, std::vector<std::uint32_t>(3), size), std::invalid_argument);
}

TEST(RaycastAllHits, EveryTriangleALoopFindsAndNoMore) {
  const Mesh torus = makeTorus(1.0f, 0.35f, 24, 12);
  const glm::mat4 model = glm::rotate(glm::mat4(1), 0.7f, glm::vec3(1, 0.2f, 0));
  RayScene scene;
  scene.add(torus, model);
  const Mesh world = transformed(torus, model);
  for (int i = 0; i < 200; ++i) {
    const float a = 0.05f * static_cast<float>(i);
    const Ray ray{{3.0f * std::cos(a), 0.3f * std::sin(3.0f * a), 3.0f * std::sin(a)},
                  {-std::cos(a), 0.05f, -std::sin(a) + 0.1f * std::cos(2.0f * a)}};
    std::size_t brute = 0;
    for (std::size_t t = 0; t < world.triangleCount(); ++t)
      brute += intersectTriangle(ray, world.positions[world.indices[3 * t]],
                                 world.positions[world.indices[3 * t + 1]],
                                 world.positions[world.indices[3 * t + 2]])
                   .has_value();
    EXPECT_EQ(scene.allHits(ray).size(), brute) << i;
  }
}
