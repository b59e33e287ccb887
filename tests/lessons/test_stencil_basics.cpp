// Lesson 00: what its pictures must show a class.
#include <array>

#include "gl/stencil_view.h"
#include "lesson_run.h"

using namespace stencil;
using stencil::testing::runLesson;

namespace {

float luma(const Image& image, std::size_t i) {
  return 0.2126f * image.pixels[4 * i] + 0.7152f * image.pixels[4 * i + 1] +
         0.0722f * image.pixels[4 * i + 2];
}

}  // namespace

// The keyhole shows day in its sky too: where nothing but sky is seen, the pixels the keyhole
// tags (stencil 1) are much brighter than the night sky around them.
TEST(StencilBasics, KeyholeSkyIsDay) {
  const auto keyhole = runLesson(LESSON_00, "keyhole", "--variant keyhole");
  const auto night = runLesson(LESSON_00, "night", "--variant stencil-off");  // night everywhere
  if (!keyhole || !night) GTEST_SKIP() << "no GL context";
  // Sky: the pixels where the all-night picture shows the clear colour (13, 15, 26).
  double day = 0, dark = 0, dayN = 0, darkN = 0;
  for (std::size_t i = 0; i < keyhole->stencil.pixels.size(); ++i) {
    if (std::abs(night->colour.pixels[4 * i] - 13) > 2 || std::abs(night->colour.pixels[4 * i + 2] - 26) > 2)
      continue;
    if (keyhole->stencil.pixels[i] == 1)
      day += luma(keyhole->colour, i), dayN += 1;
    else
      dark += luma(keyhole->colour, i), darkN += 1;
  }
  ASSERT_GT(dayN, 1000.0);
  ASSERT_GT(darkN, 1000.0);
  EXPECT_GT(day / dayN, 150.0) << dayN << " day sky pixels";
  EXPECT_GT(day / dayN, 5.0 * dark / darkN);
}

// One colour language: ops paints each outcome in the colour the stencil picture gives its value,
// so each outcome's pixels are nearer their own value's colour than the other outcomes'.
TEST(StencilBasics, OpsPaintsTheStencilPicturesColours) {
  const auto ops = runLesson(LESSON_00, "ops", "--variant ops");
  if (!ops) GTEST_SKIP() << "no GL context";
  const std::array<std::uint8_t, 3> values = {129, 2, 254};
  for (const std::uint8_t v : values) {
    std::array<double, 3> mean{};
    double n = 0;
    for (std::size_t i = 0; i < ops->stencil.pixels.size(); ++i)
      if (ops->stencil.pixels[i] == v) {
        for (int c = 0; c < 3; ++c) mean[c] += ops->colour.pixels[4 * i + c];
        n += 1;
      }
    ASSERT_GT(n, 100.0) << int(v);
    const std::array<std::uint8_t, 3> seen = {static_cast<std::uint8_t>(mean[0] / n),
                                              static_cast<std::uint8_t>(mean[1] / n),
                                              static_cast<std::uint8_t>(mean[2] / n)};
    for (const std::uint8_t other : values)
      if (other != v) {
        EXPECT_LT(colourDistance(seen, stencilColour(v)), colourDistance(seen, stencilColour(other)))
            << "the pixels holding " << int(v) << " look more like " << int(other);
      }
  }
}
