// Lesson 10's sampling patterns and exact soft-shadow reference (geometry/soft_shadow.h): the
// closed forms against hand-derived values and against a brute-force count of light points whose
// segment to the receiver a box blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/soft_shadow.h"

using namespace stencil;

namespace {

// The corners of an axis-aligned box.
std::vector<glm::vec3> boxCorners(glm::vec3 lo, glm::vec3 hi) {
  std::vector<glm::vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  return c;
}

// Whether the segment p -> q meets the box (slab test): independent of the projection.
bool segmentHitsBox(glm::dvec3 p, glm::dvec3 q, glm::dvec3 lo, glm::dvec3 hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double d = q[a] - p[a];
    if (d == 0.0) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - p[a]) / d, tb = (hi[a] - p[a]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// The visible fraction by brute force: k x k light points at cell centres (inside the disk only,
// for a disk light).
double bruteForce(const AreaLight& light, glm::vec3 lo, glm::vec3 hi, glm::vec3 receiver, int k) {
  int seen = 0, total = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const glm::dvec2 u((i + 0.5) / k, (j + 0.5) / k);
      glm::dvec3 q(
          light.centre.x + (u.x - 0.5) * light.size.x, light.centre.y,
          light.centre.z + (u.y - 0.5) * (light.shape == LightShape::Disk ? light.size.x : light.size.y));
      if (light.shape == LightShape::Disk &&
          glm::length(glm::dvec2(q.x - light.centre.x, q.z - light.centre.z)) > 0.5 * light.size.x)
        continue;
      ++total;
      seen += !segmentHitsBox(glm::dvec3(receiver), q, glm::dvec3(lo), glm::dvec3(hi));
    }
  return static_cast<double>(seen) / total;
}

}  // namespace

TEST(SoftShadow, RadicalInverse) {
  EXPECT_DOUBLE_EQ(radicalInverse(2, 1), 0.5);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 3), 0.75);
  EXPECT_DOUBLE_EQ(radicalInverse(2, 6), 0.375);  // 110 -> 0.011
  EXPECT_NEAR(radicalInverse(3, 1), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(radicalInverse(3, 5), 2.0 / 3.0 + 1.0 / 9.0, 1e-15);  // 12 -> 0.21
  EXPECT_THROW(radicalInverse(1, 3), std::invalid_argument);
}

TEST(SoftShadow, GridIsTheMostSquareFactoring) {
  EXPECT_EQ(sampleGrid(8), glm::ivec2(2, 4));
  EXPECT_EQ(sampleGrid(16), glm::ivec2(4, 4));
  EXPECT_EQ(sampleGrid(32), glm::ivec2(4, 8));
  EXPECT_EQ(sampleGrid(7), glm::ivec2(1, 7));
  EXPECT_EQ(sampleGrid(1), glm::ivec2(1, 1));
  EXPECT_THROW(sampleGrid(0), std::invalid_argument);
}

TEST(SoftShadow, GridAndJitteredSamplesOnePerCell) {
  for (SamplePattern p : {SamplePattern::Grid, SamplePattern::Jittered})
    for (int n : {1, 2, 8, 12, 64})
      for (int round : {0, 3}) {
        const std::vector<glm::vec2> s = unitSquareSamples(p, n, round);
        ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
        const glm::ivec2 g = sampleGrid(n);
        std::vector<int> hits(static_cast<std::size_t>(n), 0);
        for (glm::vec2 v : s) {
          ASSERT_GE(v.x, 0.0f);
          ASSERT_LT(v.x, 1.0f);
          ASSERT_GE(v.y, 0.0f);
          ASSERT_LT(v.y, 1.0f);
          ++hits[static_cast<std::size_t>(int(v.y * static_cast<float>(g.x)) * g.y +
                                          int(v.x * static_cast<float>(g.y)))];
        }
        for (int h : hits) EXPECT_EQ(h, 1);
      }
  // Jittered rounds differ; grid rounds repeat.
  EXPECT_NE(unitSquareSamples(SamplePattern::Jittered, 8, 0)[0],
            unitSquareSamples(SamplePattern::Jittered, 8, 1)[0]);
  EXPECT_EQ(unitSquareSamples(SamplePattern::Grid, 8, 0), unitSquareSamples(SamplePattern::Grid, 8, 1));
  EXPECT_THROW(unitSquareSamples(SamplePattern::Grid, 0), std::invalid_argument);
}

TEST(SoftShadow, HaltonRoundsContinueTheSequence) {
  const std::vector<glm::vec2> all = unitSquareSamples(SamplePattern::Halton, 8);
  const std::vector<glm::vec2> first = unitSquareSamples(SamplePattern::Halton, 4, 0);
  const std::vector<glm::vec2> second = unitSquareSamples(SamplePattern::Halton, 4, 1);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(all[static_cast<std::size_t>(i)], first[static_cast<std::size_t>(i)]);
    EXPECT_EQ(all[static_cast<std::size_t>(i + 4)], second[static_cast<std::size_t>(i)]);
  }
  EXPECT_EQ(all[0], glm::vec2(0.5f, 1.0f / 3.0f));
}

TEST(SoftShadow, ConcentricMapKeepsStrataEqualInArea) {
  // The unit square's corners go to the circle, its centre to the centre; a uniform grid's mean
  // squared radius is 1/2, as for a uniform disk.
  EXPECT_NEAR(glm::length(concentricDisk({1.0f, 0.5f})), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(concentricDisk({1.0f, 1.0f})), 1.0f, 1e-6f);
  EXPECT_EQ(concentricDisk({0.5f, 0.5f}), glm::vec2(0.0f));
  double sum = 0.0;
  const float k = 200.0f;
  const int cells = 200;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const glm::vec2 d =
          concentricDisk({(static_cast<float>(i) + 0.5f) / k, (static_cast<float>(j) + 0.5f) / k});
      ASSERT_LE(glm::length(d), 1.0f + 1e-6f);
      sum += glm::dot(d, d);
    }
  EXPECT_NEAR(sum / (cells * cells), 0.5, 1e-3);
}

