// CPU ray casting: hits derived by hand on simple geometry, and the hierarchy checked
// against brute-force loops over every triangle (rays at a flat grid's edges, a torus).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

#include "geometry/mesh.h"
#include "geometry/raycast.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

// Right triangle in the plane z = 2 with legs of length 2 along x and y; its
// hypotenuse is x + y = 2. Wound so that the front faces +z.
const glm::vec3 kA(0.0f, 0.0f, 2.0f), kB(2.0f, 0.0f, 2.0f), kC(0.0f, 2.0f, 2.0f);

void expectVecNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Mesh singleTriangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  Mesh m;
  m.positions = {a, b, c};
  m.indices = {0, 1, 2};
  return m;
}

glm::mat4 translation(glm::vec3 offset) {
  return glm::translate(glm::mat4(1.0f), offset);
}

}  // namespace

TEST(Raycast, TriangleHitAtDerivedT) {
  // Straight down the z axis: from z = -1 to the plane z = 2 is 3 units, at speed 3.
  const std::optional<float> straight =
      intersectTriangle({{0.5f, 0.5f, -1.0f}, {0.0f, 0.0f, 3.0f}}, kA, kB, kC);
  ASSERT_TRUE(straight.has_value());
  EXPECT_NEAR(*straight, 1.0f, 1e-6f);

  // Obliquely: z climbs 1.5 per unit t, so the plane is reached at t = 2, at (0.5, 1, 2).
  const Ray oblique{{0.0f, 0.0f, -1.0f}, {0.25f, 0.5f, 1.5f}};
  const std::optional<float> t = intersectTriangle(oblique, kA, kB, kC);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 2.0f, 1e-6f);
  expectVecNear(oblique.origin + *t * oblique.direction, {0.5f, 1.0f, 2.0f}, 1e-6f);
}

TEST(Raycast, MissesJustOutsideAnEdge) {
  const glm::vec3 down(0.0f, 0.0f, 1.0f);
  // Across the hypotenuse x + y = 2.
  EXPECT_TRUE(intersectTriangle({{0.999f, 0.999f, 0.0f}, down}, kA, kB, kC).has_value());
  EXPECT_FALSE(intersectTriangle({{1.001f, 1.001f, 0.0f}, down}, kA, kB, kC).has_value());
  // Across the legs x = 0 and y = 0.
  EXPECT_TRUE(intersectTriangle({{0.001f, 0.5f, 0.0f}, down}, kA, kB, kC).has_value());
  EXPECT_FALSE(intersectTriangle({{-0.001f, 0.5f, 0.0f}, down}, kA, kB, kC).has_value());
  EXPECT_TRUE(intersectTriangle({{0.5f, 0.001f, 0.0f}, down}, kA, kB, kC).has_value());
  EXPECT_FALSE(intersectTriangle({{0.5f, -0.001f, 0.0f}, down}, kA, kB, kC).has_value());
}

TEST(Raycast, ParallelRayNeverHits) {
  // In the triangle's own plane, passing right through it.
  EXPECT_FALSE(intersectTriangle({{-1.0f, 0.5f, 2.0f}, {1.0f, 0.0f, 0.0f}}, kA, kB, kC).has_value());
  // Parallel to it, just above.
  EXPECT_FALSE(intersectTriangle({{-1.0f, 0.5f, 2.001f}, {1.0f, 0.2f, 0.0f}}, kA, kB, kC).has_value());
  // Tilted slightly out of the plane, it does hit, where the plane is crossed: t = 0.001 / 0.001.
  const std::optional<float> t =
      intersectTriangle({{-0.5f, 0.5f, 2.001f}, {1.0f, 0.0f, -0.001f}}, kA, kB, kC);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 1.0f, 1e-3f);
}

