// Reflection culling: frusta through mirrors checked against brute force (a ray from the
// reflected eye through the mirror polygon), the worst-case count against the paper's
// figures, and the far plane moved without touching the rest of the projection.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "geometry/mirror.h"
#include "geometry/planar.h"

using namespace stencil;

namespace {

const glm::mat4 kProjection = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 20.0f);
const glm::mat4 kView =
    glm::lookAt(glm::vec3(0.5f, 1.0f, 4.0f), glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0, 1, 0));

bool inside(const Frustum& f, glm::vec3 p) {
  return !outside(f, BoundingSphere{p, 0.0f});
}

// A tilted square mirror, corners counter-clockwise seen from its reflective side.
struct Square {
  glm::vec4 plane;
  std::vector<glm::vec3> corners;
};
Square tiltedMirror() {
  const glm::vec3 centre(0.2f, 1.0f, -1.0f), n = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
  const glm::vec3 u = glm::normalize(glm::cross(glm::vec3(0, 1, 0), n)), v = glm::cross(n, u);
  return {planeFrom(centre, n), {centre - u - v, centre + u - v, centre + u + v, centre - u + v}};
}

// Does the segment from a to b cross the convex polygon (in its plane)?
bool segmentCrossesPolygon(glm::vec3 a, glm::vec3 b, const Square& m) {
  const float da = planeDistance(m.plane, a), db = planeDistance(m.plane, b);
  if ((da > 0) == (db > 0)) return false;
  const glm::vec3 hit = a + (b - a) * (da / (da - db));
  const glm::vec3 n(m.plane);
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 e = m.corners[(i + 1) % 4] - m.corners[i];
    if (glm::dot(glm::cross(e, hit - m.corners[i]), n) < 0.0f) return false;
  }
  return true;
}

}  // namespace

TEST(Mirror, FrustumOfKeepsWhatTheCameraSees) {
  const Frustum f = viewFrustum(kProjection * kView);
  ASSERT_EQ(f.planes.size(), 6u);
  EXPECT_TRUE(inside(f, {0.0f, 0.8f, 0.0f}));                                          // the target
  EXPECT_FALSE(inside(f, {0.5f, 1.0f, 6.0f}));                                         // behind the eye
  EXPECT_FALSE(inside(f, {0.0f, 0.8f, -30.0f}));                                       // past the far plane
  EXPECT_TRUE(inside(viewFrustum(kProjection * kView, false), {0.0f, 0.8f, -30.0f}));  // no far plane
  EXPECT_FALSE(inside(f, {20.0f, 0.8f, 0.0f}));                                        // far to the right
  for (const glm::vec4& p : f.planes) EXPECT_NEAR(glm::length(glm::vec3(p)), 1.0f, 1e-5f);
}

TEST(Mirror, SphereOutsideOnlyWhenWhollyBehindOnePlane) {
  const Frustum f = viewFrustum(kProjection * kView);
  EXPECT_TRUE(outside(f, BoundingSphere{{0.5f, 1.0f, 6.0f}, 1.0f}));
  EXPECT_FALSE(outside(f, BoundingSphere{{0.5f, 1.0f, 6.0f}, 2.5f}));  // reaches past the near plane
  EXPECT_FALSE(outside(f, BoundingSphere{{0.0f, 0.8f, 0.0f}, 0.1f}));
}

TEST(Mirror, PointsOutsideNeedOnePlaneBehindAll) {
  const Frustum f = viewFrustum(kProjection * kView);
  // One point left of the view, one right: no single plane has both behind it.
  EXPECT_FALSE(outside(f, {{-30.0f, 0.8f, 0.0f}, {30.0f, 0.8f, 0.0f}}));
  EXPECT_TRUE(outside(f, {{-30.0f, 0.8f, 0.0f}, {-25.0f, 0.0f, 1.0f}}));
}

TEST(Mirror, TransformPlaneFollowsThePoints) {
  const glm::vec4 plane = planeFrom({0.3f, -0.2f, 0.5f}, {0.2f, 1.0f, -0.3f});
  const glm::mat4 rigid =
      glm::rotate(glm::translate(glm::mat4(1), {1, 2, 3}), 0.7f, glm::vec3(0.3f, 1, 0.2f));
  const glm::mat4 mirror = reflectionMatrix(planeFrom({0, 1, -2}, {0.4f, 0.1f, 1.0f}));
  for (const glm::mat4& m : {rigid, mirror, rigid * mirror}) {
    const glm::vec4 moved = transformPlane(plane, m);
    EXPECT_NEAR(glm::length(glm::vec3(moved)), 1.0f, 1e-5f);
    for (const glm::vec3 x : {glm::vec3(1, 2, 0.5f), glm::vec3(-0.7f, 0.9f, 1.3f), glm::vec3(2.5f, -3, -1)})
      EXPECT_NEAR(planeDistance(moved, glm::vec3(m * glm::vec4(x, 1))), planeDistance(plane, x), 1e-4f);
  }
}

TEST(Mirror, FacesEyeOnlyFromTheReflectiveSide) {
  const glm::vec4 wall = planeFrom({0, 0, -2}, {0, 0, 1});
  EXPECT_TRUE(facesEye(wall, {0, 1, 0}));
  EXPECT_FALSE(facesEye(wall, {0, 1, -3}));
  EXPECT_FALSE(facesEye(wall, {0, 1, -2}));  // edge-on: nothing to see
}

