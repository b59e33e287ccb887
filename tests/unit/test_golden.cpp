// Golden comparison: the tolerance is exactly what docs/testing.md promises.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gl/golden.h"

using namespace stencil;

namespace {

Image solid(int w, int h, int channels, std::uint8_t value) {
  Image img(w, h, channels);
  std::fill(img.pixels.begin(), img.pixels.end(), value);
  return img;
}

std::filesystem::path freshDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("stencil-unit-" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// The golden functions stage their files; these write them at once, as a lesson's run does.
void writeGoldenNow(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                    const std::string& name) {
  OutputSet out;
  writeGolden(colour, stencil, dir, name, out);
  out.commit();
}
GoldenResult checkGoldenNow(const Image& colour, const Image& stencil, const std::filesystem::path& dir,
                            const std::string& name, const std::filesystem::path& artifacts) {
  OutputSet out;
  const GoldenResult r = checkGolden(colour, stencil, dir, name, artifacts, out);
  out.commit();
  return r;
}

}  // namespace

TEST(GoldenDiff, ColourWithinChannelToleranceDoesNotCount) {
  Image expected = solid(10, 10, 4, 100);
  Image actual = expected;
  actual.at(3, 4)[1] = 105;  // exactly at the tolerance
  actual.at(5, 5)[2] = 106;  // one past it
  const ImageDiff d = diffColour(actual, expected, 5);
  EXPECT_EQ(d.pixels, 100u);
  EXPECT_EQ(d.differing, 1u);
  EXPECT_EQ(d.maxChannelDiff, 6);
  // The diff picture marks the differing pixel red and only it.
  EXPECT_EQ(d.picture.at(5, 5)[0], 255);
  EXPECT_EQ(d.picture.at(5, 5)[1], 0);
  EXPECT_NE(d.picture.at(3, 4)[0], 255);
}

TEST(GoldenDiff, StencilAnyDifferenceCounts) {
  Image expected = solid(8, 8, 1, 3);
  Image actual = expected;
  *actual.at(7, 0) = 4;
  const ImageDiff d = diffStencil(actual, expected);
  EXPECT_EQ(d.differing, 1u);
  EXPECT_EQ(d.maxChannelDiff, 1);
}

TEST(GoldenDiff, SizeMismatchIsReported) {
  EXPECT_TRUE(diffColour(solid(4, 4, 4, 0), solid(4, 5, 4, 0), 5).sizeMismatch);
  EXPECT_TRUE(diffStencil(solid(4, 4, 1, 0), solid(5, 4, 1, 0)).sizeMismatch);
}

TEST(GoldenCheck, ColourFractionLimitIsInclusive) {
  // 1000 pixels and a 0.1% allowance: one differing pixel passes, two fail.
  const auto dir = freshDir("fraction");
  const Image colour = solid(100, 10, 4, 50), stencil = solid(100, 10, 1, 0);
  writeGoldenNow(colour, stencil, dir, "v");
  Image one = colour;
  one.at(0, 0)[0] = 200;
  EXPECT_TRUE(checkGoldenNow(one, stencil, dir, "v", dir / "artifacts-one").passed);
  Image two = one;
  two.at(1, 0)[0] = 200;
  EXPECT_FALSE(checkGoldenNow(two, stencil, dir, "v", dir / "artifacts-two").passed);
}

TEST(GoldenCheck, OneStencilValueFailsAndLeavesArtifacts) {
  const auto dir = freshDir("artifacts");
  const Image colour = solid(16, 16, 4, 80), stencil = solid(16, 16, 1, 1);
  writeGoldenNow(colour, stencil, dir, "v");
  ASSERT_TRUE(checkGoldenNow(colour, stencil, dir, "v", dir / "a").passed);

  Image changed = stencil;
  *changed.at(2, 2) = 2;
  const GoldenResult r = checkGoldenNow(colour, changed, dir, "v", dir / "a");
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("stencil: 1 of 256"), std::string::npos) << r.message;
  for (const char* f : {"colour-actual.png", "colour-expected.png", "colour-diff.png", "stencil-actual.png",
                        "stencil-expected.png", "stencil-diff.png", "stencil-actual.raw.png", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "a" / f)) << f;
  std::ifstream json(dir / "a" / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"stencil_pixels_differing\": 1"), std::string::npos) << text;
  // The raw values round-trip exactly through PNG.
  const Image raw = readPng(dir / "a" / "stencil-actual.raw.png", 1);
  EXPECT_EQ(raw.pixels, changed.pixels);
}

TEST(GoldenCheck, MissingGoldenFailsWithItsPath) {
  const auto dir = freshDir("missing");
  const GoldenResult r = checkGoldenNow(solid(4, 4, 4, 0), solid(4, 4, 1, 0), dir, "nope", dir / "a");
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("nope.png"), std::string::npos) << r.message;
}

// The renderer strings the goldens are made with, and two they are not (GL_RENDERER as drivers
// report it).
TEST(Golden, OnlyLlvmpipeIsComparedWithTheGoldens) {
  EXPECT_TRUE(isGoldenRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_FALSE(isGoldenRenderer("NVIDIA H200/PCIe/SSE2"));
  EXPECT_FALSE(isGoldenRenderer("AMD Radeon RX 6800 (radeonsi, navi21, LLVM 15.0.6, DRM 3.49)"));
}
