// Lesson 11's measures (geometry/halo.h): the exact distance transform, the halo's width along an
// outline, covered and twice-blended pixels, and smoothed normals.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/halo.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

std::vector<std::uint8_t> disc(glm::ivec2 size, glm::vec2 centre, float radius, std::uint8_t value = 1) {
  std::vector<std::uint8_t> m(static_cast<std::size_t>(size.x * size.y), 0);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      if (glm::length(glm::vec2(x, y) - centre) <= radius)
        m[static_cast<std::size_t>(y * size.x + x)] = value;
  return m;
}

}  // namespace

TEST(Halo, DistanceTransformIsExact) {
  const glm::ivec2 size(23, 17);
  std::vector<std::uint8_t> seeds(static_cast<std::size_t>(size.x * size.y), 0);
  const glm::ivec2 points[] = {{3, 4}, {19, 2}, {11, 15}, {0, 16}};
  for (glm::ivec2 p : points) seeds[static_cast<std::size_t>(p.y * size.x + p.x)] = 1;
  const std::vector<float> d = distanceTransform(seeds, size);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      float best = std::numeric_limits<float>::infinity();
      for (glm::ivec2 p : points) best = std::min(best, glm::length(glm::vec2(x - p.x, y - p.y)));
      EXPECT_NEAR(d[static_cast<std::size_t>(y * size.x + x)], best, 1e-4f) << x << "," << y;
    }
}

TEST(Halo, DistanceTransformWithoutSeedsIsInfinite) {
  const std::vector<float> d = distanceTransform(std::vector<std::uint8_t>(12, 0), {4, 3});
  for (float v : d) EXPECT_TRUE(std::isinf(v));
  EXPECT_THROW(distanceTransform(std::vector<std::uint8_t>(11, 0), {4, 3}), std::invalid_argument);
}

// A disc with a ring k pixels wide around it measures k everywhere along its outline, within the
// half pixel a digital circle is off by.
TEST(Halo, AnEvenRingMeasuresItsWidth) {
  const glm::ivec2 size(80, 80);
  const std::vector<std::uint8_t> object = disc(size, {40, 40}, 15.0f);
  std::vector<std::uint8_t> blends = disc(size, {40, 40}, 21.0f);
  for (std::size_t i = 0; i < blends.size(); ++i)
    if (object[i]) blends[i] = 0;
  const HaloMeasure m = measureHalo(object, blends, {}, size);
  EXPECT_GT(m.outlinePixels, 80u);
  EXPECT_NEAR(m.widthMean, 6.0, 0.5);
  EXPECT_GE(m.widthMin, 5.0);
  EXPECT_LE(m.widthMax, 7.0);
  EXPECT_EQ(m.coveredPixels, 0u);
  EXPECT_EQ(m.multiPixels, 0u);
  EXPECT_EQ(m.blends, m.haloPixels);
}

// A ring shifted to one side: wide on one side, none on the other.
TEST(Halo, AShiftedRingIsUneven) {
  const glm::ivec2 size(80, 80);
  const std::vector<std::uint8_t> object = disc(size, {40, 40}, 15.0f);
  std::vector<std::uint8_t> blends = disc(size, {46, 40}, 17.0f);
  for (std::size_t i = 0; i < blends.size(); ++i)
    if (object[i]) blends[i] = 0;
  const HaloMeasure m = measureHalo(object, blends, {}, size);
  EXPECT_EQ(m.widthMin, 0.0);
  EXPECT_GE(m.widthMax, 7.0);
}

TEST(Halo, CoveredAndTwiceBlendedPixelsAreCounted) {
  const glm::ivec2 size(10, 10);
  std::vector<std::uint8_t> object(100, 0), blends(100, 0);
  for (int i = 30; i < 40; ++i) object[static_cast<std::size_t>(i)] = 1;
  blends[33] = 1;  // over the object
  blends[34] = 2;  // over the object, twice
  blends[50] = 2;  // twice
  blends[60] = 1;
  const HaloMeasure m = measureHalo(object, blends, {}, size);
  EXPECT_EQ(m.objectPixels, 10u);
  EXPECT_EQ(m.coveredPixels, 2u);
  EXPECT_EQ(m.multiPixels, 2u);
  EXPECT_EQ(m.haloPixels, 2u);
  EXPECT_EQ(m.blends, 6u);
}