// Brute force: a point is seen in the mirror when the segment from the reflected eye to it
// crosses the mirror polygon and its mirror image is in the camera's frustum. The frustum
// through the mirror must keep every such point (conservative) and, the pyramid being exact
// for a convex polygon, reject every point the brute force rejects by a clear margin.
TEST(Mirror, ThroughMirrorMatchesBruteForce) {
  const Square m = tiltedMirror();
  const glm::vec3 eye(0.5f, 1.0f, 4.0f);
  const Frustum camera = viewFrustum(kProjection * kView, false);
  const Frustum seen = throughMirror(camera, eye, m.corners, m.plane);
  const glm::mat4 reflect = reflectionMatrix(m.plane);
  const glm::vec3 virtualEye = glm::vec3(reflect * glm::vec4(eye, 1));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-6.0f, 6.0f);
  int visible = 0, rejected = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 x(coord(rng), coord(rng), coord(rng));
    const bool truth =
        segmentCrossesPolygon(virtualEye, x, m) && inside(camera, glm::vec3(reflect * glm::vec4(x, 1)));
    if (truth) {
      ++visible;
      EXPECT_TRUE(inside(seen, x)) << x.x << " " << x.y << " " << x.z;
    } else if (!inside(seen, x)) {
      ++rejected;
    }
  }
  EXPECT_GT(visible, 100);
  EXPECT_GT(rejected, 15000);  // culls most of space, not just a little
}

// Two parallel mirrors, the eye between them facing one: the other is behind the eye, out
// of the camera's frustum, yet seen through the first. A mirror standing off to the side,
// out of the first mirror's view, is culled from the first reflection.
TEST(Mirror, MirrorSeenOnlyThroughAnotherMirror) {
  const glm::vec3 eye(0.3f, 1.0f, 1.0f);
  const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f, 1.0f, -2.0f), glm::vec3(0, 1, 0));
  const Frustum camera = viewFrustum(kProjection * view, false);
  const auto wall = [](float z, float facing) {
    return Square{planeFrom({0, 0, z}, {0, 0, facing}),
                  {{-1.5f, 0.2f, z}, {1.5f, 0.2f, z}, {1.5f, 1.8f, z}, {-1.5f, 1.8f, z}}};
  };
  const Square front = wall(-2.0f, 1.0f), back = wall(2.0f, -1.0f);
  EXPECT_FALSE(outside(camera, front.corners));
  EXPECT_TRUE(outside(camera, back.corners));  // behind the viewer
  const Frustum first = throughMirror(camera, eye, front.corners, front.plane);
  EXPECT_FALSE(outside(first, back.corners));  // seen in the front mirror
  // A small mirror far to the side, facing the room: not visible in the front mirror.
  const Square side{planeFrom({-12, 1, 0}, {1, 0, 0}),
                    {{-12, 0.5f, 0.5f}, {-12, 0.5f, -0.5f}, {-12, 1.5f, -0.5f}, {-12, 1.5f, 0.5f}}};
  EXPECT_TRUE(outside(first, side.corners));
  // One bounce deeper, through the back mirror from the reflected eye: the front mirror again.
  const glm::vec3 virtualEye = glm::vec3(reflectionMatrix(front.plane) * glm::vec4(eye, 1));
  ASSERT_TRUE(facesEye(back.plane, virtualEye));
  const Frustum second = throughMirror(first, virtualEye, back.corners, back.plane);
  EXPECT_FALSE(outside(second, front.corners));
  EXPECT_GT(second.planes.size(), first.planes.size());  // each bounce narrows the frustum further
}

TEST(Mirror, ThroughMirrorRefusesAnEyeBehindIt) {
  const Square m = tiltedMirror();
  EXPECT_THROW(throughMirror(Frustum{}, {0.2f, 1.0f, -5.0f}, m.corners, m.plane), std::invalid_argument);
  EXPECT_THROW(throughMirror(Frustum{}, {0.5f, 1.0f, 4.0f}, {m.corners[0], m.corners[1]}, m.plane),
               std::invalid_argument);
}

TEST(Mirror, WorstCaseRenderingsAsInThePaper) {
  EXPECT_EQ(worstCaseRenderings(3, 2), 10u);   // Kilgard's figures for n = 3, r = 2
  EXPECT_EQ(worstCaseRenderings(5, 4), 426u);  // and n = 5, r = 4
  for (int r = 0; r <= 8; ++r) EXPECT_EQ(worstCaseRenderings(2, r), 1u + 2u * static_cast<unsigned>(r));
  EXPECT_EQ(worstCaseRenderings(4, 0), 1u);
  EXPECT_THROW(worstCaseRenderings(0, 1), std::invalid_argument);
}

TEST(Mirror, WithFarPlaneMovesOnlyTheFarPlane) {
  const glm::mat4 moved = withFarPlane(kProjection, 80.0f);
  const glm::mat4 expected = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 80.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(moved[c][r], expected[c][r], 1e-5f * (1.0f + std::abs(expected[c][r])));
}