TEST(Raycast, RespectsTMinAndTMaxAsAnOpenInterval) {
  const Ray ray{{0.5f, 0.5f, 0.0f}, {0.0f, 0.0f, 2.0f}};  // hits at t = 1
  EXPECT_TRUE(intersectTriangle(ray, kA, kB, kC, 0.0f, 1.001f).has_value());
  EXPECT_FALSE(intersectTriangle(ray, kA, kB, kC, 0.0f, 1.0f).has_value());
  EXPECT_FALSE(intersectTriangle(ray, kA, kB, kC, 0.0f, 0.999f).has_value());
  EXPECT_TRUE(intersectTriangle(ray, kA, kB, kC, 0.999f).has_value());
  EXPECT_FALSE(intersectTriangle(ray, kA, kB, kC, 1.0f).has_value());
  EXPECT_FALSE(intersectTriangle(ray, kA, kB, kC, 1.001f).has_value());
  // Behind the origin: t = -1, outside the default (0, inf), inside a range that admits it.
  const Ray away{{0.5f, 0.5f, 4.0f}, {0.0f, 0.0f, 2.0f}};
  EXPECT_FALSE(intersectTriangle(away, kA, kB, kC).has_value());
  const std::optional<float> behind = intersectTriangle(away, kA, kB, kC, -2.0f);
  ASSERT_TRUE(behind.has_value());
  EXPECT_NEAR(*behind, -1.0f, 1e-6f);
}

TEST(Raycast, BothWindingsHitAndTheNormalFollowsTheWinding) {
  const Ray fromBelow{{0.5f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}};
  const Ray fromAbove{{0.5f, 0.5f, 5.0f}, {0.0f, 0.0f, -1.0f}};
  for (const Ray& ray : {fromBelow, fromAbove}) {
    const std::optional<float> front = intersectTriangle(ray, kA, kB, kC);
    const std::optional<float> back = intersectTriangle(ray, kA, kC, kB);
    ASSERT_TRUE(front.has_value());
    ASSERT_TRUE(back.has_value());
    EXPECT_FLOAT_EQ(*front, *back);
  }

  // (b - a) x (c - a) = (2, 0, 0) x (0, 2, 0) points along +z; the reversed triangle along -z.
  RayScene scene;
  scene.add(singleTriangle(kA, kB, kC), glm::mat4(1.0f));
  scene.add(singleTriangle(kA, kC, kB), translation({0.0f, 0.0f, 1.0f}));  // at z = 3
  const std::optional<RayHit> ccw = scene.firstHit(fromBelow);
  ASSERT_TRUE(ccw.has_value());
  EXPECT_EQ(ccw->object, 0);
  EXPECT_NEAR(ccw->t, 2.0f, 1e-6f);
  expectVecNear(ccw->normal, {0.0f, 0.0f, 1.0f}, 1e-6f);
  const std::optional<RayHit> cw = scene.firstHit(fromAbove);
  ASSERT_TRUE(cw.has_value());
  EXPECT_EQ(cw->object, 1);
  EXPECT_NEAR(cw->t, 2.0f, 1e-6f);
  expectVecNear(cw->normal, {0.0f, 0.0f, -1.0f}, 1e-6f);
}

TEST(Raycast, DegenerateTriangleNeverHits) {
  // Collinear corners and a repeated corner, each with a ray straight through the segment.
  const glm::vec3 p(0.0f, 0.0f, 0.0f), q(1.0f, 1.0f, 0.0f), r(2.0f, 2.0f, 0.0f);
  const Ray throughQ{{1.0f, 1.0f, -1.0f}, {0.0f, 0.0f, 1.0f}};
  EXPECT_FALSE(intersectTriangle(throughQ, p, q, r).has_value());
  EXPECT_FALSE(intersectTriangle(throughQ, p, r, r).has_value());
  EXPECT_FALSE(intersectTriangle(throughQ, q, q, q).has_value());
  // Collinear on paper, but rounding the corners to float leaves a sliver whose edges are
  // a few ulps from parallel. An unguarded test divides by that tiny determinant and reports
  // hits for about one such ray in ten.
  std::mt19937 rng(7u);
  const auto uniform = [&] {
    return -1.0f + 2.0f * static_cast<float>(rng() >> 8) / static_cast<float>(1u << 24);
  };
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 a(uniform(), uniform(), uniform()), e(uniform(), uniform(), uniform());
    const glm::vec3 d(uniform(), uniform(), uniform());
    const glm::vec3 through = a + 0.5f * e;
    if (intersectTriangle({through - d, d}, a, a + e, a + (1.75f + 0.5f * uniform()) * e)) ++hits;
  }
  EXPECT_EQ(hits, 0);
  // A zero direction is parallel to everything.
  EXPECT_FALSE(intersectTriangle({{0.5f, 0.5f, 0.0f}, glm::vec3(0.0f)}, kA, kB, kC).has_value());
}

