// Lesson 10's claims, measured on its output: N lights at 1/N add up to one light (in float, not in
// 8 bits); the bit set on update keeps every pixel to one addition per light; Kilgard's bits
// give the counting default's picture for one convex caster, past eight lights only with the
// re-clear, and not where two casters' volumes overlap; progressive rounds converge on the exact
// visible fraction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;

namespace {

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return stencil::testing::runLesson(LESSON_10, name, args, stats);
}

// The largest difference in a colour channel, and how many pixels differ by more than `level`.
struct Difference {
  int largest = 0;
  std::size_t pixelsOver = 0;
};
Difference difference(const Image& a, const Image& b, int level = 1) {
  Difference d;
  for (std::size_t i = 0; i < a.pixels.size() / 4; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])));
    d.largest = std::max(d.largest, worst);
    d.pixelsOver += worst > level;
  }
  return d;
}

// The samples that passed in the first pass with this name, from the --stats JSON.
long long passSamples(const stencil::testing::LessonStats& stats, const std::string& pass) {
  return stats.firstPass(pass, "samples_passed");
}

// RMS error of the red channel (the visible fraction in 1/255) against a reference, over the
// pixels the reference puts strictly inside the penumbra.
double penumbraRms(const Image& got, const Image& reference) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < reference.pixels.size() / 4; ++i) {
    const int r = reference.pixels[4 * i];
    if (r == 0 || r == 255 || reference.pixels[4 * i + 1] != r || reference.pixels[4 * i + 2] != r)
      continue;  // not the grey ground's penumbra (the background's clear colour is not grey)
    const double d = double(got.pixels[4 * i]) - r;
    sum += d * d;
    ++n;
  }
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

}  // namespace

// With the light shrunk to a point (size 0) every one of the N lights casts the same shadow, so
// N at 1/N must add up to the single light: within one level in RGBA32F. In RGBA8 each term is
// rounded to a whole level first, and N rounding errors add up; in RGBA16F too, less.
TEST(SoftShadows, NLightsAtOneNthSumToOneLight) {
  const auto one = run("one", "--set size=0 --set lights=1");
  if (!one) GTEST_SKIP() << "no GL context";
  for (int n : {8, 64, 256}) {
    const auto many = run("n" + std::to_string(n), "--set size=0 --set lights=" + std::to_string(n));
    EXPECT_LE(difference(one->colour, many->colour).largest, 1) << n << " lights in float";
  }
  // RGBA16F keeps 11 bits of mantissa: near 1 each addition rounds by up to 2^-12.
  const auto half = run("n256half", "--set size=0 --set float=2 --set lights=256");
  EXPECT_GT(difference(one->colour, half->colour).largest, 1) << "256 lights in RGBA16F";
  for (int n : {8, 64}) {
    const auto eightBit =
        run("n8bit" + std::to_string(n), "--set size=0 --set float=0 --set lights=" + std::to_string(n));
    const Difference d = difference(one->colour, eightBit->colour);
    EXPECT_GT(d.largest, 1) << n << " lights in RGBA8";
    EXPECT_GT(d.pixelsOver, 1000u) << n << " lights in RGBA8";
  }
}

// The mat lies on the ground at the ground's own depths: depth EQUAL passes both. With the tested
// bit set on update the first light's pass adds exactly as many fragments as without the mat; without
// it the mat's lit pixels are added twice.
TEST(SoftShadows, NoPixelBlendedTwice) {
  for (const char* variant : {"kilgard-8", "counting"}) {
    const auto withMat = run("mat", std::string("--variant ") + variant, true);
    if (!withMat) GTEST_SKIP() << "no GL context";
    const auto without = run("nomat", std::string("--variant ") + variant + " --set mat=0", true);
    const auto twice = run("twice", std::string("--variant ") + variant + " --set update-bit=0", true);
    const long long a = passSamples(withMat->stats, "illumination"),
                    b = passSamples(without->stats, "illumination"),
                    c = passSamples(twice->stats, "illumination");
    ASSERT_GT(b, 0) << variant;
    EXPECT_EQ(a, b) << variant;
    EXPECT_GT(c, b + 1000) << variant << ": the mat's pixels added twice";
  }
}

