#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include "geometry/adjacency.h"
#include "geometry/fast_shadows.h"
#include "geometry/shadow_oracle.h"
#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

// Every directed edge of the triangles met by its reverse as often: a closed, consistently
// wound surface (what a shadow volume must be for the count to come back to zero).
bool closedSurface(const std::vector<std::uint32_t>& indices) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> balance;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
      if (a < b)
        ++balance[{a, b}];
      else
        --balance[{b, a}];
    }
  for (const auto& [edge, count] : balance)
    if (count != 0) return false;
  return true;
}

std::vector<std::uint32_t> concat(std::vector<std::uint32_t> a, const std::vector<std::uint32_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(DoubledVertexArray, EachVertexTwiceWithWOneThenZero) {
  const PreparedCaster cube = prepareCaster(makeCube(1.0f));
  const std::vector<glm::vec4> v = doubledVertexArray(cube.mesh);
  const std::size_t n = cube.mesh.positions.size();
  ASSERT_EQ(v.size(), 2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(v[i], glm::vec4(cube.mesh.positions[i], 1.0f));
    EXPECT_EQ(v[n + i], glm::vec4(cube.mesh.positions[i], 0.0f));
  }
}

TEST(SideIndices, CubeFromAboveHasFourQuadsOrFourTriangles) {
  const PreparedCaster cube = prepareCaster(makeCube(1.0f));
  const glm::vec4 point(0.2f, 5.0f, 0.1f, 1.0f), direction(0.0f, 1.0f, 0.0f, 0.0f);
  const auto edges = possibleSilhouetteEdges(cube.adjacency, facesLight(cube.mesh, point));
  ASSERT_EQ(edges.size(), 4u);
  EXPECT_EQ(sideIndices(cube.mesh, edges, false).size(), 4u * 6u);
  const auto directionalEdges = possibleSilhouetteEdges(cube.adjacency, facesLight(cube.mesh, direction));
  const auto converging = sideIndices(cube.mesh, directionalEdges, true);
  ASSERT_EQ(converging.size(), 4u * 3u);
  const auto n = static_cast<std::uint32_t>(cube.mesh.positions.size());
  for (std::size_t t = 0; t < converging.size(); t += 3) {  // two near corners and one far
    EXPECT_LT(converging[t], n);
    EXPECT_LT(converging[t + 1], n);
    EXPECT_GE(converging[t + 2], n);
  }
}

// Sides, light cap and either dark cap close the volume, for convex and non-convex casters and
// lights on every side; the directional sides close with the light cap alone.
TEST(FastVolume, SidesAndCapsAreClosed) {
  const PreparedCaster shapes[] = {prepareCaster(makeCube(1.0f)), prepareCaster(makeSphere(1.0f, 16, 8)),
                                   prepareCaster(makeTorus(1.0f, 0.35f, 24, 12))};
  const glm::vec3 lights[] = {
      {0.3f, 4.0f, 0.2f}, {-3.0f, 0.5f, 2.0f}, {0.1f, -2.5f, -2.0f}, {0.0f, 0.0f, 0.2f}};
  for (const PreparedCaster& s : shapes)
    for (const glm::vec3& l : lights) {
      const std::vector<bool> lit = facesLight(s.mesh, glm::vec4(l, 1.0f));
      const auto edges = possibleSilhouetteEdges(s.adjacency, lit);
      const auto sides = sideIndices(s.mesh, edges, false);
      const auto lightCap = lightCapIndices(s.mesh, lit);
      EXPECT_TRUE(closedSurface(concat(concat(sides, lightCap), backFaceDarkCapIndices(s.mesh, lit))));
      const DarkCap fan = fanDarkCap(s.mesh, edges, l);
      if (fan.split.empty()) {
        EXPECT_TRUE(closedSurface(concat(concat(sides, lightCap), fan.indices)));
      }
      const glm::vec4 direction(glm::normalize(l), 0.0f);
      const std::vector<bool> litFrom = facesLight(s.mesh, direction);
      // Every far copy is the same point at infinity: one index stands for them all.
      std::vector<std::uint32_t> converging =
          sideIndices(s.mesh, possibleSilhouetteEdges(s.adjacency, litFrom), true);
      const auto n = static_cast<std::uint32_t>(s.mesh.positions.size());
      for (std::uint32_t& i : converging) i = std::min(i, n);
      EXPECT_TRUE(closedSurface(concat(converging, lightCapIndices(s.mesh, litFrom))));
    }
}

// A welded unit cube without its top faces (y = 0.5): an open mesh, its rim four border edges.
Mesh openBox() {
  const Mesh cube = weldByPosition(makeCube(1.0f)).mesh;
  Mesh tray = cube;
  tray.indices.clear();
  for (std::size_t t = 0; t < cube.triangleCount(); ++t) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top &= cube.positions[cube.indices[3 * t + k]].y > 0.5f;
    if (!top)
      tray.indices.insert(tray.indices.end(), cube.indices.begin() + 3 * t, cube.indices.begin() + 3 * t + 3);
  }
  return tray;
}

