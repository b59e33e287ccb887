// Lesson 11's claims, measured on its output. The blend-count picture (--set show=1) is the same
// passes with the same stencil and depth state, every surface a flat id colour and each halo blend
// adding 127 to red (the figure's halo) or green (the ball's): so its stencil equals the shaded
// frame's, and its red sum equals the fragments the halo pass let through (samples_passed). On it:
// no halo pixel over the object with the stencil, every halo pixel blended once with INVERT (and
// some twice without), the ring's width along the outline per method, the rail and the floor, two
// halos with a bit each. On the shaded frame: the halo changes exactly its pixels, and each effect
// keeps to its own bits.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;

namespace {

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return stencil::testing::runLesson(LESSON_11, name, args, stats);
}

// The first pass with this name in the --stats JSON: a number of its.
long long passField(const stencil::testing::LessonStats& stats, const std::string& pass,
                    const std::string& field) {
  return stats.firstPass(pass, field);
}

// The count picture decoded: blends per pixel of each halo, and which object shows.
constexpr std::uint8_t kFigure = 255, kBall = 170, kRail = 85;
// 127 a blend: 127 once, 254 twice, 255 (saturated) three times or more.
int blends(const LessonRun& r, std::size_t i, int halo) {
  const int v = r.colour.pixels[4 * i + halo];
  return v == 255 ? 3 : (v + 63) / 127;
}
std::uint8_t id(const LessonRun& r, std::size_t i) {
  return r.colour.pixels[4 * i + 2];
}
std::size_t pixels(const LessonRun& r) {
  return r.stencil.pixels.size();
}

double ratio(const LessonRun& r, const std::string& what) {
  return static_cast<double>(r.count("figure.width_" + what + "_x100")) /
         static_cast<double>(r.count("figure.width_mean_x100"));
}

const char* const kMethods[] = {"whole", "pieces", "extrude", "screen"};

}  // namespace

// The count picture is the shaded frame's passes: the same stencil, bit for bit; and what it counts
// is what the halo pass let through: the red sum is the pass's samples_passed, and the lesson's own
// counts are the picture's.
TEST(Halo, TheCountPictureIsTheSamePasses) {
  for (const char* variant : {"recipe", "no-invert", "two-halos", "screen", "no-stencil"}) {
    const auto shaded = run(std::string(variant) + "-shaded", std::string("--variant ") + variant);
    if (!shaded) GTEST_SKIP() << "no GL context";
    const auto counted = run(variant, std::string("--variant ") + variant + " --set show=1", true);
    ASSERT_TRUE(counted);
    EXPECT_EQ(counted->stencil.pixels, shaded->stencil.pixels) << variant;
    long long sum = 0, covered = 0, twice = 0;
    for (std::size_t i = 0; i < pixels(*counted); ++i) {
      sum += blends(*counted, i, 0) + blends(*counted, i, 1);
      covered += id(*counted, i) == kFigure && blends(*counted, i, 0) > 0;
      twice += blends(*counted, i, 0) > 1;
    }
    EXPECT_EQ(sum, passField(counted->stats, "halo", "samples_passed")) << variant;
    EXPECT_EQ(covered, counted->count("figure.covered_pixels")) << variant;
    EXPECT_EQ(twice, counted->count("figure.multi_blended_pixels")) << variant;
  }
}

// With the stencil no method puts a halo pixel over the figure, and INVERT blends each halo pixel
// once; without the stencil the halo covers the figure (Kilgard's "covered in yellow"), and without
// INVERT the overlapping layers blend twice.
TEST(Halo, NeverOverTheObjectAndOncePerPixel) {
  for (int method = 0; method < 4; ++method) {
    const std::string m = " --set method=" + std::to_string(method);
    const auto r = run(kMethods[method], "--set show=1" + m, true);
    if (!r) GTEST_SKIP() << "no GL context";
    EXPECT_GT(r->count("figure.halo_pixels"), 1000) << kMethods[method];
    EXPECT_EQ(r->count("figure.covered_pixels"), 0) << kMethods[method];
    EXPECT_EQ(r->count("figure.multi_blended_pixels"), 0) << kMethods[method];
    const auto keep = run(std::string(kMethods[method]) + "-keep", "--set show=1 --set invert=0" + m, true);
    EXPECT_EQ(keep->count("figure.covered_pixels"), 0) << kMethods[method];
    EXPECT_EQ(keep->count("figure.halo_pixels"), r->count("figure.halo_pixels")) << kMethods[method];
    EXPECT_GT(keep->count("figure.multi_blended_pixels"), 20) << kMethods[method];  // 37 for the whole figure
  }
  const auto off = run("no-stencil", "--variant no-stencil --set show=1", true);
  EXPECT_GT(off->count("figure.covered_pixels"), off->count("figure.object_pixels") * 9 / 10);
}

