// Lesson 03's claims, measured: the number of scene renderings (--stats "counts") against
// the paper's worst case and against what is visible, culling that never changes a pixel,
// a mirror seen only through another, and the far plane. The final stencil holds i + 1 on
// the visible pixels of top-level mirror i, 0 elsewhere.
#include "lesson_run.h"

using namespace stencil;
using namespace stencil::testing;

namespace {

// Kilgard, section 3: n mirrors that all see each other, r bounces, no mirror reflecting
// itself: 1 + n * sum_{i=1..r} (n-1)^(i-1). Written out here, independently of the lesson.
long long worstCase(long long n, int r) {
  long long total = 1, power = 1;
  for (int i = 1; i <= r; ++i, power *= n - 1) total += n * power;
  return total;
}

std::size_t pixelsDiffering(const LessonRun& a, const LessonRun& b, int tolerance = 0) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.stencil.pixels.size(); ++i)
    n += differs(a.colour, b.colour, i, tolerance) || a.stencil.pixels[i] != b.stencil.pixels[i];
  return n;
}

}  // namespace

// Without culling every mirror is re-rendered inside every other one: the worst case.
TEST(RecursiveMirrors, WithoutCullingTheCountIsThePapersWorstCase) {
  EXPECT_EQ(worstCase(3, 2), 10);  // the paper's own examples
  EXPECT_EQ(worstCase(5, 4), 426);
  for (const auto& [n, r] : {std::pair{3, 2}, std::pair{5, 4}, std::pair{2, 8}, std::pair{4, 3}}) {
    const std::string args = "--variant hall --set culling=0 --set mirrors=" + std::to_string(n) +
                             " --set depth=" + std::to_string(r);
    // std::string("n"): GCC 12 at -O3 warns falsely (-Wrestrict) on "n" + std::string.
    const auto run =
        runLesson(LESSON_03, std::string("n") + std::to_string(n) + "r" + std::to_string(r), args, true);
    if (!run) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(run->count("scene_renderings"), worstCase(n, r)) << args;
  }
}

// The hall: the eye between two parallel mirrors, facing one. The mirror behind the viewer
// is outside the camera's frustum, so culling drops it and everything seen in it; the one in
// front shows one more reflection per bounce (each of which sees only the other mirror). So
// exactly 1 + r renderings, where the worst case is 1 + 2r; and not one pixel changes.
TEST(RecursiveMirrors, CullingKeepsOnlyWhatIsVisibleInTheHall) {
  for (int r : {1, 2, 5, 8}) {
    const std::string depth = " --set depth=" + std::to_string(r);
    const auto culled = runLesson(LESSON_03, "culled" + std::to_string(r), "--variant hall" + depth, true);
    const auto all =
        runLesson(LESSON_03, "all" + std::to_string(r), "--variant hall --set culling=0" + depth, true);
    if (!culled || !all) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(all->count("scene_renderings"), worstCase(2, r));
    EXPECT_EQ(culled->count("scene_renderings"), 1 + r);
    EXPECT_EQ(pixelsDiffering(*culled, *all), 0u) << "culling changed the picture at depth " << r;
  }
}

// Three and five mirrors that see each other: culling renders fewer scenes than the worst
// case and draws the same picture.
TEST(RecursiveMirrors, CullingFallsBelowTheWorstCaseWithoutChangingThePicture) {
  for (const auto& [n, r] : {std::pair{3, 4}, std::pair{5, 3}}) {
    const std::string args =
        "--variant three-mirrors --set mirrors=" + std::to_string(n) + " --set depth=" + std::to_string(r);
    const auto culled = runLesson(LESSON_03, "culled" + std::to_string(n), args, true);
    const auto all = runLesson(LESSON_03, "all" + std::to_string(n), args + " --set culling=0", true);
    if (!culled || !all) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(all->count("scene_renderings"), worstCase(n, r));
    EXPECT_LT(culled->count("scene_renderings"), worstCase(n, r) / 2) << args;
    EXPECT_GT(culled->count("scene_renderings"), r) << args;
    EXPECT_EQ(pixelsDiffering(*culled, *all), 0u) << args;
  }
}

// The mirror behind the viewer is not visible itself (no pixel of it at the top level), yet
// with two bounces its reflection shows inside the front mirror: culling must test it
// against the frustum through the front mirror, not against the camera's.
TEST(RecursiveMirrors, AMirrorSeenOnlyThroughAnotherIsReflected) {
  const auto one = runLesson(LESSON_03, "one", "--variant hall --set depth=1");
  const auto two = runLesson(LESSON_03, "two", "--variant hall --set depth=2");
  if (!one || !two) GTEST_SKIP() << "no GL context";
  std::size_t front = 0, back = 0, changed = 0;
  for (std::size_t i = 0; i < two->stencil.pixels.size(); ++i) {
    front += two->stencil.pixels[i] == 1;
    back += two->stencil.pixels[i] == 2;
    changed += two->stencil.pixels[i] == 1 && differs(one->colour, two->colour, i);
  }
  EXPECT_GT(front, 20000u);
  EXPECT_EQ(back, 0u) << "the back mirror should not be visible directly";
  EXPECT_GT(changed, 2000u) << "its reflection should appear inside the front mirror";
}

// The deepest reflections of the hall lie beyond the camera's far plane: with the far plane
// moved out they are drawn, with the camera's they are cut off (the sky shows instead).
TEST(RecursiveMirrors, TheFarPlaneReachesTheDeepestReflection) {
  const auto moved = runLesson(LESSON_03, "moved", "--variant hall");
  const auto camera = runLesson(LESSON_03, "camera", "--variant far-plane");
  const auto shallow = runLesson(LESSON_03, "shallow", "--variant hall --set depth=3");
  const auto shallowCamera = runLesson(LESSON_03, "shallow-camera", "--variant far-plane --set depth=3");
  if (!moved || !camera || !shallow || !shallowCamera) GTEST_SKIP() << "no GL context";
  EXPECT_GT(pixelsDiffering(*moved, *camera, 5), 100u);
  EXPECT_EQ(pixelsDiffering(*shallow, *shallowCamera, 5), 0u)
      << "shallow reflections fit the camera's far plane";
}

// Each reflection turns windings over: without flipping the cull face, odd levels show the
// insides of the objects.
TEST(RecursiveMirrors, TheCullFaceFlipsWithEachReflection) {
  const auto right = runLesson(LESSON_03, "flip", "--variant hall --set depth=2");
  const auto wrong = runLesson(LESSON_03, "no-flip", "--variant hall --set depth=2 --set flip=0");
  if (!right || !wrong) GTEST_SKIP() << "no GL context";
  EXPECT_GT(pixelsDiffering(*right, *wrong, 5), 500u);
}
