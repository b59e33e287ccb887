// Reversed depth (geometry/projection.h): window depth z/w under a zero-to-one clip range, 1 at
// the near plane, 0 at the far plane or at infinity, falling monotonically in between.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "geometry/projection.h"

using namespace stencil;

namespace {

// Window depth of the eye-space point (x, y, -d, w) under a zero-to-one clip range.
double depthOf(const glm::mat4& p, float d, float w = 1.0f) {
  const glm::vec4 clip = p * glm::vec4(0.3f * d, -0.2f * d, -d, w);
  return static_cast<double>(clip.z) / static_cast<double>(clip.w);
}

// Inside the zero-to-one clip volume: 0 <= z <= w (and |x|, |y| <= w).
bool inClipVolume(const glm::vec4& c) {
  return c.z >= 0.0f && c.z <= c.w && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
}

}  // namespace

TEST(ReversedDepth, InfinitePerspectiveIsNearOverDistance) {
  const float n = 1e-4f;
  const glm::mat4 pinf = glm::infinitePerspective(glm::radians(55.0f), 4.0f / 3.0f, n);
  const glm::mat4 r = reversedDepth(pinf);
  // The depth row (glm: column-major, m[column][2]) is exactly (0 0 0 n); x, y, w untouched.
  EXPECT_EQ(glm::vec4(r[0][2], r[1][2], r[2][2], r[3][2]), glm::vec4(0, 0, 0, n));
  for (int c = 0; c < 4; ++c)
    for (int row : {0, 1, 3}) EXPECT_EQ(r[c][row], pinf[c][row]);
  EXPECT_DOUBLE_EQ(depthOf(r, n), 1.0);  // the near plane
  for (float d : {1e-3f, 0.1f, 5.0f, 1e3f, 1e6f})
    EXPECT_NEAR(depthOf(r, d), static_cast<double>(n) / d, 1e-7 * static_cast<double>(n) / d) << d;
}

TEST(ReversedDepth, PointsAtInfinityLandAtZeroInsideTheClipVolume) {
  const glm::mat4 r = reversedDepth(glm::infinitePerspective(glm::radians(45.0f), 1.5f, 0.1f));
  // Directions in front of the eye (w = 0), as the shadow volumes are extruded.
  for (const glm::vec3& dir : std::vector<glm::vec3>{{0, 0, -1}, {0.2f, -0.3f, -1}, {-0.1f, 0.25f, -2}}) {
    const glm::vec4 clip = r * glm::vec4(dir, 0.0f);
    EXPECT_EQ(clip.z, 0.0f);
    EXPECT_GT(clip.w, 0.0f);
    EXPECT_TRUE(inClipVolume(clip)) << dir.x << " " << dir.y << " " << dir.z;
  }
}

TEST(ReversedDepth, FallsMonotonicallyWithDistance) {
  const float n = 1e-4f;
  const glm::mat4 r = reversedDepth(glm::infinitePerspective(glm::radians(55.0f), 1.0f, n));
  double previous = depthOf(r, n);
  for (float d = 2e-4f; d < 1e7f; d *= 1.37f) {
    const double depth = depthOf(r, d);
    EXPECT_LT(depth, previous) << d;
    EXPECT_GT(depth, 0.0);
    previous = depth;
  }
}

// Any projection: near -> 1, far -> 0, and exactly what GL's convention clips is clipped.
TEST(ReversedDepth, FinitePerspectiveAndParallelMapNearToOneFarToZero) {
  const float n = 0.5f, f = 40.0f;
  for (const glm::mat4& p :
       {glm::perspective(glm::radians(60.0f), 1.3f, n, f), glm::ortho(-3.0f, 3.0f, -2.0f, 2.0f, n, f)}) {
    const glm::mat4 r = reversedDepth(p);
    EXPECT_NEAR(depthOf(r, n), 1.0, 1e-6);
    EXPECT_NEAR(depthOf(r, f), 0.0, 1e-6);
    for (float d : {0.3f, 1.0f, 20.0f, 39.0f, 41.0f, 100.0f}) {
      const glm::vec4 eye(0.1f, -0.1f, -d, 1.0f);
      const glm::vec4 standard = p * eye, reversed = r * eye;
      const bool inStandard = standard.z >= -standard.w && standard.z <= standard.w;
      EXPECT_EQ(reversed.z >= 0.0f && reversed.z <= reversed.w, inStandard) << d;
      // Window depth reversed: 1 - (0.5 + 0.5 z/w).
      EXPECT_NEAR(reversed.z / reversed.w, 0.5f - 0.5f * standard.z / standard.w, 1e-6f) << d;
    }
  }
}

// Near the world's origin the drawing origin is 0 and the matrix is the frame's own, bit for bit,
// so scenes there draw and ray cast exactly as from the world's origin.
TEST(DrawingOrigin, IsZeroNearTheWorldsOriginAndLeavesTheMatrixAsItIs) {
  const glm::mat4 vp = glm::infinitePerspective(glm::radians(55.0f), 4.0f / 3.0f, 0.1f) *
                       glm::lookAt(glm::vec3(3, 2, 4), glm::vec3(0, 0.5f, 0), glm::vec3(0, 1, 0));
  EXPECT_EQ(drawingOrigin(glm::vec3(3, 2, 4)), glm::vec3(0.0f));
  EXPECT_EQ(drawingOrigin(glm::vec3(-511, 300, 511)), glm::vec3(0.0f));
  EXPECT_EQ(viewProjectionFrom(vp, glm::vec3(0.0f)), vp);
  EXPECT_EQ(drawingOrigin(glm::vec3(100003, 3, 100004)), glm::vec3(100352, 0, 100352));
}

// caster-far-from-origin's box edge, 1e5 units out and 4.4 units from the eye, at 1024x768: from
// the drawing origin, float arithmetic puts it where the frame's matrix, taken exactly, does.
TEST(DrawingOrigin, KeepsAPointFarFromTheWorldsOriginOnItsPixel) {
  const glm::vec3 eye(100003, 3, 100004), target(100000, 0.5f, 100000), corner(100000.5f, 1, 100000.5f);
  const glm::mat4 vp = glm::infinitePerspective(glm::radians(55.0f), 1024.0f / 768.0f, 0.1f) *
                       glm::lookAt(eye, target, glm::vec3(0, 1, 0));
  const glm::dvec4 exact = glm::dmat4(vp) * glm::dvec4(glm::dvec3(corner), 1.0);
  const glm::vec3 origin = drawingOrigin(eye);
  const glm::vec4 drawn = viewProjectionFrom(vp, origin) * glm::vec4(corner - origin, 1.0f);
  const double pixel = 2.0 / 1024.0;  // one pixel in normalised device x
  EXPECT_NEAR(drawn.x / drawn.w, exact.x / exact.w, 0.01 * pixel);
  EXPECT_NEAR(drawn.y / drawn.w, exact.y / exact.w, 0.01 * pixel);
}
