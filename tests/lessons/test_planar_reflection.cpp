// Lesson 01's claims, measured: a polished floor's reflection changes only floor pixels; a
// free-standing mirror's reflection, drawn the same way, changes pixels far outside the
// mirror. The mirror pass records where the mirror's surface was drawn (stencil 1), which is
// where a reflection may show.
#include "lesson_run.h"

using namespace stencil;
using namespace stencil::testing;

namespace {

struct Changes {
  std::size_t onMirror = 0, elsewhere = 0;
};

// Pixels the reflection changed, against the same frame drawn without it.
Changes reflectionChanges(const LessonRun& with, const LessonRun& without) {
  Changes c;
  for (std::size_t i = 0; i < with.stencil.pixels.size(); ++i)
    if (differs(with.colour, without.colour, i))
      (with.stencil.pixels[i] == 1 ? c.onMirror : c.elsewhere) += 1;
  return c;
}

}  // namespace

TEST(PlanarReflection, AConstrainedMirrorKeepsItsReflection) {
  const auto with = runLesson(LESSON_01, "floor", "--variant floor");
  const auto without = runLesson(LESSON_01, "floor-off", "--variant floor --set reflect=0");
  if (!with || !without) GTEST_SKIP() << "no GL context";
  const Changes c = reflectionChanges(*with, *without);
  EXPECT_GT(c.onMirror, 1000u) << "the floor should show a reflection";
  EXPECT_EQ(c.elsewhere, 0u) << "the floor's reflection showed off the floor";
}

// The floor's record in the stencil is the whole floor whatever was reflected before it: no
// reflected surface lies in the floor's plane to win its depth test (the cone's base once did,
// leaving a spiky hole at its foot).
TEST(PlanarReflection, TheFloorsRecordHasNoHole) {
  const auto with = runLesson(LESSON_01, "floor", "--variant floor");
  const auto without = runLesson(LESSON_01, "floor-off", "--variant floor --set reflect=0");
  if (!with || !without) GTEST_SKIP() << "no GL context";
  std::size_t missing = 0, floor = 0;
  for (std::size_t i = 0; i < with->stencil.pixels.size(); ++i) {
    floor += without->stencil.pixels[i] == 1;
    missing += without->stencil.pixels[i] == 1 && with->stencil.pixels[i] != 1;
  }
  EXPECT_GT(floor, 10000u);
  EXPECT_EQ(missing, 0u) << "floor pixels the reflection kept from the floor's record";
}

TEST(PlanarReflection, AFreeStandingMirrorLeaks) {
  const auto with = runLesson(LESSON_01, "standing", "--variant free-standing");
  const auto without = runLesson(LESSON_01, "standing-off", "--variant free-standing --set reflect=0");
  if (!with || !without) GTEST_SKIP() << "no GL context";
  const Changes c = reflectionChanges(*with, *without);
  EXPECT_GT(c.onMirror, 500u);
  EXPECT_GT(c.elsewhere, 1000u) << "the unconstrained reflection should leak past the mirror's edges";
}

TEST(PlanarReflection, WithoutTheFlippedCullFaceTheReflectionTurnsInsideOut) {
  const auto right = runLesson(LESSON_01, "flip", "--variant floor");
  const auto wrong = runLesson(LESSON_01, "no-flip", "--variant floor --set flip=0");
  if (!right || !wrong) GTEST_SKIP() << "no GL context";
  std::size_t changed = 0;
  for (std::size_t i = 0; i < right->stencil.pixels.size(); ++i)
    changed += differs(right->colour, wrong->colour, i);
  EXPECT_GT(changed, 200u);
}
