// Lesson 16's claims, measured on its output: the three robust methods give the same shadow with
// the eye in one, z-pass alone does not; per caster the volume costs O(s) triangles in cases 1
// and 2 and O(f) in case 3 (the paper's table), against O(f) for Everitt and Kilgard's caps;
// the counts --stats reports add up to the triangles drawn; the light's bounds cull work without
// changing a pixel; and accumulating many dim lights in 8 bits rounds each one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;
using stencil::testing::LessonStats;

namespace {

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return stencil::testing::runLesson(LESSON_16, name, args, stats);
}

// Pixels whose lit/shadowed verdict (stencil 0 or not) differs between two runs.
std::size_t verdictsDiffering(const Image& a, const Image& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) n += (a.pixels[i] == 0) != (b.pixels[i] == 0);
  return n;
}

// The triangles of every pass with this name, from the --stats JSON.
long long passTriangles(const LessonStats& stats, const std::string& pass) {
  return stats.passTotal(pass, "triangles");
}

TEST(FastRobustShadows, RobustMethodsAgreeWithTheEyeInAShadowAndZPassDoesNot) {
  for (const char* camera : {"eye-in-shadow", "looking-up"}) {
    const auto mcguire = run("mcguire", std::string("--variant ") + camera);
    if (!mcguire) GTEST_SKIP() << "no GL context";
    for (int method : {1, 2}) {
      const auto other = run("method" + std::to_string(method),
                             std::string("--variant ") + camera + " --set method=" + std::to_string(method));
      EXPECT_EQ(verdictsDiffering(mcguire->stencil, other->stencil), 0u) << camera << ", method " << method;
    }
    const auto zpass = run("zpass", std::string("--variant ") + camera + " --set method=3");
    // The eye's own volume adds one to every count: most of the picture is judged wrongly.
    EXPECT_GT(verdictsDiffering(mcguire->stencil, zpass->stencil), mcguire->stencil.pixels.size() / 3)
        << camera;
  }
}

TEST(FastRobustShadows, WithNoCasterInThePyramidZPassIsEnough) {
  const auto mcguire = run("mcguire", "--variant system", true);
  if (!mcguire) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(mcguire->count("casters_zfail"), 0);
  for (int method : {1, 2, 3}) {
    const auto other =
        run("method" + std::to_string(method), "--variant system --set method=" + std::to_string(method));
    EXPECT_EQ(verdictsDiffering(mcguire->stencil, other->stencil), 0u) << "method " << method;
  }
}

// A light a hair above a box's top face: the fan triangle in that face's plane spans more than
// 179 degrees seen from the light and is split; the shadow still matches the ray cast, split or
// not (the rasterizer draws a triangle at infinity as the cone of its directions either way).
TEST(FastRobustShadows, FanTrianglesUnderALightInTheirPlaneAreSplit) {
  const std::string scene = std::string(SCENES_DIR) + "/light-on-the-box.scene";
  const auto split = run("split", "--scene " + scene, true);
  if (!split) GTEST_SKIP() << "no GL context";
  EXPECT_GT(split->count("split_fan_triangles"), 0);
  const auto whole = run("whole", "--scene " + scene + " --set split=0", true);
  EXPECT_EQ(whole->count("split_fan_triangles"), 0);
  EXPECT_EQ(verdictsDiffering(split->stencil, whole->stencil), 0u);
}

// The fill pass measures and changes nothing; Everitt and Kilgard's caps rasterize more than the
// paper's per-case volumes from the same camera.
TEST(FastRobustShadows, TheFillPassCountsEveryVolumeFragmentAndChangesNothing) {
  const auto plain = run("plain", "--variant looking-up", true);
  if (!plain) GTEST_SKIP() << "no GL context";
  const auto measured = run("measured", "--variant looking-up --set fill=1", true);
  EXPECT_EQ(plain->stencil.pixels, measured->stencil.pixels);
  EXPECT_EQ(plain->colour.pixels, measured->colour.pixels);
  // The fill pass draws the volumes again; the shadow pass also marks the sides turned from the light.
  EXPECT_EQ(passTriangles(measured->stats, "volume-fill") + measured->count("mark_triangles"),
            passTriangles(measured->stats, "shadows"));
  const auto fill = [](const LessonStats& stats) { return stats.passTotal("volume-fill", "samples_passed"); };
  const auto everittKilgard = run("ek", "--variant looking-up --set fill=1 --set method=1", true);
  EXPECT_GT(fill(measured->stats), 0);
  EXPECT_GT(fill(everittKilgard->stats), fill(measured->stats));
}

struct SphereCost {
  long long shadowCase, sides, darkCap, lightCap;
};

