#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/mesh.h"
#include "geometry/shapes.h"

namespace {

using stencil::Aabb;

void expectVecNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(Aabb, StartsEmpty) {
  const Aabb box;
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.centre(), glm::vec3(0.0f));
  EXPECT_EQ(box.extent(), glm::vec3(0.0f));
  EXPECT_TRUE(stencil::boundsOf({}).empty());
}

TEST(Aabb, SinglePointIsAZeroSizeBox) {
  Aabb box;
  box.extend({1, -2, 3});
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.min, glm::vec3(1, -2, 3));
  EXPECT_EQ(box.max, glm::vec3(1, -2, 3));
  EXPECT_EQ(box.extent(), glm::vec3(0.0f));
  EXPECT_EQ(box.centre(), glm::vec3(1, -2, 3));
}

TEST(Aabb, BoundsOfKnownPoints) {
  // Per-axis min and max picked from different points.
  const Aabb box = stencil::boundsOf({{1, 5, -1}, {-3, 2, 4}, {0, -6, 2}});
  EXPECT_EQ(box.min, glm::vec3(-3, -6, -1));
  EXPECT_EQ(box.max, glm::vec3(1, 5, 4));
  EXPECT_EQ(box.centre(), glm::vec3(-1, -0.5f, 1.5f));
  EXPECT_EQ(box.extent(), glm::vec3(4, 11, 5));  // full size, not half
}

TEST(Aabb, BoundsOfShapesMatchTheirSize) {
  const Aabb cube = stencil::boundsOf(stencil::makeCube(0.5f).positions);
  EXPECT_EQ(cube.min, glm::vec3(-0.5f));
  EXPECT_EQ(cube.max, glm::vec3(0.5f));

  // 8 slices put vertices on +-x and +-z; even stacks put a ring on the equator.
  const Aabb sphere = stencil::boundsOf(stencil::makeSphere(2.0f, 8, 4).positions);
  expectVecNear(sphere.min, glm::vec3(-2.0f), 1e-6f);
  expectVecNear(sphere.max, glm::vec3(2.0f), 1e-6f);

  const Aabb cone = stencil::boundsOf(stencil::makeCone(1.0f, 3.0f, 4).positions);
  expectVecNear(cone.min, {-1.0f, -1.5f, -1.0f}, 1e-6f);
  expectVecNear(cone.max, {1.0f, 1.5f, 1.0f}, 1e-6f);
}

TEST(Aabb, TransformedBoundsOfRotatedCube) {
  // Rotating a cube of half extent h by 45 degrees about y swings its
  // corners (h, *, h) onto the x axis at distance h*sqrt(2); y is unchanged.
  const float h = 1.0f;
  const glm::mat4 r = glm::rotate(glm::mat4(1.0f), std::numbers::pi_v<float> / 4.0f, glm::vec3(0, 1, 0));
  const Aabb box = stencil::transformedBounds(stencil::boundsOf(stencil::makeCube(h).positions), r);
  const float reach = h * std::sqrt(2.0f);
  expectVecNear(box.min, {-reach, -h, -reach}, 1e-5f);
  expectVecNear(box.max, {reach, h, reach}, 1e-5f);
}

TEST(Aabb, TransformedBoundsMatchTransformedBoxMesh) {
  // For a box the 8 corners are the mesh's own vertices, so both routes agree.
  const stencil::Mesh cube = stencil::makeCube(0.7f);
  const glm::mat4 moved = glm::translate(glm::mat4(1.0f), {3, -1, 2});
  const glm::mat4 m = glm::scale(glm::rotate(moved, 0.4f, glm::normalize(glm::vec3(1, 1, 0))), {1, 2, 0.5f});
  const Aabb viaCorners = stencil::transformedBounds(stencil::boundsOf(cube.positions), m);
  const Aabb viaMesh = stencil::boundsOf(stencil::transformed(cube, m).positions);
  expectVecNear(viaCorners.min, viaMesh.min, 1e-5f);
  expectVecNear(viaCorners.max, viaMesh.max, 1e-5f);
}