// An open box (a cube without its top) and a single square: with both sides of every face
// closing a volume, sides and caps close, for either dark cap.
TEST(FastVolume, OpenMeshesCloseFromBothSides) {
  const Mesh tray = openBox();
  const Mesh square = weldByPosition(makePlane(1.0f, 2)).mesh;
  const Mesh* meshes[] = {&tray, &square};
  for (const Mesh* m : meshes) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency(m->indices, m->positions.size());
    ASSERT_GT(adjacency.report.borderEdges, 0u);
    for (const glm::vec3& l :
         {glm::vec3(0.3f, 4.0f, 0.2f), glm::vec3(-3.0f, 0.5f, 2.0f), glm::vec3(0.2f, -3.0f, 0.1f)}) {
      const std::vector<bool> lit = facesLight(*m, glm::vec4(l, 1.0f));
      const auto edges = twoSidedSilhouetteEdges(adjacency, lit);
      const auto sides = sideIndices(*m, edges, false);
      const auto lightCap = lightCapIndices(*m, lit, true);
      EXPECT_TRUE(closedSurface(concat(concat(sides, lightCap), backFaceDarkCapIndices(*m, lit, true))));
      const DarkCap fan = fanDarkCap(*m, edges, l);
      ASSERT_TRUE(fan.split.empty());
      EXPECT_TRUE(closedSurface(concat(concat(sides, lightCap), fan.indices)));
      EXPECT_EQ(lightCap.size(), m->indices.size());  // every face, one way or the other
    }
  }
}

// The fan costs one triangle per silhouette edge not touching its apex: O(s), against the
// back-face cap's O(f).
TEST(FanDarkCap, OneTrianglePerSilhouetteEdgeBesidesTheApexEdges) {
  const PreparedCaster sphere = prepareCaster(makeSphere(1.0f, 32, 16));
  const glm::vec3 light(0.5f, 6.0f, 0.3f);
  const std::vector<bool> lit = facesLight(sphere.mesh, glm::vec4(light, 1.0f));
  const auto edges = possibleSilhouetteEdges(sphere.adjacency, lit);
  const DarkCap fan = fanDarkCap(sphere.mesh, edges, light);
  EXPECT_EQ(fan.splitTriangles, 0u);
  EXPECT_EQ(fan.triangleCount(), edges.size() - 2);  // one loop: two edges touch the apex
  EXPECT_GT(backFaceDarkCapIndices(sphere.mesh, lit).size() / 3, 3 * fan.triangleCount());
}