SphereCost sphereCost(const std::string& variant, int slices, int method = 0) {
  const auto r = run(variant + "-" + std::to_string(slices) + "-" + std::to_string(method),
                     "--variant " + variant + " --set slices=" + std::to_string(slices) +
                         " --set method=" + std::to_string(method),
                     true);
  if (!r) return {-1, 0, 0, 0};
  return {r->count("case.sphere"), r->count("sides.sphere"), r->count("dark_cap.sphere"),
          r->count("light_cap.sphere")};
}

// The sphere's silhouette has O(slices) edges and its lit half O(slices^2) faces: doubling the
// slices doubles what grows as O(s) and quadruples what grows as O(f).
TEST(FastRobustShadows, CasesCostOfSOfSOfF) {
  const char* variants[] = {"system", "eye-in-shadow", "looking-up"};  // the sphere in case 1, 2, 3
  for (int c = 0; c < 3; ++c) {
    const SphereCost small = sphereCost(variants[c], 16), large = sphereCost(variants[c], 32);
    if (small.shadowCase < 0) GTEST_SKIP() << "no GL context";
    ASSERT_EQ(small.shadowCase, c + 1);
    ASSERT_EQ(large.shadowCase, c + 1);
    for (const SphereCost& s : {small, large}) {
      EXPECT_GT(s.sides, 0);
      // The fan: one triangle per silhouette edge (two side triangles each) but the apex's two.
      EXPECT_EQ(s.darkCap, c == 0 ? 0 : s.sides / 2 - 2) << variants[c];
      EXPECT_EQ(s.lightCap == 0, c != 2) << variants[c];
    }
    const double sides = double(large.sides) / double(small.sides);
    EXPECT_GT(sides, 1.6);
    EXPECT_LT(sides, 2.4);
    if (c == 2) {
      const double lightCap = double(large.lightCap) / double(small.lightCap);
      EXPECT_GT(lightCap, 3.2);
      EXPECT_LT(lightCap, 4.8);
    }
  }
  // Everitt and Kilgard close every volume with the faces away from the light: O(f) whatever
  // the case.
  const SphereCost small = sphereCost("eye-in-shadow", 16, 1), large = sphereCost("eye-in-shadow", 32, 1);
  const double darkCap = double(large.darkCap) / double(small.darkCap);
  EXPECT_GT(darkCap, 3.2);
  EXPECT_LT(darkCap, 4.8);
  EXPECT_GT(large.lightCap, 0);
}

TEST(FastRobustShadows, ReportedCountsAddUpToTheShadowPasses) {
  for (const char* variant : {"system", "looking-up", "lengyel", "everitt-kilgard", "directional"}) {
    const auto r = run(variant, std::string("--variant ") + variant, true);
    if (!r) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(passTriangles(r->stats, "shadows"), r->count("side_triangles") + r->count("dark_cap_triangles") +
                                                      r->count("light_cap_triangles") + r->count("mark_triangles"))
        << variant;
    EXPECT_EQ(r->count("casters_case1") + r->count("casters_case2") + r->count("casters_case3") +
                  r->count("casters_culled"),
              13 * r->count("lights_drawn"))
        << variant;  // every caster once per light
    // EXT_depth_bounds_test is used for bounded lights where the driver has it, else reported skipped.
    const bool depthBounds = r->stats.feature("depth_bounds_test");
    EXPECT_EQ(r->count("depth_bounds_used") + r->count("depth_bounds_skipped"), r->count("lights_drawn"));
    if (!depthBounds) {
      EXPECT_EQ(r->count("depth_bounds_used"), 0);
    }
  }
}

TEST(FastRobustShadows, LightBoundsCullWorkButNoPixel) {
  const auto bounded = run("bounded", "--variant system", true);
  if (!bounded) GTEST_SKIP() << "no GL context";
  const auto unbounded = run("unbounded", "--variant no-bounds", true);
  EXPECT_EQ(bounded->colour.pixels, unbounded->colour.pixels);
  EXPECT_GT(bounded->count("casters_culled"), 0);
  EXPECT_EQ(unbounded->count("casters_culled"), 0);
  EXPECT_LT(passTriangles(bounded->stats, "shadows"), passTriangles(unbounded->stats, "shadows"));
}

// Thirty-two dim lights: in RGBA8 every light's contribution is rounded to 1/255 as it is added,
// so the sum drifts from the float sum, by at most half a level per light plus the float
// result's own final rounding: more than the one level a single rounding can explain.
TEST(FastRobustShadows, EightBitAccumulationRoundsEachLight) {
  const auto floating = run("float", "--variant many-lights --set stretch=0");
  if (!floating) GTEST_SKIP() << "no GL context";
  const auto eightBit = run("8bit", "--variant many-lights-8bit --set stretch=0");
  int largest = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i < floating->colour.pixels.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int(floating->colour.pixels[i + c]) - int(eightBit->colour.pixels[i + c]));
      largest = std::max(largest, d);
      sum += d;
    }
  std::cout << "8-bit against float accumulation: largest difference " << largest << " levels, mean "
            << sum / double(3 * floating->colour.pixels.size() / 4) << "\n";
  EXPECT_GT(largest, 1);
  EXPECT_LE(largest, 32 / 2 + 1);
}

}  // namespace

