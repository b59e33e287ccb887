#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "geometry/raycast.h"
#include "geometry/shadow_oracle.h"
#include "geometry/shapes.h"

namespace {

using namespace stencil;

TEST(IntersectSphere, NearestRootInRange) {
  const Ray ray{{0, 0, -5}, {0, 0, 1}};
  ASSERT_TRUE(intersectSphere(ray, {0, 0, 0}, 1.0f).has_value());
  EXPECT_FLOAT_EQ(*intersectSphere(ray, {0, 0, 0}, 1.0f), 4.0f);
  EXPECT_FLOAT_EQ(*intersectSphere(ray, {0, 0, 0}, 1.0f, 4.5f), 6.0f) << "from inside: the far root";
  EXPECT_FALSE(intersectSphere(ray, {0, 0, 0}, 1.0f, 0.0f, 3.9f).has_value()) << "beyond tMax";
  EXPECT_FALSE(intersectSphere(ray, {0, 2, 0}, 1.0f).has_value()) << "passes by";
  EXPECT_FALSE(intersectSphere(ray, {0, 0, -10}, 1.0f).has_value()) << "behind the origin";
}

// A sphere above a ground, light straight above: the oracle with the true sphere shadows a
// disc, and a coarse mesh sphere (inscribed, so smaller) shadows less of it.
TEST(OracleSphere, TrueSphereShadowsMoreThanItsInscribedMesh) {
  const Mesh ground = makePlane(3.0f, 1);
  const Mesh coarse = makeSphere(1.0f, 6, 3);
  const glm::mat4 at = glm::translate(glm::mat4(1), {0, 2, 0});
  const glm::vec4 light(0, 1, 0, 0);
  const glm::mat4 topDown = glm::ortho(-3.0f, 3.0f, -3.0f, 3.0f, 0.1f, 20.0f) *
                            glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::ivec2 size(60, 60);
  const auto count = [&](const std::vector<OracleObject>& objects) {
    std::size_t shadowed = 0, other = 0;
    for (const PixelClass c : classifyPixels(objects, light, topDown, size)) {
      shadowed += c == PixelClass::Shadowed;
      other += c == PixelClass::Other;
    }
    return std::pair{shadowed, other};
  };
  // Seen from straight above along the light, the caster hides its whole shadow: what shows is
  // the caster itself (Other), the true disc larger than the inscribed mesh's hexagon.
  const auto [trueShadow, trueSeen] = count(
      {{&ground, glm::mat4(1), false, true}, {nullptr, glm::mat4(1), true, false, glm::vec4(0, 2, 0, 1)}});
  const auto [meshShadow, meshSeen] =
      count({{&ground, glm::mat4(1), false, true}, {&coarse, at, true, false}});
  EXPECT_EQ(trueShadow, 0u) << "straight above, the sphere covers its whole shadow";
  // The disc of radius 1 covers pi / 36 of the 6x6 view: about 314 of 3600 pixels.
  EXPECT_NEAR(static_cast<double>(trueSeen), 3600.0 * M_PI / 36.0, 25.0);
  EXPECT_LT(meshSeen, trueSeen) << "the inscribed hexagonal sphere is smaller";
  EXPECT_EQ(meshShadow, 0u);

  // Seen at an angle, the shadow shows; the true sphere's is larger.
  const glm::mat4 slanted = glm::perspective(1.0f, 1.0f, 0.1f, 50.0f) *
                            glm::lookAt(glm::vec3(0, 6, 7), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
  std::size_t trueShadowed = 0, meshShadowed = 0;
  for (const PixelClass c : classifyPixels({{&ground, glm::mat4(1), false, true},
                                            {nullptr, glm::mat4(1), true, false, glm::vec4(0, 2, 0, 1)}},
                                           light, slanted, size))
    trueShadowed += c == PixelClass::Shadowed;
  for (const PixelClass c : classifyPixels({{&ground, glm::mat4(1), false, true}, {&coarse, at, true, false}},
                                           light, slanted, size))
    meshShadowed += c == PixelClass::Shadowed;
  EXPECT_GT(trueShadowed, meshShadowed);
  EXPECT_GT(meshShadowed, 0u);
}

// The far plane at infinity (glm::infinitePerspective) gives the oracle the same rays as a far
// plane beyond everything: the same classes pixel for pixel, and both see the scene.
TEST(Oracle, FarPlaneAtInfinitySeesWhatAFiniteOneSees) {
  const Mesh ground = makePlane(3.0f, 1);
  const Mesh box = makeCube(0.5f);
  const std::vector<OracleObject> objects{{&ground, glm::mat4(1), false, true},
                                          {&box, glm::translate(glm::mat4(1), {0, 1, 0}), true, true}};
  const glm::mat4 view = glm::lookAt(glm::vec3(4, 4, 6), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::vec4 light(1.5f, 4.0f, -0.8f, 1.0f);
  const glm::ivec2 size(64, 48);
  const auto finite =
      classifyPixels(objects, light, glm::perspective(0.8f, 4.0f / 3.0f, 0.5f, 100.0f) * view, size);
  const auto infinite =
      classifyPixels(objects, light, glm::infinitePerspective(0.8f, 4.0f / 3.0f, 0.5f) * view, size);
  EXPECT_EQ(finite, infinite);
  EXPECT_GT(std::count(infinite.begin(), infinite.end(), PixelClass::Shadowed), 0);
  EXPECT_GT(std::count(infinite.begin(), infinite.end(), PixelClass::Lit), 0);
}

// A bounded point light claims nothing beyond its radius: those receiver pixels are OutOfReach,
// and the others keep their class.
TEST(Oracle, NothingIsClaimedBeyondAPointLightsRadius) {
  const Mesh ground = makePlane(6.0f, 1);
  const Mesh box = makeCube(0.5f);
  const std::vector<OracleObject> objects{{&ground, glm::mat4(1), false, true},
                                          {&box, glm::translate(glm::mat4(1), {0, 1, 0}), true, true}};
  const glm::mat4 viewProjection = glm::perspective(0.9f, 4.0f / 3.0f, 0.5f, 100.0f) *
                                   glm::lookAt(glm::vec3(6, 6, 8), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::vec4 light(0.3f, 3.0f, 0.2f, 1.0f);
  const glm::ivec2 size(64, 48);
  const auto unbounded = classifyPixels(objects, light, viewProjection, size);
  const auto bounded = classifyPixels(objects, light, viewProjection, size, 4.0f);
  std::size_t outOfReach = 0;
  for (std::size_t i = 0; i < bounded.size(); ++i) {
    if (bounded[i] == PixelClass::OutOfReach) {
      outOfReach += unbounded[i] != PixelClass::OutOfReach;
      EXPECT_NE(unbounded[i], PixelClass::Empty);
      EXPECT_NE(unbounded[i], PixelClass::Other);
    } else {
      EXPECT_EQ(bounded[i], unbounded[i]);
    }
  }
  EXPECT_GT(outOfReach, 0u);
  EXPECT_GT(std::count(bounded.begin(), bounded.end(), PixelClass::Lit), 0);
  // A directional light has no bounds: the radius is ignored.
  EXPECT_EQ(classifyPixels(objects, glm::vec4(0.1f, 1, 0.2f, 0), viewProjection, size, 4.0f),
            classifyPixels(objects, glm::vec4(0.1f, 1, 0.2f, 0), viewProjection, size));
}

// A face edge-on to the light gets no light at all, lit or shadowed: no claim is made there.
TEST(Oracle, NothingIsClaimedOnAFaceEdgeOnToTheLight) {
  const Mesh box = makeCube(0.5f);
  const Mesh ground = makePlane(6.0f, 1);
  const std::vector<OracleObject> objects{{&ground, glm::mat4(1), false, true},
                                          {&box, glm::translate(glm::mat4(1), {0, 0.5f, 0}), true, true}};
  // Looking at the box's +z face (z = 0.5) head on.
  const glm::mat4 viewProjection =
      glm::perspective(0.6f, 1.0f, 0.5f, 100.0f) *
      glm::lookAt(glm::vec3(0, 0.5f, 5), glm::vec3(0, 0.5f, 0), glm::vec3(0, 1, 0));
  const glm::ivec2 size(32, 32);
  const auto centre = [&](const glm::vec4& light) {
    return classifyPixels(objects, light, viewProjection, size)[16 * 32 + 16];
  };
  EXPECT_EQ(centre({0.8f, 3.0f, 0.5f, 1.0f}), PixelClass::OutOfReach) << "the light in the face's plane";
  EXPECT_EQ(centre({0.8f, 3.0f, 0.6f, 1.0f}), PixelClass::Lit);
  EXPECT_EQ(centre({0.8f, 3.0f, 0.4f, 1.0f}), PixelClass::Shadowed) << "behind the face: the box blocks it";
  EXPECT_EQ(centre({1.0f, 0.0f, 0.0f, 0.0f}), PixelClass::OutOfReach) << "a directional light along the face";
}

}  // namespace

namespace {

// The face of a box a hair turned from a directional light (cos -2e-4): the stencil puts it in
// the box's own volume, so the ray cast must call it shadowed, though a shadow ray started off
// it would skim along the face and leave the box.
TEST(Oracle, ACastersSideTurnedFromTheLightIsShadowed) {
  const Mesh box = makeCube(1.0f);
  const glm::vec4 light(glm::normalize(glm::vec3(1.0f, 0.0f, -2e-4f)), 0.0f);
  const glm::mat4 front = glm::perspective(0.6f, 1.0f, 0.1f, 50.0f) *
                          glm::lookAt(glm::vec3(0, 0, 6), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::ivec2 size(40, 40);
  std::vector<int> surfaces;
  const auto classes = classifyPixels({{&box, glm::mat4(1), true, true}}, light, front, size,
                                      std::numeric_limits<float>::infinity(), &surfaces);
  std::size_t face = 0, shadowed = 0;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    // The side turned from the light is a surface of its own: object 0 plus the one object.
    face += surfaces[i] == 1;
    shadowed += classes[i] == PixelClass::Shadowed;
    EXPECT_EQ(surfaces[i] == 1, classes[i] != PixelClass::Empty) << "pixel " << i;
  }
  EXPECT_GT(face, 100u);
  EXPECT_EQ(shadowed, face) << "every pixel of the face turned from the light";
}

// A disagreement is forgiven where the class changes within 3x3, and, given the surfaces the
// ray cast saw, where the surface changes: a silhouette between two lit surfaces.
TEST(Oracle, ASilhouetteBetweenTwoLitSurfacesIsAnEdge) {
  const glm::ivec2 size(5, 5);
  const std::vector<PixelClass> classes(25, PixelClass::Lit);
  std::vector<bool> lit(25, true);
  lit[12] = false;  // the centre pixel reads shadowed
  std::vector<int> surfaces(25, 0);
  EXPECT_FALSE(compareWithOracle(classes, lit, size).passed()) << "one surface: not an edge";
  EXPECT_FALSE(compareWithOracle(classes, lit, size, &surfaces).passed());
  surfaces[13] = 1;  // another object begins right of the centre
  EXPECT_TRUE(compareWithOracle(classes, lit, size, &surfaces).passed());
  EXPECT_EQ(compareWithOracle(classes, lit, size, &surfaces).onEdges, 1u);
  surfaces[13] = 0;
  surfaces[24] = 1;  // two pixels away: the centre is not on it
  EXPECT_FALSE(compareWithOracle(classes, lit, size, &surfaces).passed());
}

}  // namespace
