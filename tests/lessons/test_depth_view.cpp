// The depth view (--depth-out) on lessons' own depth buffers: two spheres a scene file puts at
// known eye depths, the nearer brighter; the background the cleared colour; and lesson 15's
// reversed float depth drawing the picture its standard fixed-point variant draws.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "gl/image.h"
#include "gl/stencil_view.h"

using namespace stencil;

namespace {

// Camera on +z looking at the origin (fovy 50, 320x240, the far plane at infinity). The near
// sphere (radius 1) at x = -2, z = 3 is 7 units in front of the eye; the far one at x = 2, z = -6
// is 16. Their centres land at pixel x = 160 (1 + x_eye / (d tan 25 deg 4/3)): 86 and 192, row 120.
constexpr const char* kScene = R"(camera eye 0 0 10 target 0 0 0 fovy 50 near 0.5
light point 0 6 10
object near sphere radius 1
  translate -2 0 3
object far sphere radius 1
  translate 2 0 -6
)";

std::filesystem::path folder() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() / "stencil-depth-view" /
                   (std::string(test->test_suite_name()) + "." + test->name());
  std::filesystem::create_directories(dir);
  return dir;
}

// The --depth-out picture of `binary` drawing kScene; nothing when no context can be made.
std::optional<Image> depthOut(const std::string& binary, const std::string& name, const std::string& args) {
  const auto dir = folder();
  { std::ofstream(dir / "two-spheres.scene") << kScene; }
  const auto picture = dir / (name + ".png");
  const std::string command = binary + " --headless --quiet --size 320x240 --time 1 --scene " +
                              (dir / "two-spheres.scene").string() + " " + args + " --depth-out " +
                              picture.string();
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  EXPECT_EQ(status, 0) << command;
  return readPng(picture, 4);
}

bool isCleared(const Image& p, int x, int y) {
  return p.at(x, y)[0] == kDepthClearedColour[0] && p.at(x, y)[1] == kDepthClearedColour[1] &&
         p.at(x, y)[2] == kDepthClearedColour[2];
}

void expectNearerBrighter(const Image& p, const std::string& what) {
  ASSERT_EQ(p.width, 320) << what;
  ASSERT_GT(p.height, 240) << what;  // the legend band below
  const int nearGrey = p.at(86, 120)[0], farGrey = p.at(192, 120)[0];
  EXPECT_FALSE(isCleared(p, 86, 120)) << what;
  EXPECT_FALSE(isCleared(p, 192, 120)) << what;
  EXPECT_GT(nearGrey, farGrey + 100) << what;  // 7 against 16 units, the range about 6..17
  EXPECT_TRUE(isCleared(p, 2, 2)) << what;     // nothing drawn in the corner
  EXPECT_TRUE(isCleared(p, 160, 40)) << what;  // nor between and above the spheres
}

}  // namespace

// Lesson 16 keeps the scene's depth to the end of its frame (lesson 13 does not: its last pass
// leaves a cleared depth buffer behind its count picture).
TEST(DepthView, Lesson16NearerSurfacesAreBrighter) {
  const auto p = depthOut(LESSON_16, "lesson16", "");
  if (!p) GTEST_SKIP() << "no GL context";
  expectNearerBrighter(*p, "lesson 16");
}

TEST(DepthView, Lesson15ReversedDepthDrawsTheStandardPicture) {
  const auto reversed = depthOut(LESSON_15, "reversed", "--variant zfail");
  if (!reversed) GTEST_SKIP() << "no GL context";
  const auto standard = depthOut(LESSON_15, "fixed24", "--variant pinf-fixed24");
  expectNearerBrighter(*reversed, "zfail, reversed float depth");
  expectNearerBrighter(*standard, "pinf-fixed24, standard depth");
  // Within a grey level or two, edge pixels aside: the same eye depths through two mappings.
  std::size_t apart = 0;
  for (int y = 0; y < 240; ++y)
    for (int x = 0; x < 320; ++x) apart += std::abs(reversed->at(x, y)[0] - standard->at(x, y)[0]) > 2;
  EXPECT_LT(apart, 320u * 240u / 200u);
}
