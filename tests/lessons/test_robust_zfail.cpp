// Lesson 15's claims, measured on its own output: z-pass and z-fail give the same counts where
// nothing clips; the near plane costs z-pass exactly one entry where it cuts a volume, and the eye
// inside a volume costs it one everywhere, while z-fail is unaffected; a finite far plane costs
// z-fail exits, depth clamping gives them back; --stats reports the closed volumes' parts; and a
// scene file gets one shadow mask per light; a bounded light shades as in lesson 16 and adds nothing
// beyond its radius.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;
using stencil::testing::runLesson;

namespace {

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return runLesson(LESSON_15, name, args, stats);
}

// Pixels where b's count differs from a's, and how many of them by exactly `delta` (mod 256).
struct Difference {
  std::size_t pixels = 0, byDelta = 0;
};
Difference difference(const Image& a, const Image& b, int delta) {
  Difference d;
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (a.pixels[i] == b.pixels[i]) continue;
    ++d.pixels;
    d.byDelta += static_cast<std::uint8_t>(a.pixels[i] + delta) == b.pixels[i];
  }
  return d;
}

// Whether the scene covers pixel i: anything but the clear colour (26, 26, 33).
bool drawnAt(const LessonRun& r, std::size_t i) {
  const std::uint8_t* p = &r.colour.pixels[4 * i];
  return !(p[0] == 26 && p[1] == 26 && p[2] == 33);
}

// Whether a pixel of the 3x3 neighbourhood of pixel i has another count.
bool onCountEdge(const Image& stencil, std::size_t i) {
  const int x = static_cast<int>(i) % stencil.width, y = static_cast<int>(i) / stencil.width;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= stencil.width || ny >= stencil.height) continue;
      if (stencil.pixels[static_cast<std::size_t>(ny * stencil.width + nx)] != stencil.pixels[i]) return true;
    }
  return false;
}

}  // namespace

TEST(RobustZFail, ZPassAndZFailCountTheSameWhereNothingClips) {
  const auto zfail = run("zfail", "--variant zfail");
  const auto zpass = run("zpass", "--variant zpass");
  if (!zfail || !zpass) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(difference(zfail->stencil, zpass->stencil, 0).pixels, 0u);
  std::size_t shadowed = 0;
  for (std::uint8_t s : zfail->stencil.pixels) shadowed += s != 0;
  EXPECT_GT(shadowed, 1000u) << "a scene with shadows to compare";
}

TEST(RobustZFail, TheNearPlaneCostsZPassOneEntryWhereItCutsAVolume) {
  // The same view: z-fail is right (the oracle says so); z-pass loses the entry of every ray that
  // starts inside the cube's volume, so its count is one lower there and equal elsewhere.
  const auto zfail = run("zfail", "--variant zfail-near-plane");
  const auto zpass = run("zpass", "--variant zpass-near-plane");
  if (!zfail || !zpass) GTEST_SKIP() << "no GL context";
  const Difference d = difference(zfail->stencil, zpass->stencil, -1);
  EXPECT_GT(d.pixels, 5000u);
  EXPECT_EQ(d.byDelta, d.pixels) << "every wrong pixel lost exactly one entry";
}

TEST(RobustZFail, TheEyeInsideAVolumeCostsZPassOneEverywhereNotZFail) {
  // The counts alone: the mark (bit 7 on the sides turned from the light that count 0) is off.
  const auto zfail = run("zfail", "--variant eye-inside --set mark=0");
  const auto zpass = run("zpass", "--variant eye-inside --set zpass=1 --set mark=0");
  if (!zfail || !zpass) GTEST_SKIP() << "no GL context";
  const Difference d = difference(zfail->stencil, zpass->stencil, -1);
  EXPECT_EQ(d.pixels, zfail->stencil.pixels.size())
      << "z-pass subtracts the volume the eye is in, everywhere";
  EXPECT_EQ(d.byDelta, d.pixels);
}