TEST(SpanDegrees, KnownConfigurations) {
  EXPECT_NEAR(spanDegrees({1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
              2.0 * glm::degrees(std::acos(1.0 / std::sqrt(3.0))), 1e-3);
  EXPECT_NEAR(spanDegrees({1, 0, 0}, {0, 1, 0}, {1, 1, 0}), 90.0, 1e-3);    // the third on the arc
  EXPECT_NEAR(spanDegrees({1, 0, 0}, {-1, 0, 0}, {0, 0, 1}), 180.0, 1e-3);  // antipodes
  const float third = glm::radians(120.0f);                                 // around the origin in a plane
  EXPECT_NEAR(spanDegrees({1, 0, 0}, {std::cos(third), std::sin(third), 0},
                          {std::cos(2 * third), std::sin(2 * third), 0}),
              180.0, 1e-3);
  EXPECT_NEAR(spanDegrees({1, 0, 0}, {0, 0, 0}, {0, 1, 0}), 180.0, 1e-3);  // no direction
}

// A square's outline with the light just above it, over the inside of one fan triangle: that
// triangle spans almost 180 degrees and is split in three through the light's foot; the pieces
// span less and cover the same signed solid angle.
TEST(FanDarkCap, SplitsTrianglesSpanningHalfTheSky) {
  Mesh square;
  square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<SilhouetteEdge> loop = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const glm::vec3 light(0.3f, -0.2f, 0.05f);  // inside triangle 0, 1, 2
  const DarkCap cap = fanDarkCap(square, loop, light, 170.0f);
  ASSERT_EQ(cap.splitTriangles, 1u);
  ASSERT_EQ(cap.split.size(), 9u);
  ASSERT_EQ(cap.indices.size(), 3u);  // the other one, 0 3 2, spans about 152 degrees
  const auto direction = [&](const glm::vec4& v) { return glm::vec3(v) - light; };
  double pieces = 0.0;
  for (std::size_t t = 0; t < 9; t += 3) {
    EXPECT_LT(spanDegrees(direction(cap.split[t]), direction(cap.split[t + 1]), direction(cap.split[t + 2])),
              170.0f);
    pieces +=
        solidAngle(light, glm::vec3(cap.split[t]), glm::vec3(cap.split[t + 1]), glm::vec3(cap.split[t + 2]));
  }
  const double whole =
      solidAngle(light, square.positions[0], square.positions[2], square.positions[1]);  // c, b, a
  EXPECT_NEAR(pieces, whole, 1e-6);
  EXPECT_GT(std::abs(whole), 0.9 * 2.0 * M_PI);  // almost a hemisphere
}

// A light inside an open box: the shadow is everything but the opening, more than half the sky.
// The fan over the rim covers the opening instead, a whole sphere off; closeAroundLight adds
// the sphere back, and the volume's faces then subtend no solid angle at the light, as a volume
// that does not hold its light must.
TEST(FanDarkCap, ALightInsideAnOpenBoxGetsItsSphereBack) {
  const Mesh tray = openBox();
  const EdgeAdjacency adjacency = buildEdgeAdjacency(tray.indices, tray.positions.size());
  const auto n = static_cast<std::uint32_t>(tray.positions.size());
  const auto total = [&](const glm::vec3& light, const std::vector<std::uint32_t>& lightCap,
                         const DarkCap& cap) {
    double sum = 0.0;
    const auto at = [&](std::uint32_t i) { return tray.positions[i < n ? i : i - n]; };
    const std::vector<std::uint32_t>* lists[] = {&lightCap, &cap.indices};
    for (const auto* list : lists)
      for (std::size_t t = 0; t < list->size(); t += 3)
        sum += solidAngle(light, at((*list)[t]), at((*list)[t + 1]), at((*list)[t + 2]));
    for (std::size_t t = 0; t < cap.split.size(); t += 3)
      sum += solidAngle(light, glm::vec3(cap.split[t]), glm::vec3(cap.split[t + 1]),
                        glm::vec3(cap.split[t + 2]));
    return sum;
  };
  for (const glm::vec3& light : {glm::vec3(0, 0, 0), glm::vec3(0.0f, 3.0f, 0.0f)}) {
    const std::vector<bool> lit = facesLight(tray, glm::vec4(light, 1.0f));
    const auto edges = twoSidedSilhouetteEdges(adjacency, lit);
    const auto lightCap = lightCapIndices(tray, lit, true);
    DarkCap fan = fanDarkCap(tray, edges, light);
    const int spheres = closeAroundLight(fan, tray, lightCap, light);
    EXPECT_EQ(spheres != 0, light.y == 0.0f);  // inside: a sphere off; above the opening: none
    EXPECT_EQ(fan.split.size(), 24u * static_cast<std::size_t>(std::abs(spheres)));
    EXPECT_NEAR(total(light, lightCap, fan), 0.0, 1e-6);
  }
}

// A camera at the origin looking down -z.
glm::mat4 cameraAtOrigin() {
  return glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
}

TEST(ShadowCase, ThePyramidBetweenTheLightAndTheNearRectangle) {
  const glm::mat4 vp = cameraAtOrigin();
  const auto rect = nearRectangle(vp);
  for (const glm::vec3& c : rect) EXPECT_NEAR(c.z, -0.1f, 1e-5f);
  const auto frustum = viewFrustum(vp, false);
  {  // a light behind the camera
    const auto pyramid = occlusionPyramid(rect, {0, 0, 10, 1});
    EXPECT_EQ(shadowCase(pyramid, frustum, {0, 0, 5}, 0.5f), 2);   // between light and eye, unseen
    EXPECT_EQ(shadowCase(pyramid, frustum, {0, 0, -5}, 0.5f), 1);  // in front: its volume points away
    EXPECT_EQ(shadowCase(pyramid, frustum, {3, 0, 5}, 0.5f), 1);   // beside the pyramid
  }
  {  // a light in front of the camera
    const auto pyramid = occlusionPyramid(rect, {0, 0, -10, 1});
    EXPECT_EQ(shadowCase(pyramid, frustum, {0, 0, -5}, 0.5f), 3);   // seen, and shadows the eye
    EXPECT_EQ(shadowCase(pyramid, frustum, {2, 0, -5}, 0.5f), 1);   // seen, its shadow misses the eye
    EXPECT_EQ(shadowCase(pyramid, frustum, {0, 0, -15}, 0.5f), 1);  // beyond the light
  }
  {  // a directional light from behind the camera: a prism
    const auto prism = occlusionPyramid(rect, {0, 0, 1, 0});
    EXPECT_EQ(shadowCase(prism, frustum, {0, 0, 50}, 0.2f), 2);
    EXPECT_EQ(shadowCase(prism, frustum, {0, 0, -5}, 0.2f), 1);
    EXPECT_EQ(shadowCase(prism, frustum, {0, 1, 50}, 0.2f), 1);
  }
}

TEST(LightBounds, CullingAndScissor) {
  EXPECT_TRUE(culledByLight({0, 0, 0}, 2.0f, {4, 0, 0}, 1.5f));
  EXPECT_FALSE(culledByLight({0, 0, 0}, 2.0f, {3, 0, 0}, 1.5f));
  const glm::mat4 vp = cameraAtOrigin();
  const glm::ivec2 size(200, 100);
  const ScissorRect centred = lightScissor({0, 0, -10}, 1.0f, vp, size);
  EXPECT_GT(centred.width, 0);
  EXPECT_LT(centred.width, 100);
  EXPECT_NEAR(static_cast<float>(centred.x) + 0.5f * static_cast<float>(centred.width), 100.0f, 1.0f);
  EXPECT_NEAR(static_cast<float>(centred.y) + 0.5f * static_cast<float>(centred.height), 50.0f, 1.0f);
  // The sphere's silhouette lies inside the rectangle: its extreme point on the view's x axis.
  const float tangent = std::asin(1.0f / 10.0f);  // half the angle the sphere subtends
  const float ndcX = std::tan(tangent) / std::tan(glm::radians(30.0f));
  EXPECT_LE(static_cast<float>(centred.x), 100.0f * (1.0f - ndcX));
  const ScissorRect around = lightScissor({0, 0, 0}, 1.0f, vp, size);  // the eye inside
  EXPECT_EQ(around.width, 200);
  EXPECT_EQ(around.height, 100);
  EXPECT_EQ(lightScissor({0, 0, 10}, 1.0f, vp, size).width, 0);    // behind the camera
  EXPECT_EQ(lightScissor({50, 0, -10}, 1.0f, vp, size).width, 0);  // beside the view
}

// The oracle for a bounded light: a receiver beyond the radius is neither lit nor shadowed.
TEST(LightBounds, TheOracleJudgesOnlyWithinTheRadius) {
  const Mesh ground = makePlane(3.0f, 1);
  const glm::mat4 topDown = glm::ortho(-3.0f, 3.0f, -3.0f, 3.0f, 0.1f, 20.0f) *
                            glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::vec4 light(0, 1, 0, 1);  // one above the ground's centre
  const float radius = 2.0f;          // reaches a disc of radius sqrt(3) on the ground
  std::size_t lit = 0, outOfReach = 0;
  for (const PixelClass c :
       classifyPixels({{&ground, glm::mat4(1), false, true}}, light, topDown, {60, 60}, radius)) {
    lit += c == PixelClass::Lit;
    outOfReach += c == PixelClass::OutOfReach;
  }
  EXPECT_NEAR(static_cast<double>(lit), 3600.0 * M_PI * 3.0 / 36.0, 40.0);
  EXPECT_EQ(lit + outOfReach, 3600u);
}

// The sphere's nearest and farthest points along the view, at their window depths.
TEST(LightBounds, DepthBoundsHoldTheSphere) {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  const auto depthOf = [&](const glm::vec3& p) {
    const glm::vec4 clip = projection * view * glm::vec4(p, 1.0f);
    return 0.5f * clip.z / clip.w + 0.5f;
  };
  const DepthBounds b = lightDepthBounds({0, 0, 0}, 1.0f, view, projection);
  EXPECT_NEAR(b.nearest, depthOf({0, 0, 1}), 1e-6f);
  EXPECT_NEAR(b.farthest, depthOf({0, 0, -1}), 1e-6f);
  const DepthBounds around = lightDepthBounds({0, 0, 4}, 2.0f, view, projection);  // the eye inside
  EXPECT_EQ(around.nearest, 0.0f);
  const DepthBounds infinite =
      lightDepthBounds({0, 0, 0}, 1.0f, view, glm::infinitePerspective(glm::radians(60.0f), 1.0f, 0.1f));
  EXPECT_LT(infinite.farthest, 1.0f);
}

TEST(WorldBounds, FollowsARigidMotion) {
  const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1), {1, 2, 3}), 0.7f, glm::vec3(0, 1, 0));
  const BoundingSphere s = worldBounds({{1, 0, 0}, 0.5f}, m);
  EXPECT_NEAR(glm::length(s.centre - glm::vec3(m * glm::vec4(1, 0, 0, 1))), 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(s.radius, 0.5f);
}

}  // namespace