// The ring's width along the figure's outline, min and max as fractions of the mean: the whole
// figure scaled about its centre leaves parts of the outline bare (min 0); a piece at a time grows
// each piece by the same distance; pushing along the normals is even in world units; moving the
// outline k pixels is even on screen. Each is more uniform than the one before it.
TEST(Halo, WidthUniformityPerMethod) {
  std::vector<double> low, high;
  for (int method = 0; method < 4; ++method) {
    const auto r = run(kMethods[method], "--set show=1 --set method=" + std::to_string(method), true);
    if (!r) GTEST_SKIP() << "no GL context";
    EXPECT_GT(r->count("figure.outline_pixels"), 300) << kMethods[method];
    low.push_back(ratio(*r, "min"));
    high.push_back(ratio(*r, "max"));
  }
  EXPECT_EQ(low[0], 0.0);  // bare outline
  EXPECT_GT(high[0], 3.0);
  EXPECT_GT(low[1], 0.15);
  EXPECT_GT(low[2], low[1]);
  EXPECT_GE(low[3], 0.8);   // k = 5 pixels: 4 at worst where a digital circle rounds down
  EXPECT_LE(high[3], 1.5);  // 1.37 at the golden size
  EXPECT_LT(high[3], high[0]);
}

// The halo changes exactly the pixels it blends: every pixel that differs from the frame without
// the halo is a halo pixel of the count picture, and the halo pixels do differ.
TEST(Halo, ChangesExactlyItsPixels) {
  const auto without = run("without", "--set halo=0");
  if (!without) GTEST_SKIP() << "no GL context";
  const auto with = run("with", "");
  const auto counted = run("counted", "--set show=1");
  std::size_t outside = 0, halo = 0, changed = 0;
  for (std::size_t i = 0; i < pixels(*with); ++i) {
    const bool blended = blends(*counted, i, 0) > 0;
    const bool differs = stencil::testing::differs(with->colour, without->colour, i, 2);
    outside += differs && !blended;
    halo += blended;
    changed += differs && blended;
  }
  EXPECT_EQ(outside, 0u);
  EXPECT_GT(halo, 1000u);
  EXPECT_GT(changed, halo * 95 / 100);
}

// Each effect keeps to its bits: the floor's two bits (reflection, shadow) are the same with the
// halo or without, and the halo bits the same with the reflection and the shadow or without.
TEST(Halo, EachEffectOwnsItsBits) {
  const auto all = run("all", "--variant two-halos");
  if (!all) GTEST_SKIP() << "no GL context";
  const auto noHalo = run("no-halo", "--variant two-halos --set halo=0");
  const auto noFloor = run("no-floor-effects", "--variant two-halos --set reflect=0 --set shadow=0");
  std::size_t floorDiffers = 0, haloDiffers = 0, shadowed = 0, haloed = 0;
  for (std::size_t i = 0; i < pixels(*all); ++i) {
    const std::uint8_t s = all->stencil.pixels[i];
    floorDiffers += (s & 0x03) != (noHalo->stencil.pixels[i] & 0x03);
    haloDiffers += (s & 0x0C) != (noFloor->stencil.pixels[i] & 0x0C);
    shadowed += (s & 0x03) == 0x01;                              // floor, darkened
    haloed += (s & 0x0C) != (noHalo->stencil.pixels[i] & 0x0C);  // a halo blended here
  }
  EXPECT_EQ(floorDiffers, 0u);
  EXPECT_EQ(haloDiffers, 0u);
  EXPECT_GT(shadowed, 500u);
  EXPECT_GT(haloed, 1000u);
}

// The rail just in front of the figure: the grown shell is nearer than the rail and paints over it;
// at the figure's own depth the rail hides the halo.
TEST(Halo, TheRailHidesTheHaloAtTheObjectsDepth) {
  const auto shell = run("occluder", "--variant occluder --set show=1");
  if (!shell) GTEST_SKIP() << "no GL context";
  const auto fixed = run("occluder-fixed", "--variant occluder-fixed --set show=1");
  std::size_t painted = 0, paintedFixed = 0, rail = 0;
  for (std::size_t i = 0; i < pixels(*shell); ++i) {
    rail += id(*fixed, i) == kRail;
    painted += id(*shell, i) == kRail && blends(*shell, i, 0) > 0;
    paintedFixed += id(*fixed, i) == kRail && blends(*fixed, i, 0) > 0;
  }
  EXPECT_GT(rail, 300u);
  EXPECT_GT(painted, 20u);
  EXPECT_EQ(paintedFixed, 0u);
}