TEST(SoftShadow, StraightEdgePenumbraWidth) {
  // A light 1.5 wide at height 4, an edge at height 1.2: 1.5 * 1.2 / 2.8.
  EXPECT_DOUBLE_EQ(straightEdgePenumbraWidth(1.5, 4.0, 1.2), 1.5 * 1.2 / 2.8);
  EXPECT_DOUBLE_EQ(straightEdgePenumbraWidth(0.0, 4.0, 1.2), 0.0);  // a point light: a hard edge
  EXPECT_THROW(straightEdgePenumbraWidth(1.0, 2.0, 2.0), std::invalid_argument);
  EXPECT_THROW(straightEdgePenumbraWidth(1.0, 2.0, 0.0), std::invalid_argument);
  EXPECT_DOUBLE_EQ(straightEdgeVisibleFraction(0.0, 1.5, 4.0, 1.2), 0.0);
  EXPECT_DOUBLE_EQ(straightEdgeVisibleFraction(1.5 * 1.2 / 2.8 / 2.0, 1.5, 4.0, 1.2), 0.5);
  EXPECT_DOUBLE_EQ(straightEdgeVisibleFraction(5.0, 1.5, 4.0, 1.2), 1.0);
}

// A thin occluder much wider than the light along z acts as a straight edge along x: the visible
// fraction across its edge is the linear ramp of width W h / (H - h).
TEST(SoftShadow, VisibleFractionIsTheStraightEdgeRamp) {
  const AreaLight light{{0.0f, 4.0f, 0.0f}, {1.5f, 1.0f}, LightShape::Rectangle};
  const float h = 1.2f;
  const std::vector<glm::vec3> slab = boxCorners({-20.0f, h - 1e-4f, -20.0f}, {0.0f, h, 20.0f});
  // The edge x = 0 seen from the ground: fully lit from x = e where the light's left side
  // (x = -0.75) just clears it, umbra up to x = e - W h / (H - h).
  const double width = straightEdgePenumbraWidth(1.5, 4.0, h);
  const double litStart = 0.75 * h / (4.0 - h);  // the line from (-0.75, 4) through (0, h)
  for (double s : {-0.1, 0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0, 1.1}) {
    const glm::vec3 receiver(static_cast<float>(litStart - width + s * width), 0.0f, 0.0f);
    EXPECT_NEAR(visibleFraction(light, slab, receiver), straightEdgeVisibleFraction(s * width, 1.5, 4.0, h),
                2e-4)
        << s;
  }
}

// A square occluder straight below the light's centre, seen from the point straight below it:
// its projection is a square of side S H / h (the ray from the ground through height h reaches
// H at H / h times the offset), covering min(S H / h, W)^2 of the W x W light.
TEST(SoftShadow, SquareOccluderCoveredArea) {
  const AreaLight light{{0.0f, 4.0f, 0.0f}, {1.5f, 1.5f}, LightShape::Rectangle};
  for (float S : {0.1f, 0.2f, 0.3f, 0.5f}) {
    const std::vector<glm::vec3> square = boxCorners({-S / 2, 1.999f, -S / 2}, {S / 2, 2.0f, S / 2});
    // The bottom face, nearer the receiver, projects widest: by H / 1.999.
    const double side = std::min(S * 4.0 / 1.999, 1.5);
    EXPECT_NEAR(visibleFraction(light, square, glm::vec3(0.0f)), 1.0 - side * side / (1.5 * 1.5), 1e-5) << S;
  }
}

TEST(SoftShadow, VisibleFractionMatchesBruteForce) {
  const glm::vec3 lo(-0.6f, 1.18f, -0.6f), hi(0.6f, 1.22f, 0.6f);
  const std::vector<glm::vec3> corners = boxCorners(lo, hi);
  for (LightShape shape : {LightShape::Rectangle, LightShape::Disk}) {
    const AreaLight light{{0.2f, 4.0f, -0.1f}, {1.5f, 1.2f}, shape};
    for (glm::vec3 r : {glm::vec3(0.0f), glm::vec3(0.9f, 0.0f, 0.3f), glm::vec3(1.05f, 0.0f, 1.0f),
                        glm::vec3(-0.8f, 0.0f, 0.85f), glm::vec3(2.0f, 0.0f, 0.0f)})
      EXPECT_NEAR(visibleFraction(light, corners, r), bruteForce(light, lo, hi, r, 600), 4e-3)
          << (shape == LightShape::Disk ? "disk " : "rectangle ") << r.x << "," << r.z;
  }
  EXPECT_THROW(visibleFraction(AreaLight{}, corners, glm::vec3(0.0f)), std::invalid_argument);  // light below
}

TEST(SoftShadow, ClipAndHull) {
  const std::vector<glm::dvec2> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(polygonArea(square), 4.0);
  const std::vector<glm::dvec2> shifted{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  EXPECT_NEAR(polygonArea(clipConvex(shifted, square)), 1.0, 1e-12);
  EXPECT_TRUE(clipConvex({{5, 5}, {6, 5}, {6, 6}}, square).empty());
  const std::vector<glm::dvec2> hull = convexHull({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {0, 2}, {1, 0}});
  EXPECT_EQ(hull.size(), 4u);
  EXPECT_DOUBLE_EQ(polygonArea(hull), 4.0);
}
