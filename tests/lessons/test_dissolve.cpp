// Lesson 12's claims, measured on its output: the share of pixels showing scene B is k/256 within
// 1/256 at every one of the 257 states, for every pattern and method, and no pixel ever goes back
// from B to A as k rises (the lesson's own sweep, --set measure=1); independently of that sweep,
// each pixel of a frame shows B exactly where the stencil it leaves holds a value below k, and the
// stencil's own levels give k/256 at every state; state 0 shows only A, 256 only B, and the
// reference clamped to 0 shows B on the 1/256 of pixels holding 0; each pixel passes exactly one
// scene's stencil test; the engines' two ways (draw both and mix, shade both and discard) give the
// same picture, as does extra work per fragment; the brush only ever adds to the painted mask.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lesson_run.h"

using namespace stencil;
using stencil::testing::LessonRun;

namespace {

constexpr int kPatterns = 6;  // the equalized patterns; 6 is the painted mask

std::optional<LessonRun> run(const std::string& name, const std::string& args, bool stats = false) {
  return stencil::testing::runLesson(LESSON_12, name, args, stats);
}

// Which scene a pixel of a `which` frame shows: A flat red, B flat blue (image rows top first).
bool showsB(const Image& colour, std::size_t i) {
  return colour.pixels[4 * i + 2] > 127;
}
bool showsA(const Image& colour, std::size_t i) {
  return colour.pixels[4 * i] > 127;
}

// The stencil image is top row first, as the colour image: pixel i is the same pixel in both.
std::uint64_t below(const Image& stencil, int k) {
  std::uint64_t n = 0;
  for (std::uint8_t v : stencil.pixels) n += v < k;
  return n;
}

void expectSweepExact(const LessonRun& r, const std::string& what) {
  const long long n = r.count("pixels");
  ASSERT_GT(n, 0) << what;
  EXPECT_EQ(r.count("sweep_states"), 257) << what;
  // max over k of |256 B(k) - k n|: within 1/256 of the pixels, k/256 within 1/256.
  EXPECT_LE(r.count("sweep_max_error_256ths_of_a_pixel"), n) << what;
  // Equalized patterns do better: within one pixel.
  EXPECT_LT(r.count("sweep_max_error_256ths_of_a_pixel"), 256) << what;
  EXPECT_EQ(r.count("sweep_switch_backs"), 0) << what;     // monotone: once B, B for good
  EXPECT_EQ(r.count("sweep_neither_or_both"), 0) << what;  // every pixel one scene, every state
  EXPECT_EQ(r.count("sweep_b_at_start"), 0) << what;       // t = 0: only A
  EXPECT_EQ(r.count("sweep_a_at_end"), 0) << what;         // t = 1: only B
}

}  // namespace

TEST(Dissolve, ShareOfBIsKOver256AtEveryStateForEveryPattern) {
  for (int p = 0; p < kPatterns; ++p)
    for (const char* size :
         {"320x240", "317x239"}) {  // 256 divides the first's pixel count, not the second's
      const std::string what = "pattern " + std::to_string(p) + " at " + size;
      const auto r =
          run("sweep",
              "--variant blue-noise --set measure=1 --set pattern=" + std::to_string(p) + " --size " + size,
              true);
      if (!r) GTEST_SKIP() << "no GL context";
      expectSweepExact(*r, what);
    }
}

TEST(Dissolve, ShareOfBIsKOver256AtEveryStateForEveryMethod) {
  for (const char* method : {"1", "2"})
    for (const char* pattern : {"0", "2", "4"}) {
      const std::string what = std::string("method ") + method + " pattern " + pattern;
      const auto r = run("sweep",
                         std::string("--variant blue-noise --set measure=1 --set method=") + method +
                             " --set pattern=" + pattern,
                         true);
      if (!r) GTEST_SKIP() << "no GL context";
      expectSweepExact(*r, what);
    }
}

