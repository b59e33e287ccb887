// Threshold patterns for the dissolve (lesson 12): the Bayer matrix from its recursion, blue noise
// by void-and-cluster (a permutation, deterministic, evener than white noise), equalizing to equal
// counts per level, every pattern's share below level k against k/256, and the clumpiness measure
// on patterns whose variance is known by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <numeric>

#include "geometry/dither.h"

using namespace stencil;

namespace {

bool isPermutation(std::vector<std::uint32_t> v) {
  std::sort(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] != i) return false;
  return true;
}

const PatternKind kKinds[] = {PatternKind::WhiteNoise, PatternKind::Bayer,      PatternKind::BlueNoise,
                              PatternKind::LinearWipe, PatternKind::RadialWipe, PatternKind::ClockWipe};

}  // namespace

TEST(Dither, BayerMatrixFollowsItsRecursion) {
  EXPECT_EQ(bayerMatrix(0), std::vector<std::uint32_t>{0});
  // M(2) = [[0, 2], [3, 1]]: the first row holds 0 and 2.
  EXPECT_EQ(bayerMatrix(1), (std::vector<std::uint32_t>{0, 2, 3, 1}));
  for (int log2 = 1; log2 <= 5; ++log2) {
    const auto m = bayerMatrix(log2);
    const int side = 1 << log2, half = side / 2;
    ASSERT_TRUE(isPermutation(m)) << side;
    const auto previous = bayerMatrix(log2 - 1);
    // Each quadrant is 4 * M(side / 2) plus the quadrant's offset 0, 2, 3, 1.
    const std::uint32_t offset[2][2] = {{0, 2}, {3, 1}};
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        EXPECT_EQ(m[static_cast<std::size_t>(y * side + x)],
                  4 * previous[static_cast<std::size_t>((y % half) * half + x % half)] +
                      offset[y / half][x / half]);
  }
  EXPECT_THROW(bayerMatrix(9), std::invalid_argument);
  EXPECT_THROW(bayerMatrix(-1), std::invalid_argument);
}

TEST(Dither, VoidAndClusterIsADeterministicPermutation) {
  const auto start = std::chrono::steady_clock::now();
  const auto a = voidAndCluster(64, 1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(isPermutation(a));
  EXPECT_EQ(a, voidAndCluster(64, 1));  // the same seed, the same tile
  EXPECT_NE(a, voidAndCluster(64, 2));  // another seed, another tile
  EXPECT_TRUE(isPermutation(voidAndCluster(2)));
  EXPECT_LT(seconds, 5.0);  // about 0.1 s in a release build; generous for sanitizer builds
  EXPECT_THROW(voidAndCluster(1), std::invalid_argument);
  EXPECT_THROW(voidAndCluster(16, 1, 0.0), std::invalid_argument);
}

TEST(Dither, VoidAndClusterFillsTheLargestVoidFirst) {
  // The first pixels placed are far apart: the smallest toroidal distance between any two of the
  // first 16 in a 64x64 tile beats what a 4x4 grid of spacing 16 would give, halved.
  const int side = 64;
  const auto rank = voidAndCluster(side, 3);
  std::vector<std::pair<int, int>> first;
  for (int i = 0; i < side * side; ++i)
    if (rank[static_cast<std::size_t>(i)] < 16) first.push_back({i % side, i / side});
  ASSERT_EQ(first.size(), 16u);
  int nearest = side * side;
  for (std::size_t i = 0; i < first.size(); ++i)
    for (std::size_t j = i + 1; j < first.size(); ++j) {
      int dx = std::abs(first[i].first - first[j].first), dy = std::abs(first[i].second - first[j].second);
      dx = std::min(dx, side - dx), dy = std::min(dy, side - dy);
      nearest = std::min(nearest, dx * dx + dy * dy);
    }
  EXPECT_GE(nearest, 8 * 8);
}

TEST(Dither, EqualizeGivesEveryLevelTheSameCount) {
  for (const std::size_t n : {256u * 300u, 317u * 239u, 7u, 1000u}) {
    std::vector<double> keys(n);
    std::vector<std::uint64_t> ties(n);
    for (std::size_t i = 0; i < n; ++i)
      keys[i] = static_cast<double>((i * 7919) % 101),
      ties[i] = pixelHash(static_cast<std::uint32_t>(i), 0, 5);
    const auto levels = equalize(keys, ties);
    for (int k = 0; k <= 256; ++k) {
      const std::uint64_t below = countBelow(levels, k);
      const std::uint64_t expected = (static_cast<std::uint64_t>(k) * n + 255) / 256;  // ceil(k n / 256)
      EXPECT_EQ(below, expected) << "n " << n << " k " << k;
    }
    // The order is the keys': a smaller key never gets a higher level.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < std::min<std::size_t>(n, 64); ++j)
        if (keys[i] < keys[j]) {
          EXPECT_LE(levels[i], levels[j]);
        }
  }
  EXPECT_THROW(equalize({1.0}, {}), std::invalid_argument);
}

TEST(Dither, EveryPatternShowsKOver256AtEveryState) {
  for (const auto& [w, h] : {std::pair{320, 240}, std::pair{317, 239}, std::pair{64, 64}}) {
    const std::uint64_t n = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    for (const PatternKind kind : kKinds) {
      const auto p = makePattern(kind, w, h);
      ASSERT_EQ(p.size(), n);
      for (int k = 0; k <= 256; ++k) {
        // 256 * below - k n lies in [0, 256): below is ceil(k n / 256), within one pixel of k n / 256.
        const std::int64_t error =
            256 * static_cast<std::int64_t>(countBelow(p, k)) - k * static_cast<std::int64_t>(n);
        EXPECT_GE(error, 0) << patternName(kind) << " " << w << "x" << h << " k " << k;
        EXPECT_LT(error, 256) << patternName(kind) << " " << w << "x" << h << " k " << k;
      }
    }
  }
}

TEST(Dither, TiledPatternsKeepTheirTileWhereItFitsWholeTimes) {
  // 320x256: 20x16 Bayer tiles and 5x4 blue-noise tiles, every tile whole.
  const auto bayer = makePattern(PatternKind::Bayer, 320, 256),
             blue = makePattern(PatternKind::BlueNoise, 320, 256);
  const auto m = bayerMatrix(4), tile = voidAndCluster(64, 1);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 320; ++x) {
      const auto i = static_cast<std::size_t>(y * 320 + x);
      ASSERT_EQ(bayer[i], m[static_cast<std::size_t>((y % 16) * 16 + x % 16)]);
      ASSERT_EQ(blue[i],
                tile[static_cast<std::size_t>((y % 64) * 64 + x % 64)] / 16);  // 4096 ranks, 16 a level
    }
}