TEST(RobustZFail, AFiniteFarPlaneCostsZFailExitsDepthClampGivesThemBack) {
  // Behind the ground the volumes go on; a far plane clips their exits (INCR on back faces), so
  // the count comes out lower, never higher. Depth clamping keeps them: the counts of Pinf,
  // wherever the scene was drawn. (Over the empty background the counts mean nothing: there
  // clamped fragments at depth 1 fail where Pinf's nearer ones pass.)
  const auto pinf = run("pinf", "--variant zfail");
  const auto finite = run("finite", "--variant zfail-finite-far");
  const auto clamped = run("clamped", "--variant depth-clamp");
  if (!pinf || !finite || !clamped) GTEST_SKIP() << "no GL context";
  std::size_t lower = 0, higher = 0;
  for (std::size_t i = 0; i < pinf->stencil.pixels.size(); ++i) {
    const int lost = static_cast<std::uint8_t>(pinf->stencil.pixels[i] - finite->stencil.pixels[i]);
    lower += lost > 0 && lost < 128;
    higher += lost >= 128;
  }
  EXPECT_GT(lower, 2000u);
  EXPECT_EQ(higher, 0u);
  std::size_t drawn = 0, differ = 0;
  for (std::size_t i = 0; i < pinf->stencil.pixels.size(); ++i) {
    if (!drawnAt(*pinf, i)) continue;
    ++drawn;
    if (pinf->stencil.pixels[i] == clamped->stencil.pixels[i]) continue;
    ++differ;
    // The two projections give other depths, so a tie on a shadow's or a caster's edge may go
    // either way; nowhere else.
    EXPECT_TRUE(onCountEdge(pinf->stencil, i)) << "at pixel " << i;
  }
  EXPECT_GT(drawn, 50000u);
  EXPECT_LT(differ, 10u);
}

TEST(RobustZFail, StatsCountTheClosedVolumesParts) {
  const auto one = run("one", "--variant zfail", true);
  const auto three = run("three", "--variant coloured-lights", true);
  const auto directional = run("directional", "--variant directional", true);
  if (!one || !three || !directional) GTEST_SKIP() << "no GL context";
  for (const LessonRun* r : {&*one, &*three, &*directional}) {
    // A silhouette edge extrudes into one quad: two triangles.
    EXPECT_EQ(r->count("side_triangles"), 2 * r->count("silhouette_edges"));
    EXPECT_GT(r->count("light_cap_triangles"), 0);
    EXPECT_EQ(r->count("lights_buried"), 0);  // reported when none is, not left out
  }
  // Every caster triangle faces a point light or not: the two caps hold each triangle once per light.
  const long long caps = one->count("light_cap_triangles") + one->count("dark_cap_triangles");
  EXPECT_EQ(three->count("light_cap_triangles") + three->count("dark_cap_triangles"), 3 * caps);
  // A directional light's dark cap at infinity is the one point -L: none drawn.
  EXPECT_EQ(directional->count("dark_cap_triangles"), 0);
  EXPECT_LT(directional->count("light_cap_triangles"), caps);
}

TEST(RobustZFail, ASceneFileGetsAMaskPerLightTheLastOneIsTheFinalStencil) {
  // The two-light scene file: every light shines and writes its mask after its
  // volumes are counted; the light drawn last leaves its count in the stencil.
  const std::string scene = std::string(SCENES_DIR) + "/two-lights.scene";
  for (int last = 0; last < 2; ++last) {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const auto dir = std::filesystem::temp_directory_path() / "stencil-15-robust-zfail" /
                     (std::string(test->name()) + "-masks-" + std::to_string(last));
    std::filesystem::remove_all(dir);
    const auto r =
        run("last-" + std::to_string(last),
            "--scene " + scene + " --set last=" + std::to_string(last) + " --mask-out " + dir.string());
    if (!r) GTEST_SKIP() << "no GL context";
    ASSERT_TRUE(std::filesystem::exists(dir / "light-0.png"));
    ASSERT_TRUE(std::filesystem::exists(dir / "light-1.png"));
    const Image mask = readPng(dir / ("light-" + std::to_string(last) + ".png"), 1);
    ASSERT_EQ(mask.pixels.size(), r->stencil.pixels.size());
    std::size_t mismatches = 0, shadowed = 0;
    for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
      mismatches += mask.pixels[i] != (r->stencil.pixels[i] == 0 ? 255 : 0);
      shadowed += mask.pixels[i] == 0;
    }
    EXPECT_EQ(mismatches, 0u) << "the last light's mask is the final stencil";
    EXPECT_GT(shadowed, 1000u);
  }
}

