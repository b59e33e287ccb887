// The stencil inspector's pictures.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "gl/stencil_view.h"

using namespace stencil;

TEST(StencilView, ZeroIsBlackAndSmallValuesAreDistinct) {
  EXPECT_EQ(stencilColour(0), (std::array<std::uint8_t, 3>{0, 0, 0}));
  std::set<std::array<std::uint8_t, 3>> seen;
  for (int v = 0; v <= 255; ++v) seen.insert(stencilColour(static_cast<std::uint8_t>(v)));
  EXPECT_EQ(seen.size(), 256u);  // every value has its own colour
}

// Neighbouring values, and every value and 0, look different at a glance (lesson 08's 13..20 and
// lesson 09's floor tag 128 and its shadow 129 once shared one navy).
TEST(StencilView, NeighbouringValuesAreDistinct) {
  for (int v = 1; v < 256; ++v) {
    const auto c = stencilColour(static_cast<std::uint8_t>(v));
    EXPECT_GE(colourDistance(c, stencilColour(0)), kStencilDistinct) << v << " and 0";
    if (v < 255) {
      EXPECT_GE(colourDistance(c, stencilColour(static_cast<std::uint8_t>(v + 1))), kStencilDistinct)
          << v << " and " << v + 1;
    }
  }
}

// Every value a picture holds has a colour kStencilDistinct from every other value it holds, for
// any 24 values or fewer; with no clash each keeps its own colour.
TEST(StencilView, EveryPresentValueIsDistinctFromEveryOther) {
  const auto check = [](const std::vector<int>& values) {
    std::vector<std::uint64_t> histogram(256, 0);
    for (std::size_t i = 0; i < values.size(); ++i) histogram[static_cast<std::size_t>(values[i])] += 100 + i;
    const auto colours = stencilPictureColours(histogram);
    float least = 1e9f;
    for (const int a : values)
      for (const int b : values)
        if (a < b)
          least = std::min(least, colourDistance(colours[static_cast<std::size_t>(a)],
                                                 colours[static_cast<std::size_t>(b)]));
    return least;
  };
  EXPECT_GE(check({0, 13, 14, 15, 16, 17, 18, 19, 20}), kStencilDistinct);
  EXPECT_GE(check({0, 128, 129}), kStencilDistinct);
  std::mt19937 random(18);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<int> all(256);
    std::iota(all.begin(), all.end(), 0);
    std::shuffle(all.begin(), all.end(), random);
    const auto n = static_cast<std::size_t>(2 + trial % 23);
    const std::vector<int> values(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n));
    ASSERT_GE(check(values), kStencilDistinct) << n << " values, trial " << trial;
  }
  // Lesson 00's ops values keep their own colours, the ones the lesson paints them in.
  std::vector<std::uint64_t> ops(256, 0);
  ops[0] = 1000, ops[2] = 300, ops[129] = 5000, ops[254] = 700;
  const auto colours = stencilPictureColours(ops);
  for (const int v : {0, 2, 129, 254})
    EXPECT_EQ(colours[static_cast<std::size_t>(v)], stencilColour(static_cast<std::uint8_t>(v))) << v;
}

// A count wrapped below zero fills a picture with 21 values, 235..255: on a projector the pairs
// the classroom trials could not tell apart at 25 (246 and 251, 237 and 243, 249 and 252), and
// every other pair, are 35 apart, the distance that read apart there.
TEST(StencilView, WrappedCountsReadApartOnAProjector) {
  constexpr float kProjector = 35.0f;
  EXPECT_GE(kStencilDistinct, kProjector);
  std::vector<std::uint64_t> histogram(256, 0);
  for (int v = 235; v <= 255; ++v) histogram[static_cast<std::size_t>(v)] = 100 + static_cast<std::uint64_t>(v * 37 % 200);
  const auto colours = stencilPictureColours(histogram);
  const auto apart = [&](int a, int b) {
    return colourDistance(colours[static_cast<std::size_t>(a)], colours[static_cast<std::size_t>(b)]);
  };
  EXPECT_GE(apart(246, 251), kProjector);
  EXPECT_GE(apart(237, 243), kProjector);
  EXPECT_GE(apart(249, 252), kProjector);
  for (int a = 235; a <= 255; ++a)
    for (int b = a + 1; b <= 255; ++b) EXPECT_GE(apart(a, b), kProjector) << a << " and " << b;
}