TEST(Raycast, CubeHitFromOutsideAlongEachAxis) {
  // Unit cube (half extent 0.5) centred at (1, 2, 3). From 3 units out along an axis with
  // speed 2 towards the centre, the face at 0.5 is 2.5 units away: t = 1.25.
  const glm::vec3 centre(1.0f, 2.0f, 3.0f);
  const Mesh cube = makeCube(0.5f);
  RayScene scene;
  ASSERT_EQ(scene.add(cube, translation(centre)), 0);
  EXPECT_EQ(scene.objectCount(), 1u);
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {1.0f, -1.0f}) {
      glm::vec3 outward(0.0f);
      outward[axis] = side;
      // Off the face's centre (and its diagonal), inside the face.
      glm::vec3 offset(0.0f);
      offset[(axis + 1) % 3] = 0.2f;
      offset[(axis + 2) % 3] = -0.1f;
      const Ray ray{centre + 3.0f * outward + offset, -2.0f * outward};
      SCOPED_TRACE(testing::Message() << "axis " << axis << " side " << side);
      const std::optional<RayHit> hit = scene.firstHit(ray);
      ASSERT_TRUE(hit.has_value());
      EXPECT_EQ(hit->object, 0);
      EXPECT_NEAR(hit->t, 1.25f, 1e-6f);
      expectVecNear(hit->normal, outward, 1e-6f);
      // The reported triangle really is one on that face.
      ASSERT_GE(hit->triangle, 0);
      ASSERT_LT(hit->triangle, static_cast<int>(cube.triangleCount()));
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 corner = cube.positions[cube.indices[3 * hit->triangle + k]];
        EXPECT_FLOAT_EQ(corner[axis], 0.5f * side);
      }
    }
  }
  // From inside, the far face is hit: 0.5 away at speed 1.
  const std::optional<RayHit> inside = scene.firstHit({centre, {0.0f, 1.0f, 0.0f}});
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->t, 0.5f, 1e-6f);
  expectVecNear(inside->normal, {0.0f, 1.0f, 0.0f}, 1e-6f);
  // A ray passing beside the cube misses.
  EXPECT_FALSE(scene.firstHit({centre + glm::vec3(0.51f, 3.0f, 0.0f), {0.0f, -1.0f, 0.0f}}).has_value());
}

TEST(Raycast, MirroredObjectKeepsOutwardNormals) {
  // As transformed() does, a mirroring model flips the winding so the cube stays outward-facing.
  RayScene scene;
  scene.add(makeCube(0.5f), glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f}));
  const std::optional<RayHit> hit = scene.firstHit({{3.0f, 0.1f, 0.2f}, {-1.0f, 0.0f, 0.0f}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 2.5f, 1e-6f);
  expectVecNear(hit->normal, {1.0f, 0.0f, 0.0f}, 1e-6f);
}

TEST(Raycast, FirstHitPicksTheNearerObject) {
  // Cubes centred at x = 2 and x = 5; from the origin along +x their near faces are at 1.5 and 4.5.
  RayScene scene;
  const int far = scene.add(makeCube(0.5f), translation({5.0f, 0.0f, 0.0f}));
  const int near = scene.add(makeCube(0.5f), translation({2.0f, 0.0f, 0.0f}));
  EXPECT_EQ(far, 0);
  EXPECT_EQ(near, 1);
  EXPECT_EQ(scene.objectCount(), 2u);
  const Ray ray{{0.0f, 0.1f, -0.2f}, {1.0f, 0.0f, 0.0f}};
  const std::optional<RayHit> first = scene.firstHit(ray);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->object, near);
  EXPECT_NEAR(first->t, 1.5f, 1e-6f);
  // Starting past the near cube, the far one is the first.
  const std::optional<RayHit> later = scene.firstHit(ray, 2.6f);
  ASSERT_TRUE(later.has_value());
  EXPECT_EQ(later->object, far);
  EXPECT_NEAR(later->t, 4.5f, 1e-6f);
  // Stopping short of both finds nothing.
  EXPECT_FALSE(scene.firstHit(ray, 0.0f, 1.5f).has_value());
  // Inside the near cube, its own back face (x = 2.5) comes first.
  const std::optional<RayHit> within = scene.firstHit(ray, 1.6f);
  ASSERT_TRUE(within.has_value());
  EXPECT_EQ(within->object, near);
  EXPECT_NEAR(within->t, 2.5f, 1e-6f);
  expectVecNear(within->normal, {1.0f, 0.0f, 0.0f}, 1e-6f);
}

