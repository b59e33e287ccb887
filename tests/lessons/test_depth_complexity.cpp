// Lesson 13's claims, measured on its output: fragments that pass the depth test and those that
// fail it add up to every fragment, pixel for pixel; every fragment equals the CPU count of the
// surfaces each pixel's ray crosses (front faces only with culling), on the lesson's scene and on
// scene files; the histogram --stats prints is the stencil's own; and past 255 INCR stops (the
// picture says so in cyan) while INCR_WRAP wraps. Shadow volumes counted the same way add up to
// the fill lesson 16 reports for each method, and light bounds cut it on a hall of many lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gl/stencil_view.h"
#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;

namespace {

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return stencil::testing::runLesson(LESSON_13, name, args, stats);
}

// The oracle's verdict: every disagreement on an edge of the ray count's picture, and few of those.
void expectRayCountAgrees(const LessonRun& r, const std::string& what) {
  ASSERT_GT(r.count("oracle_pixels"), 0) << what;
  EXPECT_EQ(r.count("oracle_disagreements"), r.count("oracle_on_edges")) << what;
  EXPECT_LT(r.count("oracle_on_edges"), r.count("oracle_pixels") / 100) << what;
}

}  // namespace

TEST(DepthComplexity, PassedPlusFailedIsEveryFragment) {
  for (const char* cull : {"0", "1"}) {
    const std::string c = std::string(" --set cull=") + cull;
    const auto all = run("all", "--variant all" + c);
    if (!all) GTEST_SKIP() << "no GL context";
    const auto passed = run("passed", "--variant depth-pass" + c);
    const auto failed = run("failed", "--variant depth-fail" + c);
    const auto both = run("both", "--variant both-outcomes" + c);
    std::size_t wrong = 0, hidden = 0;
    for (std::size_t i = 0; i < all->stencil.pixels.size(); ++i) {
      wrong += passed->stencil.pixels[i] + failed->stencil.pixels[i] != all->stencil.pixels[i];
      hidden += failed->stencil.pixels[i] > 0;
    }
    EXPECT_EQ(wrong, 0u) << "cull " << cull;
    EXPECT_GT(hidden, 0u) << "cull " << cull;  // the scene hides something, in its draw order
    EXPECT_EQ(both->stencil.pixels, all->stencil.pixels) << "cull " << cull;
  }
}

TEST(DepthComplexity, EveryFragmentIsTheRayCount) {
  for (const char* variant : {"all", "all-culled", "both-outcomes"}) {
    const auto r = run(variant, std::string("--variant ") + variant + " --set oracle=1", true);
    if (!r) GTEST_SKIP() << "no GL context";
    expectRayCountAgrees(*r, variant);
  }
  // Culling drops the back faces: fewer fragments, the same pixels covered.
  const auto all = run("all", "--variant all", true);
  const auto culled = run("culled", "--variant all-culled", true);
  EXPECT_LT(culled->count("counted_fragments"), all->count("counted_fragments"));
  EXPECT_EQ(culled->count("covered_pixels"), all->count("covered_pixels"));
}

TEST(DepthComplexity, TheHistogramIsTheStencils) {
  const auto r = run("all", "--variant all", true);
  if (!r) GTEST_SKIP() << "no GL context";
  std::vector<long long> histogram(256, 0);
  for (std::uint8_t v : r->stencil.pixels) ++histogram[v];
  long long largest = 0, fragments = 0;
  for (int k = 0; k < 256; ++k) {
    const long long reported = r->count("histogram." + std::to_string(k));
    EXPECT_EQ(reported < 0 ? 0 : reported, histogram[static_cast<std::size_t>(k)]) << "count " << k;
    if (histogram[static_cast<std::size_t>(k)] > 0) largest = k;
    fragments += k * histogram[static_cast<std::size_t>(k)];
  }
  EXPECT_EQ(r->count("max_count"), largest);
  EXPECT_GE(largest, 6);  // the nested cubes alone are six deep
  EXPECT_EQ(r->count("counted_fragments"), fragments);
  // With the depth test off every fragment of the count pass passes its occlusion query.
  EXPECT_EQ(r->stats.firstPass("count", "samples_passed"), fragments);
}

// 300 quads one behind the other: INCR stops at 255, and the picture shows those pixels in the
// saturated colour; INCR_WRAP leaves 300 - 256 = 44 where all 300 overlap. The ray count, stopped
// or wrapped the same way, agrees with both.
TEST(DepthComplexity, PastTwoHundredAndFiftyFive) {
  const auto saturates = run("saturates", "--variant stack-saturates --set oracle=1", true);
  if (!saturates) GTEST_SKIP() << "no GL context";
  expectRayCountAgrees(*saturates, "stack-saturates");
  const auto wraps = run("wraps", "--variant stack-wraps --set oracle=1", true);
  expectRayCountAgrees(*wraps, "stack-wraps");
  // Where INCR stopped at 255, INCR_WRAP holds what is left past 256: 0..44, and 44 where all
  // 300 quads overlap.
  std::size_t stopped = 0, wrapped = 0;
  for (std::size_t i = 0; i < saturates->stencil.pixels.size(); ++i) {
    if (saturates->stencil.pixels[i] != 255) continue;
    ++stopped;
    EXPECT_LE(wraps->stencil.pixels[i], 44);
    wrapped += wraps->stencil.pixels[i] == 44;
  }
  EXPECT_GT(stopped, 1000u);
  EXPECT_GT(wrapped, 0u);
  EXPECT_EQ(saturates->count("saturated_pixels"), static_cast<long long>(stopped));
  // The stored counts lose what INCR dropped: fewer than the fragments drawn.
  EXPECT_LT(saturates->count("counted_fragments"), saturates->stats.firstPass("count", "samples_passed"));
  // Every saturated pixel above the legend band shows the saturated colour.
  const auto cyan = saturatedCountColour();
  std::size_t saturatedAbove = 0, notCyan = 0;
  for (std::size_t i = 0; i < 150u * 320u; ++i) {
    if (saturates->stencil.pixels[i] != 255) continue;
    ++saturatedAbove;
    const std::uint8_t* p = &saturates->colour.pixels[4 * i];
    notCyan += p[0] != cyan[0] || p[1] != cyan[1] || p[2] != cyan[2];
  }
  EXPECT_GT(saturatedAbove, 1000u);
  EXPECT_EQ(notCyan, 0u);
}