// The shell below the floor fails the depth test: without the floor pass the ring is cut at the
// feet (bare outline there, min width 0); the pixels the floor pass adds are all visible floor.
TEST(Halo, TheFloorPassKeepsTheRingAtTheFeet) {
  const auto cut = run("floor-cut", "--variant floor-cut --set show=1", true);
  if (!cut) GTEST_SKIP() << "no GL context";
  const auto whole = run("recipe", "--set show=1", true);
  EXPECT_EQ(cut->count("figure.width_min_x100"), 0);
  EXPECT_GT(whole->count("figure.width_min_x100"), 0);
  std::size_t added = 0, addedOffFloor = 0;
  for (std::size_t i = 0; i < pixels(*whole); ++i) {
    if (blends(*whole, i, 0) == 0 || blends(*cut, i, 0) > 0) continue;
    ++added;
    addedOffFloor += (whole->stencil.pixels[i] & 0x01) == 0;
  }
  EXPECT_GT(added, 50u);
  EXPECT_EQ(addedOffFloor, 0u);
}

// Two haloed objects: with a bit each both halos blend once, the ball's also over the figure behind
// it and where the two rings overlap, the figure's not over the ball in front of it; in one shared
// bit the figure's tag and INVERT cut the ball's ring.
TEST(Halo, TwoHalosNeedABitEach) {
  const auto own = run("two-halos", "--variant two-halos --set show=1", true);
  if (!own) GTEST_SKIP() << "no GL context";
  const auto shared = run("one-bit", "--variant two-halos-one-bit --set show=1", true);
  for (const LessonRun* r : {&*own, &*shared}) {
    EXPECT_EQ(r->count("ball.covered_pixels"), 0);
    EXPECT_EQ(r->count("ball.multi_blended_pixels"), 0);
    EXPECT_EQ(r->count("figure.multi_blended_pixels"), 0);
  }
  std::size_t both = 0, bothShared = 0, ballOverFigure = 0, ballOverFigureShared = 0, ball = 0,
              figureOverBall = 0;
  for (std::size_t i = 0; i < pixels(*own); ++i) {
    both += blends(*own, i, 0) > 0 && blends(*own, i, 1) > 0;
    bothShared += blends(*shared, i, 0) > 0 && blends(*shared, i, 1) > 0;
    ballOverFigure += id(*own, i) == kFigure && blends(*own, i, 1) > 0;
    ballOverFigureShared += id(*shared, i) == kFigure && blends(*shared, i, 1) > 0;
    ball += id(*own, i) == kBall;
    figureOverBall += id(*own, i) == kBall && blends(*own, i, 0) > 0;  // the ball stands in front
  }
  EXPECT_GT(ball, 500u);
  EXPECT_EQ(figureOverBall, 0u);
  EXPECT_GT(both, 10u);
  EXPECT_EQ(bothShared, 0u);
  EXPECT_GT(ballOverFigure, 10u);
  EXPECT_EQ(ballOverFigureShared, 0u);
  EXPECT_GT(own->count("ball.width_min_x100"), 0);
  EXPECT_EQ(shared->count("ball.width_min_x100"), 0);
  EXPECT_GT(own->count("ball.halo_pixels"), shared->count("ball.halo_pixels"));
}

// What each method costs: the screen-space dilation draws the figure once per pixel offset in a disc
// of radius 5 (81 offsets, 7 pieces each), so it rasterizes tens of times the fragments of a grown
// shell, for the same blended pixels give or take the ring's width.
TEST(Halo, TheScreenSpaceDilationCostsItsTaps) {
  const auto pieces = run("pieces", "--set show=1 --set method=1", true);
  if (!pieces) GTEST_SKIP() << "no GL context";
  const auto screen = run("screen", "--set show=1 --set method=3", true);
  const auto whole = run("whole", "--set show=1 --set method=0", true);
  const auto extrude = run("extrude", "--set show=1 --set method=2", true);
  EXPECT_EQ(passField(screen->stats, "halo", "draw_calls"), 2 * 81 * 7);  // the floor pass and the rest
  EXPECT_EQ(passField(pieces->stats, "halo", "draw_calls"), 2 * 7);
  EXPECT_GT(screen->count("figure.shell_fragments"), 20 * pieces->count("figure.shell_fragments"));
  for (const LessonRun* r : {&*pieces, &*whole, &*extrude})
    EXPECT_LT(r->count("figure.shell_fragments"), 2 * pieces->count("figure.shell_fragments"));
}