TEST(Raycast, OccludedRespectsTheCastsFilter) {
  // A floor point under a blocker cube, a point light above both.
  RayScene scene;
  const int floor = scene.add(makePlane(5.0f), glm::mat4(1.0f));
  const int blocker = scene.add(makeCube(0.5f), translation({0.0f, 2.0f, 0.0f}));
  const LightRay toLight = rayTowardsLight({0.1f, 0.0f, 0.1f}, {0.0f, 4.0f, 0.0f, 1.0f});
  // tMin above 0 so the floor the point lies on does not count.
  const float tMin = 1e-4f;
  EXPECT_TRUE(scene.occluded(toLight.ray, tMin, toLight.tMax));
  EXPECT_TRUE(scene.occluded(toLight.ray, tMin, toLight.tMax, [&](int o) { return o == blocker; }));
  EXPECT_FALSE(scene.occluded(toLight.ray, tMin, toLight.tMax, [&](int o) { return o == floor; }));
  EXPECT_FALSE(scene.occluded(toLight.ray, tMin, toLight.tMax, [](int) { return false; }));
  // Off to the side, the light is in plain view.
  const LightRay clear = rayTowardsLight({3.0f, 0.0f, 3.0f}, {0.0f, 4.0f, 0.0f, 1.0f});
  EXPECT_FALSE(scene.occluded(clear.ray, tMin, clear.tMax));
  // Just above the floor, the floor is behind the ray (t < 0) and cannot occlude even with tMin = 0.
  const LightRay above = rayTowardsLight({3.0f, 0.01f, 3.0f}, {0.0f, 4.0f, 0.0f, 1.0f});
  EXPECT_FALSE(scene.occluded(above.ray, 0.0f, above.tMax));
}

TEST(Raycast, BlockerBeyondAPointLightDoesNotOcclude) {
  // The light at y = 1 sits between the point at the origin and the cube at y = 3 (faces at 2.5, 3.5).
  RayScene scene;
  scene.add(makeCube(0.5f), translation({0.0f, 3.0f, 0.0f}));
  const LightRay point = rayTowardsLight({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f, 1.0f});
  EXPECT_FALSE(scene.occluded(point.ray, 0.0f, point.tMax));
  // The same ray unbounded, or a light from that direction at infinity, is blocked.
  EXPECT_TRUE(scene.occluded(point.ray, 0.0f, INFINITY));
  const LightRay sun = rayTowardsLight({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f});
  EXPECT_TRUE(scene.occluded(sun.ray, 0.0f, sun.tMax));
  // Moving the light past the cube puts the cube in between.
  const LightRay behind = rayTowardsLight({0.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f, 1.0f});
  EXPECT_TRUE(scene.occluded(behind.ray, 0.0f, behind.tMax));
}

TEST(Raycast, RayTowardsLightForPointAndDirection) {
  const glm::vec3 point(1.0f, -2.0f, 0.5f);
  const LightRay toPoint = rayTowardsLight(point, {4.0f, 2.0f, -1.0f, 1.0f});
  EXPECT_EQ(toPoint.ray.origin, point);
  EXPECT_EQ(toPoint.tMax, 1.0f);
  expectVecNear(toPoint.ray.origin + toPoint.tMax * toPoint.ray.direction, {4.0f, 2.0f, -1.0f}, 1e-6f);
  // w = 2 is the same point light written with another scale.
  const LightRay scaled = rayTowardsLight(point, {8.0f, 4.0f, -2.0f, 2.0f});
  expectVecNear(scaled.ray.direction, toPoint.ray.direction, 1e-6f);
  EXPECT_EQ(scaled.tMax, 1.0f);

  const LightRay toSun = rayTowardsLight(point, {0.0f, 3.0f, 4.0f, 0.0f});
  EXPECT_EQ(toSun.ray.origin, point);
  EXPECT_TRUE(std::isinf(toSun.tMax) && toSun.tMax > 0.0f);
  // Pointing towards the light, not away from it.
  EXPECT_NEAR(glm::dot(glm::normalize(toSun.ray.direction), glm::vec3(0.0f, 0.6f, 0.8f)), 1.0f, 1e-6f);

  EXPECT_THROW(rayTowardsLight(point, {0.0f, 0.0f, 0.0f, 0.0f}), std::invalid_argument);
  EXPECT_THROW(rayTowardsLight(point, {std::nanf(""), 1.0f, 0.0f, 1.0f}), std::invalid_argument);
}