// The stack stands in for the shadow volumes: with `volumes` on too, its depth-pass count is the
// stack's own, against an empty depth buffer, not against the shaded scene's depth.
TEST(DepthComplexity, TheStackCountsTheSameWithVolumesOn) {
  const auto alone = run("stack-alone", "--set stack=1 --set count=1");
  const auto withVolumes = run("stack-volumes", "--set stack=1 --set count=1 --set volumes=1");
  if (!alone || !withVolumes) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(withVolumes->stencil.pixels, alone->stencil.pixels);
  EXPECT_GT(std::count(alone->stencil.pixels.begin(), alone->stencil.pixels.end(), 1), 1000);
}

// Scene files (lessons 15-16's format): the ray count agrees with every fragment, with and without
// culling; the mirrored view turns the front faces round, which culling must follow.
TEST(DepthComplexity, SceneFilesAgreeWithTheRayCount) {
  for (const char* file :
       {"builtin.scene", "two-lights.scene", "hard/mirrored-view.scene", "hard/open-mesh.scene",
        "hard/mirrored-one-sided.scene"}) {
    for (const char* cull : {"0", "1"}) {
      const auto r =
          run("scene",
              std::string("--scene ") + SCENES_DIR + "/" + file + " --set oracle=1 --set cull=" + cull, true);
      if (!r) GTEST_SKIP() << "no GL context";
      expectRayCountAgrees(*r, std::string(file) + " cull " + cull);
    }
  }
}

namespace {

// Every fragment of every light's shadow volumes, as lesson 16 reports it: the samples_passed of
// all its volume-fill passes (one per light drawn), with --set fill=1.
long long lessonSixteenFill(const stencil::testing::LessonStats& stats) {
  return stats.passTotal("volume-fill", "samples_passed");
}

const char* const kMethods[] = {"mcguire", "everitt-kilgard", "lengyel", "zpass"};

}  // namespace

// The volumes' fill counted per pixel in the stencil adds up to the fragments lesson 16's fill
// pass rasterizes, for each method, with the light bounds on and off. Lesson 16's fill pass has
// no depth bounds test; where the driver has EXT_depth_bounds_test, lesson 13's count (which
// uses it, as the stencil pass does) can only be smaller.
TEST(DepthComplexity, ShadowVolumeFillIsLessonSixteensFill) {
  for (const char* file :
       {"builtin.scene", "hard/light-in-open-container.scene", "interior-many-lights.scene"}) {
    const std::string scene = std::string("--scene ") + SCENES_DIR + "/" + file;
    for (int method = 0; method < 4; ++method) {
      for (const char* bounds : {"1", "0"}) {
        const std::string set = std::string(" --set bounds=") + bounds;
        const std::string name = std::string(kMethods[method]) + "-" + bounds;
        const auto counted = run(name, scene + set + " --set volumes=" + std::to_string(method + 1), true);
        if (!counted) GTEST_SKIP() << "no GL context";
        const auto reported = stencil::testing::runLesson(
            LESSON_16, name + "-16", scene + set + " --set fill=1 --set method=" + std::to_string(method),
            true);
        ASSERT_TRUE(reported);
        const std::string what = std::string(file) + ", " + kMethods[method] + ", bounds " + bounds;
        EXPECT_EQ(counted->count("saturated_pixels"), 0) << what;
        EXPECT_GT(counted->count("counted_fragments"), 0) << what;
        const long long fill = lessonSixteenFill(reported->stats);
        if (counted->count("depth_bounds_used") > 0) {
          EXPECT_LE(counted->count("counted_fragments"), fill) << what;
        } else {
          EXPECT_EQ(counted->count("counted_fragments"), fill) << what;
        }
      }
    }
  }
}

// Sixteen attenuated lights in a hall: the lights' bounds (culling and scissor) cut every
// method's fill, McGuire et al.'s per-case caps cut it below Everitt and Kilgard's, and the
// paper's system rasterizes less than half of what Everitt and Kilgard's unbounded volumes do.
TEST(DepthComplexity, LightBoundsCutTheInteriorsFill) {
  const std::string scene = std::string("--scene ") + SCENES_DIR + "/interior-many-lights.scene";
  long long fill[4][2];
  for (int method = 0; method < 4; ++method)
    for (int bounds = 0; bounds < 2; ++bounds) {
      const auto r = run(
          std::string(kMethods[method]) + "-" + std::to_string(bounds),
          scene + " --set volumes=" + std::to_string(method + 1) + " --set bounds=" + std::to_string(bounds),
          true);
      if (!r) GTEST_SKIP() << "no GL context";
      fill[method][bounds] = r->count("counted_fragments");
      if (bounds == 1) {
        EXPECT_GT(r->count("casters_culled"), 0) << kMethods[method];
      }
    }
  for (int method = 0; method < 4; ++method)
    EXPECT_LT(2 * fill[method][1], fill[method][0]) << kMethods[method];
  EXPECT_LT(fill[0][1], fill[1][1]);
  EXPECT_LT(fill[0][0], fill[1][0]);
  EXPECT_LT(2 * fill[0][1], fill[1][0]);
}