// One convex caster: parity and count agree, z-pass and z-fail agree (the eye is outside every
// volume), so Kilgard's sixteen lights in two groups of eight give the counting default's picture
// of the same sixteen lights. Without the re-clear the second group tests bits the first set.
TEST(SoftShadows, MoreThanEightLightsNeedTheReclear) {
  const auto counting = run("counting", "--set lights=16 --set pattern=0", true);
  if (!counting) GTEST_SKIP() << "no GL context";
  const auto kilgard = run("kilgard", "--variant kilgard-16", true);
  const auto noReclear = run("noreclear", "--variant kilgard-16-no-reclear", true);
  const std::size_t pixels = counting->colour.pixels.size() / 4;
  EXPECT_LE(difference(counting->colour, kilgard->colour).pixelsOver, pixels / 1000);
  EXPECT_GT(difference(counting->colour, noReclear->colour).pixelsOver, pixels / 10);
  EXPECT_EQ(kilgard->count("light_groups"), 2);
  EXPECT_EQ(kilgard->count("stencil_clears"), 2);
  EXPECT_EQ(noReclear->count("stencil_clears"), 1);
  EXPECT_EQ(counting->count("stencil_clears"), 16);
}

// Two casters whose volumes overlap: the counting default keeps the overlap dark, Kilgard's parity
// lights it. One caster: both the same picture.
TEST(SoftShadows, OverlappingVolumesParityWrongCountingRight) {
  const auto countingOne = run("counting1", "--set lights=8 --set pattern=0");
  if (!countingOne) GTEST_SKIP() << "no GL context";
  const auto kilgardOne = run("kilgard1", "--variant kilgard-8");
  const std::size_t pixels = countingOne->colour.pixels.size() / 4;
  EXPECT_LE(difference(countingOne->colour, kilgardOne->colour).pixelsOver, pixels / 1000);
  const auto counting = run("counting3", "--set lights=8 --set pattern=0 --set casters=3");
  const auto kilgard = run("kilgard3", "--variant kilgard-overlap");
  std::size_t lighter = 0;
  for (std::size_t i = 0; i < pixels; ++i)
    lighter += int(kilgard->colour.pixels[4 * i]) > int(counting->colour.pixels[4 * i]) + 8;
  EXPECT_GT(lighter, 500u) << "pixels the parity lights in the overlap";
}

// Each progressive round adds N fresh samples: after eight rounds of eight Halton lights the penumbra
// is nearer the exact visible fraction than after one, and as near as 64 lights at once.
TEST(SoftShadows, ProgressiveRoundsConverge) {
  const auto reference = run("reference", "--variant reference");
  if (!reference) GTEST_SKIP() << "no GL context";
  const auto once = run("once", "--set visibility=1 --set pattern=2 --set lights=8");
  const auto rounds =
      run("rounds", "--set visibility=1 --set pattern=2 --set lights=8 --set progressive=1 --frames 8", true);
  const auto at64 = run("at64", "--set visibility=1 --set pattern=2 --set lights=64");
  EXPECT_EQ(rounds->count("rounds"), 8);
  EXPECT_EQ(rounds->count("samples"), 64);
  const double e1 = penumbraRms(once->colour, reference->colour),
               e8 = penumbraRms(rounds->colour, reference->colour),
               e64 = penumbraRms(at64->colour, reference->colour);
  EXPECT_LT(e8, 0.5 * e1) << e1 << " -> " << e8;
  EXPECT_NEAR(e8, e64, 1.0);
}

// The penumbra's width measured on the picture (2% to 98% of the light along the ground, over
// 0.96) against W h / (H - h): within 5% across the slab's +x edge (W = 1.5) and its +z edge
// (the light's depth, 1.0), in the exact reference and in 64 Halton lights.
TEST(SoftShadows, PenumbraWidthIsWhOverHMinush) {
  for (const char* variant : {"reference", "visibility"}) {
    const auto r = run(variant, std::string("--variant ") + variant, true);
    if (!r) GTEST_SKIP() << "no GL context";
    for (const char* edge : {"x", "z"}) {
      const double measured = double(r->count(std::string("penumbra_width_") + edge + "_milli"));
      const double predicted = double(r->count(std::string("penumbra_width_") + edge + "_predicted_milli"));
      EXPECT_GT(predicted, 0.0) << variant << " " << edge;
      EXPECT_NEAR(measured, predicted, 0.05 * predicted) << variant << " " << edge;
    }
  }
  const auto r = run("reference", "--variant reference", true);
  EXPECT_EQ(r->count("penumbra_width_x_predicted_milli"), 643);  // 1.5 * 1.2 / 2.8
  EXPECT_EQ(r->count("penumbra_width_z_predicted_milli"), 429);  // 1.0 * 1.2 / 2.8
}