TEST(Dissolve, CellsKeepTheShareWithin1Over256) {
  // A pattern held over cell x cell blocks is exact in cells: within one cell (cell^2 pixels) of
  // k n / 256, less than n / 256 here; and still monotone.
  for (const char* cell : {"2", "4", "8"}) {
    const auto r =
        run("cells", std::string("--variant blue-noise-cells --set measure=1 --set cell=") + cell, true);
    if (!r) GTEST_SKIP() << "no GL context";
    const long long n = r->count("pixels"), c = std::stoll(cell);
    EXPECT_LE(r->count("sweep_max_error_256ths_of_a_pixel"), 256 * c * c) << "cell " << cell;
    EXPECT_LE(r->count("sweep_max_error_256ths_of_a_pixel"), n) << "cell " << cell;
    EXPECT_EQ(r->count("sweep_switch_backs"), 0) << "cell " << cell;
    EXPECT_EQ(r->count("sweep_neither_or_both"), 0) << "cell " << cell;
    EXPECT_EQ(r->count("sweep_b_at_start") + r->count("sweep_a_at_end"), 0) << "cell " << cell;
  }
}

TEST(Dissolve, EachPixelShowsBWhereItsStencilIsBelowK) {
  // Not the lesson's sweep: the frame as written and the stencil it leaves, compared per pixel.
  for (int p = 0; p < kPatterns; ++p)
    for (const int k : {0, 1, 77, 128, 200, 255, 256}) {
      const std::string what = "pattern " + std::to_string(p) + " k " + std::to_string(k);
      const auto r = run("which", "--variant which-scene --set pattern=" + std::to_string(p) +
                                      " --set step=" + std::to_string(k));
      if (!r) GTEST_SKIP() << "no GL context";
      std::size_t wrong = 0;
      for (std::size_t i = 0; i < r->stencil.pixels.size(); ++i)
        wrong += showsB(r->colour, i) != (r->stencil.pixels[i] < k) ||
                 showsA(r->colour, i) == showsB(r->colour, i);
      EXPECT_EQ(wrong, 0u) << what;
      if (k == 128) {
        // The stencil's own levels: k/256 of the pixels below k within one pixel, at every state.
        const std::uint64_t n = r->stencil.pixels.size();
        for (int s = 0; s <= 256; ++s) {
          const std::int64_t error =
              256 * static_cast<std::int64_t>(below(r->stencil, s)) - s * static_cast<std::int64_t>(n);
          EXPECT_GE(error, 0) << what << " state " << s;
          EXPECT_LT(error, 256) << what << " state " << s;
        }
      }
    }
}

TEST(Dissolve, ExactEndsAndTheClampedReference) {
  const auto start = run("start", "--variant start --set which=1");
  if (!start) GTEST_SKIP() << "no GL context";
  const auto end = run("end", "--variant end --set which=1");
  const auto clamped = run("clamped", "--variant start-clamped");
  std::size_t bAtStart = 0, aAtEnd = 0, bClamped = 0, zeros = 0, wrong = 0;
  for (std::size_t i = 0; i < start->stencil.pixels.size(); ++i) {
    bAtStart += showsB(start->colour, i);
    aAtEnd += showsA(end->colour, i);
    bClamped += showsB(clamped->colour, i);
    zeros += clamped->stencil.pixels[i] == 0;
    wrong += showsB(clamped->colour, i) != (clamped->stencil.pixels[i] == 0);
  }
  EXPECT_EQ(bAtStart, 0u);
  EXPECT_EQ(aAtEnd, 0u);
  // The reference -1 clamps to 0: GEQUAL 0 passes where the stencil is 0, 1/256 of the pixels.
  EXPECT_EQ(bClamped, zeros);
  EXPECT_EQ(zeros, start->stencil.pixels.size() / 256);
  EXPECT_EQ(wrong, 0u);
}

TEST(Dissolve, EachPixelPassesExactlyOneScenesTest) {
  // Occlusion queries on a full-screen quad under each scene's stencil test: the two counts add up
  // to the pixels, and B's is k n / 256 (256 divides 320 x 240), at states through the range.
  for (const int k : {0, 1, 64, 128, 255, 256}) {
    const auto r =
        run("counts", "--variant blue-noise --set measure=1 --set step=" + std::to_string(k), true);
    if (!r) GTEST_SKIP() << "no GL context";
    const long long n = r->count("pixels");
    EXPECT_EQ(r->count("a_pixels") + r->count("b_pixels"), n) << "k " << k;
    EXPECT_EQ(r->count("b_pixels") * 256, k * n) << "k " << k;
  }
}

