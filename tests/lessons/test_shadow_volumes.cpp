// Lessons 07 and 08's claims about where shadow volumes fail, measured on their output against
// the ray-cast oracle's classes (--oracle writes them beside its picture), and what counting
// costs against one inverted bit (--stats).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "../lesson_stats.h"
#include "geometry/shadow_oracle.h"
#include "gl/image.h"

using namespace stencil;

namespace {

constexpr int kWidth = 320, kHeight = 240;

std::filesystem::path outDir() {
  return std::filesystem::temp_directory_path() / "stencil-shadow-volumes" /
         ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

// Runs a lesson at the golden size; 77 (no GL context) gives nullopt. The command's exit code
// is not checked: an --oracle run of a failing variant exits 1 on purpose.
std::optional<std::string> run(const std::string& lesson, const std::string& name, const std::string& args) {
  std::filesystem::create_directories(outDir());
  const auto stdoutFile = outDir() / (name + ".out");
  const std::string command = lesson + " --headless --quiet --size " + std::to_string(kWidth) + "x" +
                              std::to_string(kHeight) + " --time 1 " + args + " > " + stdoutFile.string() +
                              " 2> " + (outDir() / (name + ".err")).string();
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  std::ifstream in(stdoutFile);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Verdicts {
  Image classes, stencil;  // the oracle's PixelClass per pixel; the final stencil values
};

std::optional<Verdicts> judged(const std::string& lesson, const std::string& variant) {
  const auto oracle = outDir() / (variant + "-oracle.png"), stencil = outDir() / (variant + "-stencil.png");
  if (!run(lesson, variant,
           "--variant " + variant + " --oracle " + oracle.string() + " --stencil-out " + stencil.string()))
    return std::nullopt;
  return Verdicts{readPng(outDir() / (variant + "-oracle.raw.png"), 1),
                  readPng(outDir() / (variant + "-stencil.raw.png"), 1)};
}

PixelClass classAt(const Image& classes, int x, int y) {
  return static_cast<PixelClass>(classes.pixels[static_cast<std::size_t>(y * kWidth + x)]);
}

bool receiver(PixelClass c) {
  return c == PixelClass::Lit || c == PixelClass::Shadowed;
}

// As compareWithOracle: an edge pixel has a neighbour of another class (the picture's border counts).
bool onEdge(const Image& classes, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= kWidth || ny >= kHeight) continue;
      if (classAt(classes, nx, ny) != classAt(classes, x, y)) return true;
    }
  return false;
}

// Off-edge receiver pixels, sorted by what the lesson drew against what the oracle says.
struct Tally {
  std::size_t agree = 0, falselyLit = 0, falselyShadowed = 0;
};

template <typename ShadowedInStencil>
Tally tally(const Verdicts& v, ShadowedInStencil shadowed, std::vector<bool>* falselyLitMask = nullptr) {
  Tally t;
  if (falselyLitMask) falselyLitMask->assign(static_cast<std::size_t>(kWidth * kHeight), false);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const PixelClass c = classAt(v.classes, x, y);
      if (!receiver(c) || onEdge(v.classes, x, y)) continue;
      const bool inImage = shadowed(v.stencil.pixels[static_cast<std::size_t>(y * kWidth + x)]);
      const bool inOracle = c == PixelClass::Shadowed;
      if (inImage == inOracle)
        ++t.agree;
      else if (inImage)
        ++t.falselyShadowed;
      else {
        ++t.falselyLit;
        if (falselyLitMask) (*falselyLitMask)[static_cast<std::size_t>(y * kWidth + x)] = true;
      }
    }
  return t;
}

std::uint64_t samplesPassed(const std::string& stats, const std::string& pass) {
  return static_cast<std::uint64_t>(stencil::testing::LessonStats(stats).firstPass(pass, "samples_passed"));
}

auto oddBit = [](std::uint8_t s) { return (s & 1) != 0; };
auto nonzero = [](std::uint8_t s) { return s != 0; };

}  // namespace

TEST(InvertShadowVolumes, EyeInsideTheVolumeInvertsEveryReceiverPixel) {
  const auto v = judged(LESSON_07, "eye-inside");
  if (!v) GTEST_SKIP() << "no GL context";
  const Tally t = tally(*v, oddBit);
  EXPECT_EQ(t.agree, 0u) << "with the eye in a volume every crossing count is off by one";
  EXPECT_GT(t.falselyLit, 1000u);        // the shadow the eye stands in comes out lit
  EXPECT_GT(t.falselyShadowed, 10000u);  // and the lit ground comes out dark
}

TEST(InvertShadowVolumes, WhereTwoVolumesOverlapTheShadowComesOutLit) {
  // Lesson 08 counts the same scene's volumes: the pixels it counts twice are the overlap.
  const auto inverted = judged(LESSON_07, "overlap");
  const auto counted = judged(LESSON_08, "silhouette");
  if (!inverted || !counted) GTEST_SKIP() << "no GL context";
  ASSERT_EQ(inverted->classes.pixels, counted->classes.pixels) << "not the same scene";
  std::vector<bool> falselyLit;
  const Tally t = tally(*inverted, oddBit, &falselyLit);
  EXPECT_EQ(t.falselyShadowed, 0u);
  EXPECT_GT(t.falselyLit, 300u);
  std::size_t overlap = 0, overlapLit = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      if (!receiver(classAt(counted->classes, x, y)) || onEdge(counted->classes, x, y)) continue;
      const bool twice = counted->stencil.pixels[i] == 2;
      overlap += twice;
      overlapLit += twice && falselyLit[i];
      EXPECT_TRUE(!falselyLit[i] || twice) << "falsely lit outside the overlap at " << x << "," << y;
    }
  EXPECT_EQ(overlapLit, overlap) << "every doubly shadowed pixel should come out lit";
}

TEST(CountingShadowVolumes, SaturatingDecrementsFirstOnlyAddFalseShadows) {
  const auto v = judged(LESSON_08, "saturate-back-first");
  if (!v) GTEST_SKIP() << "no GL context";
  const Tally t = tally(*v, nonzero);
  EXPECT_EQ(t.falselyLit, 0u) << "a lost DECR can only leave a count too high";
  EXPECT_GT(t.falselyShadowed, 300u);  // where a volume passes entirely in front of lit ground
}

TEST(CountingShadowVolumes, CountingTheSameSilhouetteCostsWhatTheBitCosts) {
  // The same quads pass the same depth test whether they invert a bit in one pass or count in
  // two; extruding every lit triangle rasterizes more (the shared edges' quads cancel, but cost).
  const auto invert = run(LESSON_07, "invert", "--variant overlap --stats");
  const auto silhouette = run(LESSON_08, "silhouette", "--variant silhouette --stats");
  const auto perTriangle = run(LESSON_08, "per-triangle", "--variant counting --stats");
  if (!invert || !silhouette || !perTriangle) GTEST_SKIP() << "no GL context";
  const std::uint64_t bit = samplesPassed(*invert, "volumes");
  const std::uint64_t counted =
      samplesPassed(*silhouette, "front-faces") + samplesPassed(*silhouette, "back-faces");
  const std::uint64_t extruded =
      samplesPassed(*perTriangle, "front-faces") + samplesPassed(*perTriangle, "back-faces");
  EXPECT_EQ(counted, bit);
  EXPECT_GT(extruded, counted);
  std::cout << "volume fragments passing depth: invert " << bit << ", counting silhouettes " << counted
            << ", counting per-triangle volumes " << extruded << "\n";
}
