// Lesson 09's claims, measured on its output: the three extrusions of the cut-out give the same
// stencil; the lattice's holes come through as lit islands inside the shadow, exactly as many as
// the ray cast finds; a cut-out edge-on to the light (or parallel to a directional one) changes
// nothing; and the flattened silhouette shadows the floor exactly as the planar shadow does.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "geometry/shadow_oracle.h"
#include "gl/image.h"

using namespace stencil;

namespace {

struct Render {
  Image colour, stencil, oracle;  // oracle: the ray cast's PixelClass per pixel (empty without --oracle)
};

constexpr std::uint8_t kCount = 0x7F;

// Runs the lesson headless at the golden size and time; skips the test without a context.
// Each test writes into its own folder: ctest runs the tests of this file in parallel.
std::optional<Render> render(const std::string& name, const std::string& args, bool oracle = false) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "stencil-lesson-09" /
                                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto colour = out / (name + ".png"), stencil = out / (name + "-stencil.png"),
             classes = out / (name + "-oracle.png");
  const std::string command = std::string(LESSON_09) + " --headless --quiet --size 320x240 --time 1 " + args +
                              " --out " + colour.string() + " --stencil-out " + stencil.string() +
                              (oracle ? " --oracle " + classes.string() : "") + " 2>/dev/null";
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  EXPECT_EQ(status, 0) << command;
  Render r{readPng(colour, 4), readPng(out / (name + "-stencil.raw.png"), 1), {}};
  if (oracle) r.oracle = readPng(out / (name + "-oracle.raw.png"), 1);
  return r;
}

std::size_t differingPixels(const Image& a, const Image& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

// Connected regions (4-neighbours) of pixels for which `inside` holds that touch neither the
// image's border nor a pixel for which `wall` holds: islands enclosed by everything else.
std::size_t enclosedIslands(int width, int height, const std::function<bool(std::size_t)>& inside,
                            const std::function<bool(std::size_t)>& wall) {
  std::vector<int> label(static_cast<std::size_t>(width * height), -1);
  std::size_t islands = 0;
  for (int start = 0; start < width * height; ++start) {
    if (label[static_cast<std::size_t>(start)] >= 0 || !inside(static_cast<std::size_t>(start))) continue;
    bool enclosed = true;
    std::vector<int> stack{start};
    label[static_cast<std::size_t>(start)] = 1;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % width, y = p / width;
      if (x == 0 || y == 0 || x == width - 1 || y == height - 1) enclosed = false;
      for (const int q : {p - 1, p + 1, p - width, p + width}) {
        if (q < 0 || q >= width * height || (q % width != x && q / width != y)) continue;
        const auto qi = static_cast<std::size_t>(q);
        if (wall(qi)) enclosed = false;
        if (label[qi] >= 0 || !inside(qi)) continue;
        label[qi] = 1;
        stack.push_back(q);
      }
    }
    islands += enclosed;
  }
  return islands;
}

}  // namespace

TEST(CutoutExtrusion, CpuMatrixAndGpuExtrusionsGiveTheSameStencil) {
  for (const std::string light : {"", " --set light=1", " --set light=2"}) {
    const auto cpu = render("cpu", "--variant cpu" + light);
    const auto matrix = render("matrix", "--variant matrix" + light);
    const auto gpu = render("gpu", "--variant gpu" + light);
    if (!cpu || !matrix || !gpu) GTEST_SKIP() << "no GL context";
    std::size_t shadowed = 0;
    for (const std::uint8_t s : cpu->stencil.pixels) shadowed += (s & kCount) != 0;
    EXPECT_GT(shadowed, 500u) << "light" << light << ": the lattice should shadow something";
    // Different vertices reach the rasteriser (w = 0 points, a projective matrix, blended
    // matrices), so a pixel exactly on a volume's edge may fall either way; nothing more.
    EXPECT_LE(differingPixels(cpu->stencil, matrix->stencil), 20u) << "light" << light;
    EXPECT_LE(differingPixels(cpu->stencil, gpu->stencil), 20u) << "light" << light;
  }
}

TEST(CutoutExtrusion, TheLatticesHolesAreLitIslandsInItsShadow) {
  for (const std::string args : {"--variant cpu", "--variant directional", "--variant gpu --set holes=5"}) {
    const auto r = render("holes", args, true);
    if (!r) GTEST_SKIP() << "no GL context";
    const auto receiver = [&](std::size_t i) {
      const auto c = static_cast<PixelClass>(r->oracle.pixels[i]);
      return c == PixelClass::Lit || c == PixelClass::Shadowed;
    };
    const auto litInStencil = [&](std::size_t i) {
      return receiver(i) && (r->stencil.pixels[i] & kCount) == 0;
    };
    const auto litInOracle = [&](std::size_t i) {
      return static_cast<PixelClass>(r->oracle.pixels[i]) == PixelClass::Lit;
    };
    const auto notReceiver = [&](std::size_t i) { return !receiver(i); };
    const std::size_t stencilIslands = enclosedIslands(320, 240, litInStencil, notReceiver);
    const std::size_t oracleIslands = enclosedIslands(320, 240, litInOracle, notReceiver);
    // Only holes whose light lands wholly on visible ground count; several do at t = 1.
    EXPECT_GE(oracleIslands, 4u) << args << ": the scene should show the holes";
    EXPECT_EQ(stencilIslands, oracleIslands) << args;
  }
}

TEST(CutoutExtrusion, ACutoutEdgeOnToTheLightChangesNothing) {
  for (const std::string variant : {"edge-on", "edge-on-gpu", "parallel", "parallel-matrix"}) {
    const auto withShadow = render("shadow", "--variant " + variant);
    const auto without = render("plain", "--variant " + variant + " --set shadow=0");
    if (!withShadow || !without) GTEST_SKIP() << "no GL context";
    std::size_t counted = 0;
    for (const std::uint8_t s : withShadow->stencil.pixels) counted += s != 0;
    EXPECT_EQ(counted, 0u) << variant << ": no volume, so no count anywhere";
    EXPECT_EQ(differingPixels(withShadow->colour, without->colour), 0u) << variant;
  }
}

TEST(CutoutExtrusion, FlattenedSilhouetteShadowsTheFloorAsThePlanarShadowDoes) {
  const auto flattened = render("flatten", "--variant flatten --set logo=0", true);
  const auto planar = render("planar", "--variant figure-14 --set logo=0");
  if (!flattened || !planar) GTEST_SKIP() << "no GL context";
  std::size_t ground = 0, shadowedByBoth = 0, differ = 0;
  for (std::size_t i = 0; i < flattened->stencil.pixels.size(); ++i) {
    const auto c = static_cast<PixelClass>(flattened->oracle.pixels[i]);
    if (c != PixelClass::Lit && c != PixelClass::Shadowed) continue;  // the floor only
    ++ground;
    const bool a = (flattened->stencil.pixels[i] & kCount) != 0,
               b = (planar->stencil.pixels[i] & kCount) != 0;
    shadowedByBoth += a && b;
    differ += a != b;
  }
  EXPECT_GT(ground, 10000u);
  EXPECT_GT(shadowedByBoth, 500u) << "the teapot's shadow should be on the floor";
  EXPECT_LE(differ, 20u) << "a shadow volume from the outline and the projected teapot disagree";
}