TEST(Dissolve, OnlyTheShownSceneIsDrawnPerPixel) {
  // The fragments that pass the depth and stencil tests: with the stencil, those of the scene each
  // pixel shows; drawing both whole and mixing passes every fragment of both and the mix's own.
  // At state 0 the stencil frame is scene A alone, at 256 scene B alone, and half way it lies
  // between them; mixing passes A's and B's and one per pixel more, at every state.
  const auto stencilAt = [&](int k) {
    const auto r =
        run("stencil", "--variant blue-noise --set measure=1 --set step=" + std::to_string(k), true);
    return r ? r->count("samples_passed") : -1;
  };
  const long long a = stencilAt(0);
  if (a < 0) GTEST_SKIP() << "no GL context";
  const long long b = stencilAt(256), half = stencilAt(128);
  const auto mixed = run("mix", "--variant mix --set measure=1", true);
  EXPECT_GT(half, std::min(a, b));
  EXPECT_LT(half, std::max(a, b));
  EXPECT_NEAR(static_cast<double>(half), 0.5 * static_cast<double>(a + b), 0.02 * static_cast<double>(a + b));
  EXPECT_EQ(mixed->count("samples_passed"), a + b + mixed->count("pixels"));
}

TEST(Dissolve, TheEnginesWaysGiveTheSamePicture) {
  for (const char* pattern : {"0", "1", "2", "3", "5"}) {
    const std::string set = std::string(" --set step=128 --set pattern=") + pattern;
    const auto stencil = run("stencil", "--variant blue-noise" + set);
    if (!stencil) GTEST_SKIP() << "no GL context";
    // The other methods, and the stencil's with extra work per fragment (the timing's stand-in for
    // costly shading, which must not change a pixel).
    for (const char* method : {"mix", "discard", "blue-noise --set work=16"}) {
      const auto other = run("other", std::string("--variant ") + method + set);
      std::size_t differ = 0;
      for (std::size_t i = 0; i < stencil->stencil.pixels.size(); ++i)
        differ += stencil::testing::differs(stencil->colour, other->colour, i);
      EXPECT_EQ(differ, 0u) << method << " pattern " << pattern;
    }
  }
}

TEST(Dissolve, TheBrushOnlyAdds) {
  // The painted mask: 255 (A) and the brush's 0 (B from state 1) and nothing else; the stroke at
  // 0.5 s (following time) is inside the variant's own stroke of 1 s, which it shows at t = 0
  // too; half way, B shows exactly where the brush went.
  const auto early = run("early", "--set pattern=6 --set step=128 --set which=1 --time 0.5");
  if (!early) GTEST_SKIP() << "no GL context";
  const auto late = run("late", "--variant painted --set which=1 --time 0");
  const auto later = run("later", "--variant painted --set which=1 --time 1");
  EXPECT_EQ(late->stencil.pixels, later->stencil.pixels);  // the variant's stroke ignores time
  std::size_t other = 0, lost = 0, earlyPainted = 0, latePainted = 0, wrong = 0;
  for (std::size_t i = 0; i < late->stencil.pixels.size(); ++i) {
    const std::uint8_t e = early->stencil.pixels[i], l = late->stencil.pixels[i];
    other += (e != 0 && e != 255) + (l != 0 && l != 255);
    lost += e == 0 && l != 0;
    earlyPainted += e == 0, latePainted += l == 0;
    wrong += showsB(late->colour, i) != (l == 0);
  }
  EXPECT_EQ(other, 0u);
  EXPECT_EQ(lost, 0u);
  EXPECT_GT(earlyPainted, 0u);
  EXPECT_GT(latePainted, earlyPainted);
  EXPECT_EQ(wrong, 0u);
}