TEST(Dither, CoverageVarianceByHand) {
  const int w = 64, h = 64;
  // A checkerboard of 0 and 255: below 128 on half of every 8x8 window exactly, variance 0.
  std::vector<std::uint8_t> checker(w * h);
  for (int i = 0; i < w * h; ++i) checker[static_cast<std::size_t>(i)] = ((i % w + i / w) % 2) ? 255 : 0;
  EXPECT_NEAR(coverageVariance(checker, w, h, 128), 0.0, 1e-12);
  // A half-plane: windows left of x = 32 - 8 cover 1, right of 32 cover 0, the 7 straddling
  // positions j/8 (j = 1..7). Mean and variance over the 57 window columns by hand.
  std::vector<std::uint8_t> half(w * h);
  for (int i = 0; i < w * h; ++i) half[static_cast<std::size_t>(i)] = (i % w) < 32 ? 0 : 255;
  double sum = 0, squares = 0;
  for (int x = 0; x + 8 <= w; ++x) {
    const double c = std::clamp(32 - x, 0, 8) / 8.0;
    sum += c, squares += c * c;
  }
  const double mean = sum / 57, variance = squares / 57 - mean * mean;
  EXPECT_NEAR(coverageVariance(half, w, h, 128), variance, 1e-12);
  EXPECT_THROW(coverageVariance(half, w, h, 128, 65), std::invalid_argument);
  EXPECT_THROW(coverageVariance(half, w, h - 1, 128), std::invalid_argument);
}

TEST(Dither, BlueNoiseIsEvenerThanWhiteNoise) {
  // At every state the blue-noise pattern's 8x8 windows vary less than white noise's, and white
  // noise's are close to the binomial c (1 - c) / 64; the wipes vary most.
  const int w = 320, h = 240;
  const auto white = makePattern(PatternKind::WhiteNoise, w, h),
             blue = makePattern(PatternKind::BlueNoise, w, h), bayer = makePattern(PatternKind::Bayer, w, h),
             wipe = makePattern(PatternKind::LinearWipe, w, h);
  for (int k = 16; k <= 240; k += 16) {
    const double c = k / 256.0;
    const double vWhite = coverageVariance(white, w, h, k), vBlue = coverageVariance(blue, w, h, k);
    EXPECT_LT(vBlue, 0.5 * vWhite) << "k " << k;
    EXPECT_NEAR(vWhite, c * (1 - c) / 64, 0.25 * c * (1 - c) / 64) << "k " << k;
    EXPECT_LT(coverageVariance(bayer, w, h, k), vWhite) << "k " << k;
    EXPECT_GT(coverageVariance(wipe, w, h, k), 10 * vWhite) << "k " << k;
  }
}