TEST(Aabb, TransformedBoundsTranslateAndStayEmpty) {
  const Aabb box = stencil::boundsOf({{0, 0, 0}, {1, 2, 3}});
  const Aabb moved = stencil::transformedBounds(box, glm::translate(glm::mat4(1.0f), {10, 20, 30}));
  EXPECT_EQ(moved.min, glm::vec3(10, 20, 30));
  EXPECT_EQ(moved.max, glm::vec3(11, 22, 33));
  EXPECT_TRUE(stencil::transformedBounds(Aabb{}, glm::mat4(2.0f)).empty());
}

void expectContainsAll(const std::vector<glm::vec3>& points) {
  const stencil::BoundingSphere s = stencil::boundingSphereOf(points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LE(glm::distance(points[i], s.centre), s.radius) << "point " << i;
  }
  // Never worse than the sphere around the AABB centre reaching the farthest
  // point, which in turn is within the sphere through the AABB's corners.
  const Aabb box = stencil::boundsOf(points);
  float aroundBox = 0.0f;
  for (const glm::vec3& p : points) aroundBox = std::max(aroundBox, glm::distance(p, box.centre()));
  EXPECT_LE(s.radius, aroundBox * (1.0f + 1e-5f) + 1e-30f);
  EXPECT_LE(aroundBox, 0.5f * glm::length(box.extent()) * (1.0f + 1e-5f));
}

TEST(BoundingSphere, ContainsEveryVertexOfEveryShape) {
  for (const stencil::Mesh& m : {stencil::makePlane(2.0f, 3), stencil::makeCube(0.5f),
                                 stencil::makeSphere(1.0f, 13, 7), stencil::makeTorus(2.0f, 0.3f, 17, 9),
                                 stencil::makeCylinder(0.3f, 5.0f, 11), stencil::makeCone(2.0f, 0.5f, 7)}) {
    expectContainsAll(m.positions);
  }
  // Off-centre and rotated copies, so the centre is not trivially the origin.
  const glm::mat4 m =
      glm::rotate(glm::translate(glm::mat4(1.0f), {5, -3, 8}), 1.1f, glm::vec3(0.2f, 1, 0.3f));
  expectContainsAll(stencil::transformed(stencil::makeTorus(1.0f, 0.6f, 23, 11), m).positions);
  expectContainsAll(stencil::transformed(stencil::makeCone(1.0f, 4.0f, 5), m).positions);
}

TEST(BoundingSphere, TightOnKnownSets) {
  // Two points: the sphere with them as a diameter.
  const stencil::BoundingSphere pair = stencil::boundingSphereOf({{-1, 0, 0}, {3, 0, 0}});
  expectVecNear(pair.centre, {1, 0, 0}, 1e-6f);
  EXPECT_NEAR(pair.radius, 2.0f, 1e-5f);

  // A sphere mesh: every vertex is at distance r from the origin, the poles
  // are +-r apart, so the answer is the sphere itself.
  const stencil::BoundingSphere sphere =
      stencil::boundingSphereOf(stencil::makeSphere(1.5f, 12, 6).positions);
  expectVecNear(sphere.centre, glm::vec3(0.0f), 1e-5f);
  EXPECT_NEAR(sphere.radius, 1.5f, 1e-5f);

  const stencil::BoundingSphere single = stencil::boundingSphereOf({{4, 5, 6}});
  EXPECT_EQ(single.centre, glm::vec3(4, 5, 6));
  EXPECT_GE(single.radius, 0.0f);
  EXPECT_LT(single.radius, 1e-6f);
}

TEST(BoundingSphere, EquilateralTriangle) {
  // Unit circumradius triangle in z = 0: the minimal sphere is the circumcircle,
  // and the AABB centre (0.25, 0, 0) is off by a quarter, so the AABB sphere
  // (radius sqrt(0.75^2 + 0.75) ~ 1.146) is not the answer to expect.
  const float s = std::sqrt(3.0f) / 2.0f;
  const std::vector<glm::vec3> points = {{1, 0, 0}, {-0.5f, s, 0}, {-0.5f, -s, 0}};
  expectContainsAll(points);
  EXPECT_LE(stencil::boundingSphereOf(points).radius, std::sqrt(0.75f * 0.75f + 0.75f) * 1.00001f);
}

TEST(BoundingSphere, NoPointsThrows) {
  EXPECT_THROW(stencil::boundingSphereOf({}), std::invalid_argument);
}

}  // namespace