namespace {

// A camera at the origin looking down -z, a point light behind it: a caster between them is in
// the occlusion pyramid (case 2), one in front of the camera is not (case 1), one far off the
// light's bounds is culled.
std::vector<int> casesFor(float radius) {
  const glm::mat4 vp = cameraAtOrigin();
  const glm::vec4 light(0, 0, 10, 1);
  const std::vector<BoundingSphere> casters = {{{0, 0, 5}, 0.5f}, {{0, 0, -5}, 0.5f}, {{40, 0, -5}, 0.5f}};
  LightClip clip;
  clip.centre = glm::vec3(light);
  clip.radius = radius;
  return shadowCases(casters, clip, occlusionPyramid(nearRectangle(vp), light), viewFrustum(vp, false));
}

}  // namespace

TEST(ShadowCases, ByThePyramidAndTheLightsBounds) {
  EXPECT_EQ(casesFor(20.0f), (std::vector<int>{2, 1, 0}));  // the third beyond the light's reach
  EXPECT_EQ(casesFor(std::numeric_limits<float>::infinity()), (std::vector<int>{2, 1, 1}));  // no culling
}

TEST(RecipeFor, EachMethodPerCase) {
  const auto recipe = [](ShadowMethod m, int shadowCase, bool anyInPyramid, bool lightCap = true,
                         bool directional = false) {
    const Recipe r = recipeFor(m, shadowCase, anyInPyramid, lightCap, directional);
    return std::tuple(r.zfail, r.darkCap, r.lightCap);
  };
  using K = DarkCapKind;
  // McGuire et al.: z-pass outside the pyramid, the fan inside it, the light cap when on screen.
  EXPECT_EQ(recipe(ShadowMethod::McGuire, 1, true), std::tuple(false, K::None, false));
  EXPECT_EQ(recipe(ShadowMethod::McGuire, 2, true), std::tuple(true, K::Fan, false));
  EXPECT_EQ(recipe(ShadowMethod::McGuire, 3, true), std::tuple(true, K::Fan, true));
  EXPECT_EQ(recipe(ShadowMethod::McGuire, 3, true, false), std::tuple(true, K::Fan, false));
  EXPECT_EQ(recipe(ShadowMethod::McGuire, 3, true, true, true), std::tuple(true, K::None, true));
  // Everitt and Kilgard: both full caps, whatever the case.
  for (int c : {1, 2, 3})
    EXPECT_EQ(recipe(ShadowMethod::EverittKilgard, c, false), std::tuple(true, K::BackFaces, true));
  // Lengyel: z-pass until some caster of the light is in the pyramid, then full z-fail for all.
  EXPECT_EQ(recipe(ShadowMethod::Lengyel, 1, false), std::tuple(false, K::None, false));
  EXPECT_EQ(recipe(ShadowMethod::Lengyel, 1, true), std::tuple(true, K::BackFaces, true));
  for (int c : {1, 2, 3}) EXPECT_EQ(recipe(ShadowMethod::ZPass, c, true), std::tuple(false, K::None, false));
  for (ShadowMethod m : {ShadowMethod::McGuire, ShadowMethod::EverittKilgard, ShadowMethod::Lengyel})
    EXPECT_EQ(recipe(m, 0, true), std::tuple(false, K::None, false));  // culled: no volume
}

