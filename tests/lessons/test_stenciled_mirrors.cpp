// Lesson 02's claims, measured on its output. After the frame the stencil holds 2 wherever a
// mirror's reflection was drawn (the cleared tag), 0 elsewhere.
#include "lesson_run.h"

using namespace stencil;
using namespace stencil::testing;

namespace {

constexpr std::uint8_t kDone = 2;

std::size_t count(const LessonRun& r, std::uint8_t value) {
  std::size_t n = 0;
  for (std::uint8_t s : r.stencil.pixels) n += s == value;
  return n;
}

struct Changes {
  std::size_t inMirrors = 0, elsewhere = 0;
};

// Pixels that differ between two renders, inside and outside `region`'s mirrors.
Changes changes(const LessonRun& a, const LessonRun& b, const LessonRun& region) {
  Changes c;
  for (std::size_t i = 0; i < a.stencil.pixels.size(); ++i)
    if (differs(a.colour, b.colour, i)) (region.stencil.pixels[i] == kDone ? c.inMirrors : c.elsewhere) += 1;
  return c;
}

}  // namespace

// The reflections change only pixels of the mirrors that show them, in every stenciled
// variant, the grazing mirror and the marble included.
TEST(StenciledMirrors, ReflectionsStayInsideTheirMirrors) {
  for (const std::string variant : {"mirrors", "semi-reflective", "no-clip", "grazing"}) {
    const auto with = runLesson(LESSON_02, variant, "--variant " + variant);
    const auto without = runLesson(LESSON_02, variant + "-off", "--variant " + variant + " --set reflect=0");
    if (!with || !without) GTEST_SKIP() << "no GL context";
    const Changes c = changes(*with, *without, *with);
    EXPECT_GT(c.inMirrors, 2000u) << variant;
    EXPECT_EQ(c.elsewhere, 0u) << variant << ": a reflection leaked out of its mirror";
  }
}

// The same check catches lesson 01's leaks when the stencil is off.
TEST(StenciledMirrors, WithoutTheStencilReflectionsLeak) {
  const auto region = runLesson(LESSON_02, "mirrors", "--variant mirrors");
  const auto with = runLesson(LESSON_02, "off", "--variant stencil-off");
  const auto without = runLesson(LESSON_02, "off-none", "--variant stencil-off --set reflect=0");
  if (!region || !with || !without) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(count(*with, kDone), 0u) << "stencil-off should leave no tags";
  EXPECT_GT(changes(*with, *without, *region).elsewhere, 2000u);
}

// A mirror in front of another: the tag is depth tested and the restore writes the glass's
// depth back, so the order in which the mirrors are processed does not matter. Without
// either, the mirror processed last would paint over the one in front of it.
TEST(StenciledMirrors, MirrorOrderDoesNotMatterWhenOneOccludesAnother) {
  const auto back = runLesson(LESSON_02, "back", "--variant mirrors --set mirrors=1");
  const auto forwards = runLesson(LESSON_02, "forwards", "--variant mirrors --set mirrors=2");
  const auto backwards = runLesson(LESSON_02, "backwards", "--variant mirrors --set mirrors=2 --set order=1");
  if (!back || !forwards || !backwards) GTEST_SKIP() << "no GL context";
  std::size_t covered = 0;  // back-mirror pixels that show something else with the front mirror there
  for (std::size_t i = 0; i < back->stencil.pixels.size(); ++i)
    covered += back->stencil.pixels[i] == kDone && forwards->stencil.pixels[i] == kDone &&
               differs(back->colour, forwards->colour, i);
  EXPECT_GT(covered, 800u) << "the front mirror should cover part of the back one";
  std::size_t different = 0;
  for (std::size_t i = 0; i < back->stencil.pixels.size(); ++i)
    different += differs(forwards->colour, backwards->colour, i, 0) ||
                 forwards->stencil.pixels[i] != backwards->stencil.pixels[i];
  EXPECT_EQ(different, 0u);
}

// An object straddling the mirror's plane: the reflection shows exactly what it would show
// if the object ended at the plane, so only the reflective side is reflected. Without the
// clip plane the part behind the mirror shows up in it.
TEST(StenciledMirrors, OnlyTheReflectiveSideOfAStraddlingObjectIsReflected) {
  const auto rod = runLesson(LESSON_02, "rod", "--variant straddle");
  const auto cut = runLesson(LESSON_02, "cut", "--variant straddle --set cut=1");
  const auto rodNoClip = runLesson(LESSON_02, "rod-no-clip", "--variant straddle --set clip=0");
  const auto cutNoClip = runLesson(LESSON_02, "cut-no-clip", "--variant straddle --set cut=1 --set clip=0");
  if (!rod || !cut || !rodNoClip || !cutNoClip) GTEST_SKIP() << "no GL context";
  ASSERT_GT(count(*rod, kDone), 5000u);
  const Changes clipped = changes(*rod, *cut, *rod);
  EXPECT_EQ(clipped.inMirrors, 0u) << "the part behind the mirror was reflected";
  EXPECT_GT(changes(*rodNoClip, *cutNoClip, *rodNoClip).inMirrors, 100u)
      << "the check should see the unclipped part";
}

// A mirror seen at a grazing angle: a thin strip of tagged pixels that still shows a
// reflection (and, above, no leak).
TEST(StenciledMirrors, AGrazingMirrorShowsAThinReflection) {
  const auto two = runLesson(LESSON_02, "two", "--variant grazing --set mirrors=2");
  const auto three = runLesson(LESSON_02, "three", "--variant grazing");
  const auto glass = runLesson(LESSON_02, "glass", "--variant grazing --set reflect=0");
  if (!two || !three || !glass) GTEST_SKIP() << "no GL context";
  std::size_t strip = 0, reflected = 0;
  for (std::size_t i = 0; i < three->stencil.pixels.size(); ++i) {
    if (three->stencil.pixels[i] != kDone || two->stencil.pixels[i] == kDone) continue;
    ++strip;
    reflected += differs(three->colour, glass->colour, i);
  }
  EXPECT_GT(strip, 50u);
  EXPECT_LT(strip, 3000u) << "seen almost edge-on, the mirror should be thin";
  EXPECT_GT(reflected, strip / 4);
}

// One scene rendering for the real scene and one per mirror, however little of it shows.
TEST(StenciledMirrors, OneSceneRenderingPerMirror) {
  for (int n = 0; n <= 3; ++n) {
    // std::string("n"): GCC 12 at -O3 warns falsely (-Wrestrict) on "n" + std::string.
    const auto run = runLesson(LESSON_02, std::string("n") + std::to_string(n),
                               "--set mirrors=" + std::to_string(n), true);
    if (!run) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(run->count("scene_renderings"), 1 + n);
  }
}