TEST(RobustZFail, ABoundedLightAddsNothingBeyondItsRadiusAndShadesAsLesson16Does) {
  // One shading rule for both lessons (shaders/common/light.frag): a point light's radius is
  // where its light reaches zero. The scene's light (radius 3 at (0, 1.5, 0)) may change only
  // pixels inside the screen rectangle of its bounding cube; the same scene with the light
  // turned off is the ambient picture.
  const std::string file = std::string(SCENES_DIR) + "/hard/light-radius-shades-nothing-beyond.scene";
  const auto dark = std::filesystem::temp_directory_path() / "stencil-15-robust-zfail" / "light-off.scene";
  std::filesystem::create_directories(dark.parent_path());  // this test may run first
  {
    std::ifstream in(file);
    std::ofstream out(dark);
    for (std::string line; std::getline(in, line);)
      out << (line.rfind("light point", 0) == 0 ? "light point 0 1.5 0 color 0 0 0 radius 3" : line) << "\n";
  }
  const auto lit = run("bounded", "--scene " + file), ambient = run("ambient", "--scene " + dark.string());
  const auto sixteen = runLesson(LESSON_16, "bounded", "--scene " + file);
  if (!lit || !ambient || !sixteen) GTEST_SKIP() << "no GL context";

  const int w = lit->colour.width, h = lit->colour.height;
  const glm::mat4 viewProjection = glm::perspective(glm::radians(55.0f), float(w) / float(h), 0.3f, 100.0f) *
                                   glm::lookAt(glm::vec3(0, 7, 9), glm::vec3(0), glm::vec3(0, 1, 0));
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 offset(corner & 1 ? 3.0f : -3.0f, corner & 2 ? 3.0f : -3.0f, corner & 4 ? 3.0f : -3.0f);
    const glm::vec4 clip = viewProjection * glm::vec4(glm::vec3(0, 1.5f, 0) + offset, 1.0f);
    const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(w, h);
    lo = glm::min(lo, pixel);
    hi = glm::max(hi, pixel);
  }
  std::size_t outsideChanged = 0, insideChanged = 0, disagree = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x);
      // PNG rows run top down, window coordinates bottom up; a pixel's centre is at +0.5.
      const glm::vec2 centre(float(x) + 0.5f, float(h - 1 - y) + 0.5f);
      const bool inside = glm::all(glm::greaterThanEqual(centre, lo - 1.0f)) &&
                          glm::all(glm::lessThanEqual(centre, hi + 1.0f));
      const bool changed = stencil::testing::differs(lit->colour, ambient->colour, i, 1);
      (inside ? insideChanged : outsideChanged) += changed;
      if (drawnAt(*lit, i))  // the background is each lesson's own
        disagree += stencil::testing::differs(lit->colour, sixteen->colour, i, 2);
    }
  EXPECT_EQ(outsideChanged, 0u) << "the light reaches past its radius";
  EXPECT_GT(insideChanged, 1000u) << "the light lights nothing";
  EXPECT_EQ(disagree, 0u) << "lessons 15 and 16 shade the scene differently";
}

TEST(RobustZFail, ARoomIsLitFromInsideWhicheverWayItsFacesPoint) {
  // The eye and light 0 inside a closed box (a room), light 1 outside a corner: light 0 lights
  // the walls' inner sides (two-sided receivers: the side the eye sees), light 1 nothing. The
  // room written as an OBJ facing inwards gives the same picture, in both lessons.
  const std::string box = std::string(SCENES_DIR) + "/hard/room-eye-inside-a-box.scene";
  const std::string inward = std::string(SCENES_DIR) + "/hard/room-faces-inward.scene";
  const auto dark = std::filesystem::temp_directory_path() / "stencil-15-robust-zfail" / "room-dark.scene";
  std::filesystem::create_directories(dark.parent_path());  // this test may run first
  {  // the same room with light 0 off: what light 0 adds shows against it
    std::ifstream in(box);
    std::ofstream out(dark);
    for (std::string line; std::getline(in, line);)
      out << (line.rfind("light point 0.8", 0) == 0 ? "light point 0.8 2.5 0.8 color 0 0 0" : line) << "\n";
  }
  const auto lit = run("room", "--scene " + box), off = run("room-dark", "--scene " + dark.string()),
             fromObj = run("room-inward", "--scene " + inward);
  const auto sixteen = runLesson(LESSON_16, "room", "--scene " + box),
             sixteenObj = runLesson(LESSON_16, "room-inward", "--scene " + inward);
  if (!lit || !off || !fromObj || !sixteen || !sixteenObj) GTEST_SKIP() << "no GL context";
  const std::size_t pixels = lit->colour.pixels.size() / 4;
  std::size_t brighter = 0, objDiffers = 0, sixteenDiffers = 0, sixteenObjDiffers = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    brighter += stencil::testing::differs(lit->colour, off->colour, i, 2);
    objDiffers += stencil::testing::differs(lit->colour, fromObj->colour, i, 2);
    sixteenDiffers += stencil::testing::differs(lit->colour, sixteen->colour, i, 2);
    sixteenObjDiffers += stencil::testing::differs(sixteen->colour, sixteenObj->colour, i, 2);
  }
  EXPECT_GT(brighter, pixels * 9 / 10) << "light 0 lights the room's inside";
  EXPECT_EQ(objDiffers, 0u) << "the room facing inwards looks the same";
  EXPECT_EQ(sixteenDiffers, 0u) << "lesson 16 draws the room as lesson 15 does";
  EXPECT_EQ(sixteenObjDiffers, 0u);
}