namespace {

// Mean brightness, (r + g + b) / 3 in 0..1, of a colour picture.
double meanBrightness(const Image& image) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 4)
    sum += (image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2]) / 3.0;
  return sum / 255.0 / double(image.pixels.size() / 4);
}

// Pixels where some channel differs by more than `levels` between two pictures.
std::size_t pixelsDiffering(const Image& a, const Image& b, int levels) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); i += 4) {
    bool differs = false;
    for (std::size_t c = 0; c < 3; ++c)
      differs |= std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > levels;
    n += differs;
  }
  return n;
}

// The views from inside the sphere's shadow are readable: the scene's 0.12 ambient left them at a
// mean of 0.104, the system view's is 0.263.
TEST(FastRobustShadows, ViewsFromTheShadowAreBrightEnoughToRead) {
  for (const char* variant : {"looking-up", "everitt-kilgard", "lengyel", "no-light-cap"}) {
    const auto r = run(variant, std::string("--variant ") + variant);
    if (!r) GTEST_SKIP() << "no GL context";
    const double mean = meanBrightness(r->colour);
    std::cout << variant << ": mean brightness " << mean << "\n";
    EXPECT_GT(mean, 0.15) << variant;
  }
}

// Without the light cap the sphere's count is wrong; the shadow tint shows where in the colour
// picture, not only in the stencil.
TEST(FastRobustShadows, AMissingLightCapShowsInTheColourPicture) {
  const auto right = run("right", "--variant looking-up");
  if (!right) GTEST_SKIP() << "no GL context";
  const auto wrong = run("wrong", "--variant no-light-cap");
  const std::size_t verdicts = verdictsDiffering(right->stencil, wrong->stencil);
  const std::size_t colours = pixelsDiffering(right->colour, wrong->colour, 16);
  std::cout << "no light cap: " << verdicts << " verdicts wrong, " << colours << " colour pixels differ\n";
  EXPECT_GT(verdicts, 0u);
  EXPECT_GT(colours, right->colour.pixels.size() / 4 / 100);  // over 1% of the picture
  EXPECT_GE(colours, verdicts * 9 / 10);                      // most wrong verdicts are seen
}

// The 8-bit bands are shown: the pictures of the two many-lights variants differ by more than
// a few levels (2 mean per channel is below what the eye finds in a smooth gradient).
TEST(FastRobustShadows, EightBitBandsShowInThePicture) {
  const auto floating = run("float-shown", "--variant many-lights");
  if (!floating) GTEST_SKIP() << "no GL context";
  const auto eightBit = run("8bit-shown", "--variant many-lights-8bit");
  double sum = 0.0;
  for (std::size_t i = 0; i < floating->colour.pixels.size(); i += 4)
    for (std::size_t c = 0; c < 3; ++c)
      sum += std::abs(int(floating->colour.pixels[i + c]) - int(eightBit->colour.pixels[i + c]));
  const double mean = sum / double(3 * floating->colour.pixels.size() / 4);
  const std::size_t visible = pixelsDiffering(floating->colour, eightBit->colour, 6);
  std::cout << "8-bit against float as shown: mean " << mean << " levels, " << visible
            << " pixels over 6 levels\n";
  EXPECT_GT(visible, floating->colour.pixels.size() / 4 / 20);  // over 5% of the picture
}

}  // namespace

// The three ways of finding the possible silhouette edges (--set silhouettes) are one edge set:
// the same stencil and the same colour, pixel for pixel, and the same side triangles, on a point
// light above, the directional light and the eye looking up through the shadows; the dual-space
// tree is really queried (it reports the cells it visited).
TEST(FastRobustShadows, SilhouettesFoundEachWayAreTheSameEdges) {
  for (const char* variant : {"system", "directional", "looking-up"}) {
    const auto brute = run("brute", std::string("--variant ") + variant, true);
    if (!brute) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(brute->count("dual_cells_visited"), -1) << variant;
    for (int how : {1, 2}) {
      const auto other =
          run("silhouettes" + std::to_string(how),
              std::string("--variant ") + variant + " --set silhouettes=" + std::to_string(how), true);
      EXPECT_EQ(other->stencil.pixels, brute->stencil.pixels) << variant << ", silhouettes=" << how;
      EXPECT_EQ(other->colour.pixels, brute->colour.pixels) << variant << ", silhouettes=" << how;
      EXPECT_EQ(other->count("side_triangles"), brute->count("side_triangles")) << variant << ", " << how;
      if (how == 2) {
        EXPECT_GT(other->count("dual_cells_visited"), 0) << variant;
      }
    }
  }
}
