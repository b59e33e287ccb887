// Lesson 04's claim, measured: with the stencil, every shadowed ground pixel is darkened
// exactly once (no double blending) and nothing else changes; without it, some pixels are
// darkened more than once, so the check below does catch double blending.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "gl/image.h"

using namespace stencil;

namespace {

struct Render {
  Image colour, stencil;
};

// Runs the lesson headless at the golden size and time; skips the test without a context.
// Each test writes into its own folder: ctest runs the tests of this file in parallel.
std::optional<Render> render(const std::string& name, const std::string& args) {
  const std::filesystem::path kOut = std::filesystem::temp_directory_path() / "stencil-lesson-04" /
                                     ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto colour = kOut / (name + ".png"), stencil = kOut / (name + "-stencil.png");
  const std::string command = std::string(LESSON_04) + " --headless --quiet --size 320x240 --time 1 " + args +
                              " --out " + colour.string() + " --stencil-out " + stencil.string();
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  EXPECT_EQ(status, 0) << command;
  return Render{readPng(colour, 4), readPng(kOut / (name + "-stencil.raw.png"), 1)};
}

// Pixels the stencil recipe shadowed: ground tagged (1) without the shadow, cleared (0) with it.
std::vector<bool> shadowedPixels(const Render& withShadow, const Render& without) {
  std::vector<bool> shadowed(without.stencil.pixels.size());
  for (size_t i = 0; i < shadowed.size(); ++i)
    shadowed[i] = without.stencil.pixels[i] == 1 && withShadow.stencil.pixels[i] == 0;
  return shadowed;
}

// Blending black at alpha 0.5 once halves each channel (up to rounding).
bool singleBlend(int lit, int shadowed) {
  return std::abs(2 * shadowed - lit) <= 2;
}

}  // namespace

TEST(ProjectedShadows, StencilDarkensEachShadowedGroundPixelExactlyOnce) {
  const auto reference = render("reference", "--variant stencil --set shadow=0");
  const auto shadowedRun = render("stencil", "--variant stencil");
  if (!reference || !shadowedRun) GTEST_SKIP() << "no GL context";
  const std::vector<bool> shadowed = shadowedPixels(*shadowedRun, *reference);

  size_t count = 0, wrong = 0, changedElsewhere = 0;
  for (size_t i = 0; i < shadowed.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const int lit = reference->colour.pixels[4 * i + c], now = shadowedRun->colour.pixels[4 * i + c];
      if (shadowed[i])
        wrong += !singleBlend(lit, now);
      else
        changedElsewhere += lit != now;
    }
  for (bool s : shadowed) count += s;
  // Guards against a vacuous pass: at t = 1 the shadow covers about 1560 pixels.
  EXPECT_GT(count, 1000u) << "the shadow should cover a good part of the ground";
  EXPECT_EQ(wrong, 0u) << "shadowed channels not darkened exactly once";
  EXPECT_EQ(changedElsewhere, 0u) << "channels changed outside the shadowed ground";
}

TEST(ProjectedShadows, WithoutStencilTheOverlapIsDarkenedTwice) {
  const auto reference = render("reference", "--variant stencil --set shadow=0");
  const auto stencilRun = render("stencil", "--variant stencil");
  const auto naive = render("double", "--variant double-blending");
  if (!reference || !stencilRun || !naive) GTEST_SKIP() << "no GL context";
  const std::vector<bool> shadowed = shadowedPixels(*stencilRun, *reference);

  size_t darker = 0;
  for (size_t i = 0; i < shadowed.size(); ++i) {
    const int lit = reference->colour.pixels[4 * i], now = naive->colour.pixels[4 * i];
    // Two blends leave a quarter; anything clearly below a half was blended more than once.
    if (shadowed[i] && 2 * now < lit - 8) ++darker;
  }
  EXPECT_GT(darker, 100u) << "the double-blending variant should show its blotch";
}