TEST(Raycast, AddRejectsBrokenMeshes) {
  RayScene scene;
  Mesh nan = singleTriangle(kA, kB, kC);
  nan.positions[1].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(scene.add(nan, glm::mat4(1.0f)), std::invalid_argument);
  Mesh infinite = singleTriangle(kA, kB, kC);
  infinite.positions[2].z = std::numeric_limits<float>::infinity();
  EXPECT_THROW(scene.add(infinite, glm::mat4(1.0f)), std::invalid_argument);
  Mesh outOfRange = singleTriangle(kA, kB, kC);
  outOfRange.indices[2] = 3;
  EXPECT_THROW(scene.add(outOfRange, glm::mat4(1.0f)), std::invalid_argument);
  Mesh partial = singleTriangle(kA, kB, kC);
  partial.indices.push_back(0);
  EXPECT_THROW(scene.add(partial, glm::mat4(1.0f)), std::invalid_argument);
  // Finite positions that overflow under the model matrix.
  Mesh huge = singleTriangle(kA, kB, {0.0f, 3e38f, 0.0f});
  EXPECT_THROW(scene.add(huge, glm::scale(glm::mat4(1.0f), glm::vec3(10.0f))), std::invalid_argument);
  // A flattening model matrix, as transformed() refuses it.
  EXPECT_THROW(scene.add(singleTriangle(kA, kB, kC), glm::scale(glm::mat4(1.0f), {1.0f, 0.0f, 1.0f})),
               std::invalid_argument);
  EXPECT_EQ(scene.objectCount(), 0u);

  // A rejected mesh leaves no trace: the next good one is object 0, and an empty mesh is
  // a valid object that nothing hits.
  EXPECT_EQ(scene.add(Mesh{}, glm::mat4(1.0f)), 0);
  EXPECT_EQ(scene.add(singleTriangle(kA, kB, kC), glm::mat4(1.0f)), 1);
  const std::optional<RayHit> hit = scene.firstHit({{0.5f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->object, 1);
  EXPECT_EQ(hit->triangle, 0);
}

TEST(Raycast, RaysAimedAtTheEdgesOfAFlatGridAreNotLost) {
  // Every box of a flat grid is zero-thick in y and the aimed-at points lie on box faces,
  // where the slab test's rounding would reject about one ray in twenty without its margin.
  const Mesh grid = makePlane(1.0f, 8);
  RayScene scene;
  scene.add(grid, glm::mat4(1.0f));
  std::mt19937 rng(99u);
  const auto uniform = [&](float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(rng() >> 8) / static_cast<float>(1u << 24);
  };
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const std::size_t triangle = rng() % grid.triangleCount();
    const glm::vec3 a = grid.positions[grid.indices[3 * triangle]];
    const glm::vec3 b = grid.positions[grid.indices[3 * triangle + 1]];
    const glm::vec3 target = (i % 2 == 0) ? a : a + uniform(0.0f, 1.0f) * (b - a);  // a corner or an edge
    const glm::vec3 origin(uniform(-3.0f, 3.0f), uniform(0.1f, 3.0f), uniform(-3.0f, 3.0f));
    const Ray ray{origin, target - origin};
    std::optional<float> bruteT;
    for (std::size_t t = 0; t < grid.triangleCount() && !bruteT; ++t) {
      bruteT =
          intersectTriangle(ray, grid.positions[grid.indices[3 * t]], grid.positions[grid.indices[3 * t + 1]],
                            grid.positions[grid.indices[3 * t + 2]]);
    }
    if (!bruteT) continue;  // rounding put the aimed-at point outside every triangle
    ++checked;
    const std::optional<RayHit> hit = scene.firstHit(ray);
    ASSERT_TRUE(hit.has_value()) << "ray " << i;
    EXPECT_NEAR(hit->t, *bruteT, 1e-5f) << "ray " << i;
    EXPECT_TRUE(scene.occluded(ray, 0.0f, INFINITY)) << "ray " << i;
    // The same hit behind a reversed ray, where the box exits are negative t.
    const std::optional<RayHit> behind = scene.firstHit({origin, -ray.direction}, -INFINITY, 0.0f);
    ASSERT_TRUE(behind.has_value()) << "ray " << i;
    EXPECT_NEAR(behind->t, -*bruteT, 1e-5f) << "ray " << i;
  }
  EXPECT_GT(checked, 350);
}

TEST(Raycast, HierarchyMatchesBruteForceOnATorus) {
  const glm::mat4 model =
      glm::rotate(translation({0.3f, -0.2f, 0.5f}), 0.7f, glm::normalize(glm::vec3(1, 2, 0.5f)));
  const Mesh torus = makeTorus(0.7f, 0.25f, 48, 24);
  const Mesh world = transformed(torus, model);
  RayScene scene;
  scene.add(torus, model);

  // mt19937's output is fixed by the standard (the distributions are not), so map it by hand.
  std::mt19937 rng(20240611u);
  const auto uniform = [&](float lo, float hi) {
    return lo + (hi - lo) * static_cast<float>(rng() >> 8) / static_cast<float>(1u << 24);
  };
  const auto jitter = [&](float half) {
    return glm::vec3(uniform(-half, half), uniform(-half, half), uniform(-half, half));
  };

  int hits = 0, misses = 0, sameTriangle = 0;
  for (int i = 0; i < 400; ++i) {
    // From anywhere in a box around the torus towards a point near its surface, so most rays hit.
    Ray ray{glm::vec3(0.3f, -0.2f, 0.5f) + jitter(2.0f), glm::vec3(0.0f)};
    const glm::vec3 target = world.positions[rng() % world.positions.size()] + jitter(0.1f);
    ray.direction = (target - ray.origin) * uniform(0.3f, 3.0f);
    // Some axis-parallel components, for the box tests' zero-direction path.
    if (i % 7 == 0) ray.direction.x = 0.0f;
    if (i % 11 == 0) ray.direction.z = 0.0f;
    const float tMin = (i % 3 == 0) ? uniform(0.0f, 0.5f) : 0.0f;
    const float tMax = (i % 5 == 0) ? uniform(0.5f, 2.0f) : INFINITY;

    std::optional<float> bestT;
    int bestTriangle = -1;
    for (std::size_t t = 0; t < world.triangleCount(); ++t) {
      const std::optional<float> h = intersectTriangle(
          ray, world.positions[world.indices[3 * t]], world.positions[world.indices[3 * t + 1]],
          world.positions[world.indices[3 * t + 2]], tMin, bestT.value_or(tMax));
      if (h) {
        bestT = h;
        bestTriangle = static_cast<int>(t);
      }
    }

    SCOPED_TRACE(testing::Message() << "ray " << i);
    const std::optional<RayHit> hit = scene.firstHit(ray, tMin, tMax);
    EXPECT_EQ(scene.occluded(ray, tMin, tMax), bestT.has_value());
    ASSERT_EQ(hit.has_value(), bestT.has_value());
    if (!hit) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_EQ(hit->object, 0);
    EXPECT_NEAR(hit->t, *bestT, 1e-5f);
    if (hit->triangle == bestTriangle) {
      ++sameTriangle;
      const glm::vec3 a = world.positions[world.indices[3 * bestTriangle]];
      const glm::vec3 b = world.positions[world.indices[3 * bestTriangle + 1]];
      const glm::vec3 c = world.positions[world.indices[3 * bestTriangle + 2]];
      expectVecNear(hit->normal, glm::normalize(glm::cross(b - a, c - a)), 1e-5f);
    } else {
      // A tie on a shared edge: the other triangle must really be hit there too.
      const std::optional<float> other =
          intersectTriangle(ray, world.positions[world.indices[3 * hit->triangle]],
                            world.positions[world.indices[3 * hit->triangle + 1]],
                            world.positions[world.indices[3 * hit->triangle + 2]], tMin, tMax);
      ASSERT_TRUE(other.has_value());
      EXPECT_NEAR(*other, *bestT, 1e-5f);
    }
    EXPECT_NEAR(glm::length(hit->normal), 1.0f, 1e-5f);
  }
  // Both outcomes well represented, and ties are rare, so the comparison means something.
  EXPECT_GT(hits, 200);
  EXPECT_GT(misses, 40);
  EXPECT_GT(sameTriangle, hits - 5);
}