// The legend gives each value's pixel count, and a value a few pixels hold is ringed in its colour.
TEST(StencilView, RareValuesAreRingedAndCounted) {
  Image s(40, 30, 1);
  std::fill(s.pixels.begin(), s.pixels.end(), std::uint8_t{1});
  *s.at(20, 15) = 129;
  const Image pic = stencilRamp(s);
  const auto c = stencilColour(129);
  const auto at = [&](int x, int y) {
    return std::array<std::uint8_t, 3>{pic.at(x, y)[0], pic.at(x, y)[1], pic.at(x, y)[2]};
  };
  EXPECT_EQ(at(20, 15), c);
  EXPECT_EQ(at(24, 15), c);  // the ring, 4 pixels out
  EXPECT_EQ(at(20, 11), c);
  EXPECT_EQ(at(22, 15), stencilColour(1));  // inside the ring: the value around it
  EXPECT_EQ(at(10, 5), stencilColour(1));
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

// The swatches along the legend's first row of entries, in order: the colours met along the row
// through their middle that are none of the band's own (its grey, the swatches' outline, the
// digits' white and the counts' grey).
std::vector<std::array<std::uint8_t, 3>> firstRowSwatches(const Image& pic, int pictureHeight) {
  const int y = pictureHeight + 4 + 5;  // legendScale 1: entries 4 px into the band, swatches 10 px high
  std::vector<std::array<std::uint8_t, 3>> out;
  for (int x = 0; x < pic.width; ++x) {
    const std::array<std::uint8_t, 3> c{pic.at(x, y)[0], pic.at(x, y)[1], pic.at(x, y)[2]};
    const bool band = c[0] == c[1] && c[1] == c[2] && (c[0] == 48 || c[0] == 200 || c[0] == 255 || c[0] == 170);
    const bool starts = x == 0 || !std::equal(c.begin(), c.end(), pic.at(x - 1, y));
    if (!band && starts) out.push_back(c);
  }
  return out;
}

// A legend limited to its rows keeps the lowest values, none skipped, however rare they are: here
// the higher a value the more pixels hold it, and the legend still starts 0, 1, 2.
TEST(StencilView, ALimitedLegendKeepsTheLowestValuesInValueOrder) {
  std::vector<std::uint8_t> values;
  for (int v = 0; v < 40; ++v)
    values.insert(values.end(), static_cast<std::size_t>(10 + 5 * v), static_cast<std::uint8_t>(v));
  Image s(430, static_cast<int>(values.size()) / 430, 1);  // 4300 pixels: a row of entries holds six
  std::copy_n(values.begin(), s.pixels.size(), s.pixels.begin());
  const Image pic = stencilRamp(s, {.maxLegendRows = 1});
  std::vector<std::uint64_t> histogram(256, 0);
  for (std::uint8_t v : s.pixels) ++histogram[v];
  const auto colours = stencilPictureColours(histogram);
  const auto swatches = firstRowSwatches(pic, s.height);
  ASSERT_GE(swatches.size(), 3u);
  EXPECT_EQ(swatches[0], colours[0]);
  EXPECT_EQ(swatches[1], colours[1]);
  EXPECT_EQ(swatches[2], colours[2]);
}

// The grey view: the values present stretched so that the largest is white (v x 255 / 4 here,
// rounded: counts of 1 to 4 would be black to the eye as grey levels 1 to 4), no rings, and a
// legend naming the values.
TEST(StencilView, GreyPictureStretchesTheValuesToWhiteAndNamesThemInItsLegend) {
  Image s(700, 40, 1);  // wide enough for the rule and the five entries in one row
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 700; ++x) *s.at(x, y) = static_cast<std::uint8_t>(x < 300 ? 0 : y < 10 ? 1 : y < 20 ? 2 : 3);
  *s.at(10, 20) = 4;  // a rare value: no ring in the grey view
  const Image pic = stencilRamp(s, {.grey = true});
  ASSERT_GT(pic.height, s.height);
  const std::array<int, 5> level = {0, 64, 128, 191, 255};  // (v x 255 + 2) / 4
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) ASSERT_EQ(pic.at(x, y)[0], level[*s.at(x, y)]) << x << "," << y;
  const auto swatches = firstRowSwatches(pic, s.height);
  // 4's swatch, white, reads as the legend's white digits to firstRowSwatches.
  const std::vector<std::array<std::uint8_t, 3>> want = {{0, 0, 0}, {64, 64, 64}, {128, 128, 128}, {191, 191, 191}};
  EXPECT_EQ(swatches, want);
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

// Each tile's label is 1/64 of the tile wide a dot, times the label scale (the window's UI scale):
// its red box is 7 dots high.
TEST(StencilView, BitPlaneLabelsGrowWithTheLabelScale) {
  const int n = 256;
  const Image s(n, n, 1);
  for (const float labelScale : {1.0f, 2.0f, 3.0f}) {
    const Image pic = stencilBitPlanes(s, labelScale);
    int redRows = 0;
    for (int y = 0; y < n; ++y) {
      bool red = false;
      for (int x = 0; x < n; ++x) {
        const std::uint8_t* p = pic.at(x, y);
        red = red || (p[0] == 200 && p[1] == 40 && p[2] == 40);
      }
      redRows += red;
    }
    EXPECT_EQ(redRows, 7 * static_cast<int>(4 * labelScale)) << labelScale;
  }
}

