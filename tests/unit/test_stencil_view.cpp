// The stencil inspector's pictures.
#include <gtest/gtest.h>

#include <set>

#include "gl/stencil_view.h"

using namespace stencil;

TEST(StencilView, ZeroIsBlackAndSmallValuesAreDistinct) {
  EXPECT_EQ(stencilColour(0), (std::array<std::uint8_t, 3>{0, 0, 0}));
  std::set<std::array<std::uint8_t, 3>> seen;
  for (int v = 0; v <= 255; ++v) seen.insert(stencilColour(static_cast<std::uint8_t>(v)));
  EXPECT_EQ(seen.size(), 256u);  // every value has its own colour
}

TEST(StencilView, RampShowsEachPixelsColourAndAddsALegendBand) {
  Image s(20, 10, 1);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) *s.at(x, y) = x < 10 ? 0 : 7;
  const Image pic = stencilRamp(s);
  EXPECT_EQ(pic.width, 20);
  EXPECT_GT(pic.height, 10);  // legend below
  const auto c7 = stencilColour(7);
  EXPECT_EQ(pic.at(15, 5)[0], c7[0]);
  EXPECT_EQ(pic.at(15, 5)[1], c7[1]);
  EXPECT_EQ(pic.at(15, 5)[2], c7[2]);
  EXPECT_EQ(pic.at(2, 5)[0], 0);
}

TEST(StencilView, BitPlanesShowEachBitInItsTile) {
  const int n = 32;  // tiles large enough that the label leaves the bottom-right corner clear
  Image s(n, n, 1);
  std::fill(s.pixels.begin(), s.pixels.end(), std::uint8_t{0b1000'0101});  // bits 0, 2, 7
  const Image pic = stencilBitPlanes(s);
  const int gap = 2;
  ASSERT_EQ(pic.width, 4 * n + 3 * gap);
  ASSERT_EQ(pic.height, 2 * n + gap);
  for (int bit = 0; bit < 8; ++bit) {
    // Bottom-right pixel of each tile, clear of the label in the top-left corner.
    const int x = (bit % 4) * (n + gap) + n - 1, y = (bit / 4) * (n + gap) + n - 1;
    const bool set = bit == 0 || bit == 2 || bit == 7;
    EXPECT_EQ(pic.at(x, y)[0], set ? 255 : 0) << "bit " << bit;
  }
}