// Penumbra wedges change where the N-light loop runs, not the picture: for each pattern and
// N = 8, 64, 256, with both casters, within one level of the plain loop (outside the wedges the
// N terms are summed in the shader and added once, inside they are added one by one as in the
// plain loop: the float sums round differently by far less than a level, so only a pixel whose
// value lies that close to a rounding boundary moves, by one). The visible fraction (each term
// the same share, summed in the same order) is identical to the bit. Fewer fragments throughout.
TEST(SoftShadows, WedgesGiveThePlainLoopsPicture) {
  for (int pattern : {0, 1, 2})
    for (int n : {8, 64, 256}) {
      const std::string args =
          "--set casters=3 --set pattern=" + std::to_string(pattern) + " --set lights=" + std::to_string(n);
      const std::string name = "p" + std::to_string(pattern) + "n" + std::to_string(n);
      const auto plain = run("plain-" + name, args, true);
      if (!plain) GTEST_SKIP() << "no GL context";
      const auto wedges = run("wedges-" + name, args + " --set wedges=1", true);
      const Difference d = difference(plain->colour, wedges->colour, 0);
      EXPECT_LE(d.largest, 1) << name;
      EXPECT_LE(d.pixelsOver, 20u) << name;
      EXPECT_LT(passSamples(wedges->stats, "other-lights"), passSamples(plain->stats, "other-lights"))
          << name;
      EXPECT_GT(wedges->count("wedges"), 0) << name;
    }
  const auto plain = run("plain-visibility", "--set casters=3 --set lights=64 --set visibility=1");
  const auto wedges =
      run("wedges-visibility", "--set casters=3 --set lights=64 --set visibility=1 --set wedges=1");
  EXPECT_EQ(difference(plain->colour, wedges->colour, 0).largest, 0);
}

// The wedges bound the penumbra: every pixel where the plain loop's lights disagree (tinted by
// --set penumbra=1) is marked by the wedges (tinted by show-wedges). Wedges built from a light of
// half the size miss part of the penumbra, and the check sees it.
TEST(SoftShadows, WedgesContainEveryPixelWhereTheLightsDisagree) {
  auto changed = [](const Image& a, const Image& b) {
    std::vector<bool> c(a.pixels.size() / 4);
    for (std::size_t i = 0; i < c.size(); ++i)
      for (int k = 0; k < 3; ++k) c[i] = c[i] || a.pixels[4 * i + k] != b.pixels[4 * i + k];
    return c;
  };
  auto missed = [&](const std::string& name, const std::string& args, int wedgeSize) {
    const auto plain = run(name + "-plain", args);
    const auto disagree = run(name + "-penumbra", args + " --set penumbra=1");
    const std::string w = args + " --set wedges=1 --set wedge-size=" + std::to_string(wedgeSize);
    const auto wedges = run(name + "-wedges", w);
    const auto marked = run(name + "-marked", w + " --set show-wedges=1");
    const std::vector<bool> penumbra = changed(plain->colour, disagree->colour),
                            wedge = changed(wedges->colour, marked->colour);
    std::size_t outside = 0, inPenumbra = 0;
    for (std::size_t i = 0; i < penumbra.size(); ++i) {
      inPenumbra += penumbra[i];
      outside += penumbra[i] && !wedge[i];
    }
    EXPECT_GT(inPenumbra, 1000u) << name;
    return outside;
  };
  if (!run("probe", "--set lights=1")) GTEST_SKIP() << "no GL context";
  for (const std::string disk : {"0", "1"}) {
    const std::string args = "--set casters=3 --set lights=64 --set pattern=2 --set disk=" + disk;
    EXPECT_EQ(missed("disk" + disk, args, 100), 0u) << "disk=" << disk;
    EXPECT_GT(missed("disk" + disk + "-shrunk", args, 50), 100u)
        << "disk=" << disk << ", wedges from half the light";
  }
}

// The ray-cast reference (converged=10: 1024 stratified shadow rays per pixel) agrees with the
// analytic one past the slab: each pixel's estimate deviates by at most 1024^(-3/4) = 0.0055 of
// the light (geometry/soft_shadow_reference.h), 1.4 levels, plus the half level of 8-bit
// rounding: an RMS under 1.5 levels over the penumbra and no pixel 5 deviations (7 levels) plus a
// level off. With the ball it darkens ground the slab alone leaves lit.
TEST(SoftShadows, ConvergedReferenceAgreesWithTheAnalyticOne) {
  const auto exact = run("reference", "--variant reference");
  if (!exact) GTEST_SKIP() << "no GL context";
  const auto cast = run("converged", "--variant reference --set converged=10", true);
  EXPECT_EQ(cast->count("reference_rays_per_pixel"), 1024);
  EXPECT_LT(penumbraRms(cast->colour, exact->colour), 1.5);
  int worst = 0;
  for (std::size_t i = 0; i < exact->colour.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(cast->colour.pixels[i]) - int(exact->colour.pixels[i])));
  EXPECT_LE(worst, 8);
  const auto ball = run("ball", "--variant converged --set converged=6");
  std::size_t darker = 0;
  for (std::size_t i = 0; i < exact->colour.pixels.size() / 4; ++i)
    darker += exact->colour.pixels[4 * i] == 255 && ball->colour.pixels[4 * i] < 128;
  EXPECT_GT(darker, 500u);
}