// Beside a blocked pixel (another object in front) the outline is not sampled, and blocked pixels
// are not the outside: a ring cut by an occluder still measures its width elsewhere.
TEST(Halo, BlockedPixelsAreNeitherOutsideNorSampled) {
  const glm::ivec2 size(80, 80);
  const std::vector<std::uint8_t> object = disc(size, {40, 40}, 15.0f);
  std::vector<std::uint8_t> blends = disc(size, {40, 40}, 21.0f), blocked(object.size(), 0);
  for (std::size_t i = 0; i < blends.size(); ++i) {
    if (object[i]) blends[i] = 0;
    if (i % 80 >= 50) {  // a wall over the right side: neither halo nor object shows there
      blocked[i] = 1;
      blends[i] = 0;
    }
  }
  const HaloMeasure cut = measureHalo(object, blends, {}, size);
  EXPECT_LT(cut.widthMin, 1.0);  // without the wall's mask the cut looks like a thin ring
  const HaloMeasure m = measureHalo(object, blends, blocked, size);
  EXPECT_GE(m.widthMin, 5.0);
  EXPECT_LT(m.outlinePixels, cut.outlinePixels);
}

// A notch open at one end (a U): rays from its floor run out through the filled notch, past the
// arms' own halo; they are filled, not a width of 20 pixels.
TEST(Halo, AnOpenNotchIsNotAWidth) {
  const glm::ivec2 size(80, 80);
  std::vector<std::uint8_t> object(static_cast<std::size_t>(size.x * size.y), 0), blends = object;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const bool u = x >= 20 && x < 60 && y >= 20 && y < 60 && !(x >= 35 && x < 45 && y >= 35);
      const bool grown = x >= 15 && x < 65 && y >= 15 && y < 65;
      object[static_cast<std::size_t>(y * size.x + x)] = u;
      blends[static_cast<std::size_t>(y * size.x + x)] = grown && !u;
    }
  const HaloMeasure m = measureHalo(object, blends, {}, size);
  EXPECT_GT(m.filledPixels, 5u);
  EXPECT_LE(m.widthMax, 7.5);  // the corners' diagonal rays run a little further than 5
  EXPECT_GE(m.widthMin, 4.5);
}

// Two discs 6 pixels apart inside one ring: the outline facing the gap the halo fills is not a width.
TEST(Halo, AFilledGapIsNotAWidth) {
  const glm::ivec2 size(100, 60);
  std::vector<std::uint8_t> object = disc(size, {30, 30}, 12.0f), right = disc(size, {61, 30}, 12.0f);
  std::vector<std::uint8_t> blends = disc(size, {30, 30}, 17.0f), rightRing = disc(size, {61, 30}, 17.0f);
  for (std::size_t i = 0; i < object.size(); ++i) {
    object[i] = object[i] || right[i];
    blends[i] = (blends[i] || rightRing[i]) && !object[i];
  }
  const HaloMeasure m = measureHalo(object, blends, {}, size);
  EXPECT_GT(m.filledPixels, 5u);
  EXPECT_NEAR(m.widthMean, 5.0, 0.6);
  EXPECT_LE(m.widthMax, 6.5);
}

TEST(Halo, SmoothNormalsCloseTheCylindersRims) {
  const Mesh cylinder = makeCylinder(1.0f, 2.0f, 16);
  const Mesh smooth = smoothNormals(cylinder);
  ASSERT_EQ(smooth.normals.size(), cylinder.normals.size());
  for (std::size_t i = 0; i < smooth.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(smooth.normals[i]), 1.0f, 1e-5f);
    for (std::size_t j = 0; j < smooth.positions.size(); ++j)
      if (smooth.positions[i] == smooth.positions[j]) {
        EXPECT_EQ(smooth.normals[i], smooth.normals[j]);
      }
  }
  // A rim vertex's normal lies halfway between the side's and the cap's.
  std::size_t rim = 0;
  for (std::size_t i = 0; i < smooth.positions.size(); ++i) {
    const glm::vec3 p = smooth.positions[i];
    if (std::abs(p.y - 1.0f) < 1e-6f && std::abs(glm::length(glm::vec2(p.x, p.z)) - 1.0f) < 1e-5f) {
      EXPECT_NEAR(smooth.normals[i].y, std::sqrt(0.5f), 1e-4f);
      ++rim;
    }
  }
  EXPECT_EQ(rim, 32u);  // 16 on the side, 16 on the cap
  Mesh bare = cylinder;
  bare.normals.clear();
  EXPECT_THROW(smoothNormals(bare), std::invalid_argument);
}