TEST(VolumeOf, RangesFollowTheRecipe) {
  const PreparedCaster cube = prepareCaster(makeCube(0.5f));
  const glm::vec4 light(0.3f, 3.0f, 0.2f, 1.0f);
  const std::vector<bool> lit = facesLight(cube.mesh, light);
  const std::vector<SilhouetteEdge> edges = possibleSilhouetteEdges(cube, lit);
  const VolumeIndices zpass = volumeOf(cube, light, {false, DarkCapKind::None, false}, lit, edges);
  EXPECT_EQ(zpass.volume.sides, 4u * 6u);  // four silhouette edges, a quad each
  EXPECT_EQ(zpass.volume.darkCap + zpass.volume.lightCap, 0u);
  EXPECT_EQ(zpass.indices.size(), zpass.volume.sides + zpass.volume.silhouette);
  const VolumeIndices fan = volumeOf(cube, light, {true, DarkCapKind::Fan, true}, lit, edges);
  EXPECT_EQ(fan.volume.darkCap, 3u * 2u);   // four edges, the apex's two left out
  EXPECT_EQ(fan.volume.lightCap, 3u * 2u);  // the top face
  EXPECT_EQ(volumeOf(cube, light, {true, DarkCapKind::Fan, false}, lit, edges).volume.lightCap, 0u);
  const VolumeIndices full = volumeOf(cube, light, {true, DarkCapKind::BackFaces, true}, lit, edges);
  EXPECT_EQ(full.volume.darkCap, 3u * 10u);  // the five faces away from the light
  EXPECT_EQ(full.volume.lightCap, 3u * 2u);
  std::vector<std::uint32_t> closed(
      full.indices.begin(),
      full.indices.begin() +
          static_cast<std::ptrdiff_t>(full.volume.sides + full.volume.darkCap + full.volume.lightCap));
  EXPECT_TRUE(closedSurface(closed));
}

TEST(LightClip, BoundedOrNot) {
  const glm::mat4 projection = cameraAtOrigin(), view(1.0f);
  const glm::ivec2 size(200, 100);
  const LightClip bounded = lightClip({0, 0, -10, 1}, 1.0f, true, view, projection, size);
  EXPECT_TRUE(bounded.depthBounds);
  EXPECT_LT(bounded.scissor.width, 200);
  EXPECT_LT(bounded.depth.nearest, bounded.depth.farthest);
  const LightClip off = lightClip({0, 0, -10, 1}, 1.0f, false, view, projection, size);
  EXPECT_FALSE(off.depthBounds);
  EXPECT_EQ(off.scissor.width, 200);
  EXPECT_EQ(off.scissor.height, 100);
  const LightClip directional = lightClip({0, 1, 0, 0}, 1.0f, true, view, projection, size);
  EXPECT_TRUE(std::isinf(directional.radius));
  EXPECT_FALSE(directional.offScreen());
  EXPECT_TRUE(lightClip({0, 0, 10, 1}, 1.0f, true, view, projection, size).offScreen());  // behind the eye
}