// Lesson 13's count colours: a larger count always looks brighter, for any top, and adjacent
// counts stay apart while the ramp is short (the GLUT demo's map showed 3 brighter than 4 and
// everything from 8 up white).
TEST(CountView, LuminanceRisesWithTheCountForAnyTop) {
  for (int top : {1, 2, 3, 7, 8, 16, 100, 254}) {
    EXPECT_EQ(countColour(0, top), (std::array<std::uint8_t, 3>{0, 0, 0}));
    for (int k = 1; k <= top; ++k)
      EXPECT_GT(luminance(countColour(k, top)), luminance(countColour(k - 1, top))) << k << " of " << top;
    EXPECT_EQ(countColour(top + 5, top), countColour(top, top));  // past top: top's colour
  }
  // 1..16 over five segments, three steps each; the flattest segment rises 27.5 levels of
  // luminance (about 31 to 59), 9.2 a step, less up to one level for rounding to bytes.
  for (int k = 1; k <= 16; ++k)
    EXPECT_GE(luminance(countColour(k, 16)) - luminance(countColour(k - 1, 16)), 8.0f) << k;
}

TEST(CountView, SaturatedIsOffTheRamp) {
  const auto cyan = saturatedCountColour();
  for (int top : {1, 8, 254})
    for (int k = 0; k <= top; ++k) {
      const auto c = countColour(k, top);
      EXPECT_NE(c, cyan);
      if (k > 0) {
        EXPECT_GE(c[0], 40);  // every count above 0 has red in it; cyan has none
      }
    }
  EXPECT_EQ(cyan[0], 0);
}

TEST(CountView, PictureColoursEachCountAndTheLegendShowsTheHistogram) {
  Image s(64, 8, 1);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 64; ++x) *s.at(x, y) = static_cast<std::uint8_t>(x < 16 ? 0 : x < 48 ? 3 : 255);
  const Image saturating = countPicture(s, true);
  EXPECT_EQ(saturating.width, 64);
  EXPECT_GT(saturating.height, 8);
  const auto pixel = [](const Image& img, int x, int y) {
    return std::array<std::uint8_t, 3>{img.at(x, y)[0], img.at(x, y)[1], img.at(x, y)[2]};
  };
  EXPECT_EQ(pixel(saturating, 20, 3), countColour(3, 3));  // top is 3: 255 is saturated, not a count
  EXPECT_EQ(pixel(saturating, 60, 3), saturatedCountColour());
  EXPECT_EQ(pixel(saturating, 2, 3), (std::array<std::uint8_t, 3>{0, 0, 0}));
  // Wrapping: 255 is a count like any other, the top of the ramp.
  const Image wrapping = countPicture(s, false);
  EXPECT_EQ(pixel(wrapping, 60, 3), countColour(255, 255));
  EXPECT_EQ(pixel(wrapping, 20, 3), countColour(3, 255));

  // The legend: count 3's bar (32 pixels) stands taller than count 1's (none) and as tall as the
  // tallest; the saturated column is drawn only when asked for.
  std::vector<std::uint64_t> histogram(256, 0);
  histogram[0] = 16, histogram[3] = 32, histogram[255] = 16;
  const auto barHeight = [&](const Image& legend, int column, int top) {
    const auto colour = countColour(column, top);
    int height = 0;
    for (int y = 0; y < legend.height; ++y)
      for (int x = 0; x < legend.width; ++x)
        if (pixel(legend, x, y) == colour) {
          int h = 0;
          while (y + h < legend.height && pixel(legend, x, y + h) == colour) ++h;
          height = std::max(height, h);
          break;
        }
    return height;
  };
  const Image legend = countLegend(histogram, 3, true, 200);
  EXPECT_GT(barHeight(legend, 3, 3), barHeight(legend, 1, 3));
  bool cyanSeen = false;
  for (std::size_t i = 0; i + 3 < legend.pixels.size(); i += 4)
    cyanSeen |= std::array<std::uint8_t, 3>{legend.pixels[i], legend.pixels[i + 1], legend.pixels[i + 2]} ==
                saturatedCountColour();
  EXPECT_TRUE(cyanSeen);
  const Image plain = countLegend(histogram, 3, false, 200);
  bool cyanInPlain = false;
  for (std::size_t i = 0; i + 3 < plain.pixels.size(); i += 4)
    cyanInPlain |= std::array<std::uint8_t, 3>{plain.pixels[i], plain.pixels[i + 1], plain.pixels[i + 2]} ==
                   saturatedCountColour();
  EXPECT_FALSE(cyanInPlain);
}

TEST(ShadowHoursView, LegendLabelsAreExactHoursAndMinutes) {
  EXPECT_EQ(hoursAndMinutes(0), "0h");
  EXPECT_EQ(hoursAndMinutes(180), "3h");
  EXPECT_EQ(hoursAndMinutes(20), "0h20");  // a twenty-minute step, not "0.3h"
  EXPECT_EQ(hoursAndMinutes(80), "1h20");
  EXPECT_EQ(hoursAndMinutes(65), "1h05");
  EXPECT_EQ(hoursAndMinutes(1440), "24h");
}
