// The depth view: window depths back to eye depths, and the picture made of them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "geometry/projection.h"
#include "gl/stencil_view.h"

using namespace stencil;

namespace {

// The window depth a point at eye depth `d` on the view axis gets: GL's mapping 0.5 + 0.5 z/w,
// or z/w for a reversed projection (clip control's zero-to-one range).
float windowDepth(const glm::mat4& projection, float d, bool reversed) {
  const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -d, 1.0f);
  return reversed ? clip.z / clip.w : 0.5f + 0.5f * clip.z / clip.w;
}

// A 4 x 2 depth buffer: eye depths 2, 4, 8 and 16 along the top row, cleared along the bottom.
std::vector<float> scene(const glm::mat4& projection, bool reversed) {
  std::vector<float> depth;
  for (float d : {2.0f, 4.0f, 8.0f, 16.0f}) depth.push_back(windowDepth(projection, d, reversed));
  for (int i = 0; i < 4; ++i) depth.push_back(reversed ? 0.0f : 1.0f);
  return depth;
}

const glm::mat4 kFinite = glm::perspective(glm::radians(50.0f), 4.0f / 3.0f, 0.5f, 40.0f);
const glm::mat4 kInfinite = glm::infinitePerspective(glm::radians(50.0f), 4.0f / 3.0f, 0.5f);

}  // namespace

TEST(DepthView, EyeDepthUndoesTheProjection) {
  for (const glm::mat4& p : {kFinite, kInfinite, glm::ortho(-2.0f, 2.0f, -1.5f, 1.5f, 1.0f, 30.0f)})
    for (float d : {1.0f, 3.0f, 9.5f, 25.0f}) {
      EXPECT_NEAR(eyeDepth(windowDepth(p, d, false), p, false), d, 1e-3f * d) << d;
      EXPECT_NEAR(eyeDepth(windowDepth(reversedDepth(p), d, true), p, true), d, 1e-3f * d) << d;
    }
  // The infinite far plane is at infinity, in either mapping.
  EXPECT_TRUE(std::isinf(eyeDepth(1.0f, kInfinite, false)));
  EXPECT_TRUE(std::isinf(eyeDepth(0.0f, kInfinite, true)));
}

TEST(DepthView, NearerIsBrighterAndClearedIsDistinct) {
  for (const glm::mat4& p : {kFinite, kInfinite}) {
    DepthRange range;
    const Image picture = depthPicture(scene(p, false), 4, 2, p, false, &range);
    EXPECT_EQ(picture.width, 4);
    EXPECT_GT(picture.height, 2);  // the legend band below
    EXPECT_NEAR(range.nearest, 2.0f, 1e-3f);
    EXPECT_NEAR(range.farthest, 16.0f, 1e-2f);
    EXPECT_EQ(range.cleared, 4u);
    EXPECT_EQ(range.drawn, 4u);
    EXPECT_EQ(picture.at(0, 0)[0], 255);            // the nearest white
    EXPECT_EQ(picture.at(3, 0)[0], kDepthFarGrey);  // the farthest dark grey
    for (int x = 0; x + 1 < 4; ++x) EXPECT_GT(picture.at(x, 0)[0], picture.at(x + 1, 0)[0]) << x;
    // Linear in eye depth: 4 lies 2/14 of the way from 2 to 16.
    EXPECT_NEAR(picture.at(1, 0)[0], 255.0 - 2.0 / 14.0 * (255 - kDepthFarGrey), 1.0);
    for (int x = 0; x < 4; ++x) {
      const std::array<std::uint8_t, 3> c{picture.at(x, 1)[0], picture.at(x, 1)[1], picture.at(x, 1)[2]};
      EXPECT_EQ(c, kDepthClearedColour);
      const std::uint8_t g = kDepthFarGrey;
      EXPECT_GE(colourDistance(c, {g, g, g}), kStencilDistinct);  // not mistaken for the far grey
    }
  }
}

TEST(DepthView, ReversedDepthGivesTheSamePicture) {
  for (const glm::mat4& p : {kFinite, kInfinite}) {
    const Image standard = depthPicture(scene(p, false), 4, 2, p, false);
    const Image reversed = depthPicture(scene(reversedDepth(p), true), 4, 2, p, true);
    ASSERT_EQ(standard.height, reversed.height);
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_LE(std::abs(standard.at(x, y)[c] - reversed.at(x, y)[c]), 1) << x << "," << y;
    // Read with the standard mapping, the reversed buffer would turn near and far about.
    const Image misread = depthPicture(scene(reversedDepth(p), true), 4, 2, p, false);
    EXPECT_NE(misread.at(0, 0)[0], standard.at(0, 0)[0]);
  }
}

TEST(DepthView, NothingDrawnIsAllCleared) {
  const std::vector<float> depth(6, 1.0f);
  DepthRange range;
  const Image picture = depthPicture(depth, 3, 2, kFinite, false, &range);
  EXPECT_EQ(range.cleared, 6u);
  EXPECT_EQ(range.drawn, 0u);
  EXPECT_EQ(picture.at(2, 1)[2], kDepthClearedColour[2]);
}

// The legend's digits are textScale pixels a dot (3x5 dots): the window's grow with its UI scale.
TEST(DepthView, LegendDigitsFollowTheTextScale) {
  const int width = 240, height = 4;
  const std::vector<float> depth(static_cast<std::size_t>(width * height), windowDepth(kFinite, 3.0f, false));
  for (const int textScale : {2, 4, 6}) {
    const Image picture = depthPicture(depth, width, height, kFinite, false, nullptr, textScale);
    ASSERT_EQ(picture.height, height + 7 * textScale + 8) << textScale;
    // Rows of the band holding white: the digits' 5 dots (the ramp's white end is as high).
    int whiteRows = 0;
    for (int y = height; y < picture.height; ++y) {
      bool white = false;
      for (int x = 0; x < width; ++x) {
        const std::uint8_t* p = picture.at(x, y);
        white = white || (p[0] == 255 && p[1] == 255 && p[2] == 255);
      }
      whiteRows += white;
    }
    EXPECT_EQ(whiteRows, 5 * textScale) << textScale;
  }
}
