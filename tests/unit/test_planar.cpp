// Shadow and reflection matrices: checked against their defining properties, with points
// and planes in general position (no axis-aligned shortcuts).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/matrix.hpp>

#include "geometry/planar.h"

using namespace stencil;

namespace {

const glm::vec4 kTilted = planeFrom({0.3f, -0.2f, 0.5f}, {0.2f, 1.0f, -0.3f});
const glm::vec3 kPoints[] = {{1.0f, 2.0f, 0.5f}, {-0.7f, 0.9f, 1.3f}, {2.5f, 3.0f, -1.0f}};

glm::vec3 project(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 h = m * glm::vec4(p, 1.0f);
  return glm::vec3(h) / h.w;
}

}  // namespace

TEST(Planar, PlaneFromHasUnitNormalAndContainsThePoint) {
  EXPECT_NEAR(glm::length(glm::vec3(kTilted)), 1.0f, 1e-6f);
  EXPECT_NEAR(planeDistance(kTilted, {0.3f, -0.2f, 0.5f}), 0.0f, 1e-6f);
}

TEST(Planar, PointShadowLandsOnThePlaneOnTheLineFromTheLight) {
  const glm::vec3 light(0.5f, 6.0f, -0.4f);
  const glm::mat4 m = planarShadowMatrix(kTilted, glm::vec4(light, 1.0f));
  for (glm::vec3 p : kPoints) {
    const glm::vec3 s = project(m, p);
    EXPECT_NEAR(planeDistance(kTilted, s), 0.0f, 1e-4f);
    // s, p and the light are collinear, and p lies between the light and its shadow.
    EXPECT_NEAR(glm::length(glm::cross(s - light, p - light)), 0.0f, 1e-3f);
    EXPECT_GT(glm::dot(s - light, p - light), 0.0f);
    EXPECT_GT(glm::length(s - light), glm::length(p - light));
  }
}

TEST(Planar, DirectionalShadowMovesAlongTheLightDirection) {
  const glm::vec3 towardsLight = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::mat4 m = planarShadowMatrix(kTilted, glm::vec4(towardsLight, 0.0f));
  for (glm::vec3 p : kPoints) {
    const glm::vec3 s = project(m, p);
    EXPECT_NEAR(planeDistance(kTilted, s), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(glm::cross(s - p, towardsLight)), 0.0f, 1e-4f);
  }
}

TEST(Planar, PointsOnThePlaneAreTheirOwnShadow) {
  const glm::mat4 m = planarShadowMatrix(kTilted, glm::vec4(0.5f, 6.0f, -0.4f, 1.0f));
  const glm::vec3 onPlane = glm::vec3(0.3f, -0.2f, 0.5f) + glm::cross(glm::vec3(kTilted), glm::vec3(1, 0, 0));
  const glm::vec3 s = project(m, onPlane);
  EXPECT_NEAR(glm::length(s - onPlane), 0.0f, 1e-5f);
}

TEST(Planar, TheLightItselfMapsToZero) {
  const glm::vec4 light(0.5f, 6.0f, -0.4f, 1.0f);
  const glm::vec4 image = planarShadowMatrix(kTilted, light) * light;
  EXPECT_NEAR(glm::length(image), 0.0f, 1e-4f);
}

TEST(Planar, ReflectionMirrorsAndIsItsOwnInverse) {
  const glm::mat4 r = reflectionMatrix(kTilted);
  EXPECT_NEAR(glm::determinant(r), -1.0f, 1e-5f);
  for (glm::vec3 p : kPoints) {
    const glm::vec3 q = project(r, p);
    EXPECT_NEAR(planeDistance(kTilted, q), -planeDistance(kTilted, p), 1e-5f);
    EXPECT_NEAR(glm::length(glm::cross(q - p, glm::vec3(kTilted))), 0.0f, 1e-5f);  // moved along n
    EXPECT_NEAR(glm::length(project(r, q) - p), 0.0f, 1e-5f);
  }
}
