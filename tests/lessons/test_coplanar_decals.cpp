// Lesson 06's claims, measured on its own output:
//   - with the stencil recipe every visible marking pixel has exactly the marking's colour,
//     and the markings change no other pixel (not the tower in front of the runway);
//   - with the plain depth test a large share of those pixels shows the runway instead
//     (z-fighting), so the first check does catch the artifact;
//   - the decals leave the depth buffer as the runway left it: the objects drawn afterwards
//     pass the depth test on exactly the same number of fragments as without any decals
//     (polygon offset, which writes pulled-forward depths, does not).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "../lesson_stats.h"
#include "gl/image.h"

using namespace stencil;

namespace {

const std::filesystem::path kOut = std::filesystem::temp_directory_path() / "stencil-lesson-06";

std::string lessonCommand(const std::string& args) {
  return std::string(LESSON_06) + " --headless --quiet --size 320x240 --time 1 " + args;
}

bool noContext(int status) {
  return WIFEXITED(status) && WEXITSTATUS(status) == 77;
}

// One run: the colour after the runway pass and after the decals pass, and the final stencil.
struct Render {
  Image runway, decals, stencil;
};

// Each test renders into its own folder: ctest runs the tests in parallel.
std::optional<Render> render(const std::string& name, const std::string& args) {
  const auto dir = kOut / ::testing::UnitTest::GetInstance()->current_test_info()->name() / name;
  std::filesystem::remove_all(dir);
  const std::string command = lessonCommand(args + " --passes " + dir.string() + " --stencil-out " +
                                            (dir / "final-stencil.png").string());
  const int status = std::system(command.c_str());
  if (noContext(status)) return std::nullopt;
  EXPECT_EQ(status, 0) << command;
  return Render{readPng(dir / "02-runway.png", 4), readPng(dir / "03-decals.png", 4),
                readPng(dir / "final-stencil.raw.png", 1)};
}

bool samePixel(const Image& a, const Image& b, size_t i) {
  for (int c = 0; c < 3; ++c)
    if (a.pixels[4 * i + c] != b.pixels[4 * i + c]) return false;
  return true;
}

// The visible marking pixels, derived without the stencil recipe: where the markings land when
// drawn with no depth test and no stencil (depth-off: their whole screen footprint), and where
// the runway is visible (tag 1 in the stencil run without decals).
struct Markings {
  std::vector<bool> visible;
  size_t count = 0, offRunway = 0;  // footprint pixels that are not visible runway
  std::uint8_t colour[3] = {0, 0, 0};
  bool uniform = true;
};

Markings visibleMarkings(const Render& footprint, const Render& bare) {
  Markings m;
  m.visible.resize(bare.stencil.pixels.size());
  bool first = true;
  for (size_t i = 0; i < m.visible.size(); ++i) {
    if (samePixel(footprint.runway, footprint.decals, i)) continue;
    if (bare.stencil.pixels[i] != 1) {
      ++m.offRunway;
      continue;
    }
    m.visible[i] = true;
    ++m.count;
    for (int c = 0; c < 3; ++c) {
      const std::uint8_t v = footprint.decals.pixels[4 * i + c];
      if (first) m.colour[c] = v;
      m.uniform = m.uniform && m.colour[c] == v;
    }
    first = false;
  }
  return m;
}

// samples_passed of one pass in the lesson's --stats JSON.
std::optional<long> samplesPassed(const std::string& args, const std::string& pass) {
  const std::string command = lessonCommand(args + " --stats");
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string json;
  char buffer[4096];
  while (size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) json.append(buffer, n);
  const int status = pclose(pipe);
  if (noContext(status)) return std::nullopt;
  EXPECT_EQ(status, 0) << command;
  return stencil::testing::LessonStats(json).firstPass(pass, "samples_passed");
}

}  // namespace

TEST(CoplanarDecals, StencilPaintsEveryVisibleMarkingPixelAndNothingElse) {
  const auto footprint = render("footprint", "--variant depth-off");
  const auto bare = render("bare", "--variant stencil --set decals=0");
  const auto recipe = render("stencil", "--variant stencil");
  if (!footprint || !bare || !recipe) GTEST_SKIP() << "no GL context";
  const Markings m = visibleMarkings(*footprint, *bare);
  // Guards against a vacuous pass: at t = 1 about 2380 marking pixels are visible and the
  // tower hides about 500 more.
  EXPECT_GT(m.count, 1500u) << "the markings should cover a good part of the runway";
  EXPECT_GT(m.offRunway, 200u) << "the tower should hide some of the markings";
  EXPECT_TRUE(m.uniform) << "a marking drawn flat and lit by the sun has one colour";

  size_t wrong = 0, changedElsewhere = 0;
  for (size_t i = 0; i < m.visible.size(); ++i) {
    if (m.visible[i]) {
      for (int c = 0; c < 3; ++c) wrong += recipe->decals.pixels[4 * i + c] != m.colour[c];
    } else {
      changedElsewhere += !samePixel(recipe->runway, recipe->decals, i);
    }
  }
  std::cout << "[ measured ] " << m.count << " visible marking pixels, " << m.offRunway
            << " hidden by the tower or off the runway; wrong channels " << wrong << ", changed elsewhere "
            << changedElsewhere << "\n";
  EXPECT_EQ(wrong, 0u) << "marking channels that are not the marking's colour";
  EXPECT_EQ(changedElsewhere, 0u) << "pixels the markings changed off the visible runway";
}

TEST(CoplanarDecals, WithTheDepthTestTheRunwayWinsManyMarkingPixels) {
  const auto footprint = render("footprint", "--variant depth-off");
  const auto bare = render("bare", "--variant stencil --set decals=0");
  const auto fighting = render("z-fighting", "--variant z-fighting");
  if (!footprint || !bare || !fighting) GTEST_SKIP() << "no GL context";
  const Markings m = visibleMarkings(*footprint, *bare);

  size_t lost = 0;
  for (size_t i = 0; i < m.visible.size(); ++i)
    if (m.visible[i] && samePixel(fighting->runway, fighting->decals, i)) ++lost;
  std::cout << "[ measured ] z-fighting: " << lost << " of " << m.count
            << " marking pixels show the runway\n";
  // At t = 1 the runway keeps a little over half of them; a fifth is plenty to see.
  EXPECT_GT(lost, m.count / 5) << "z-fighting should leave many marking pixels runway-coloured";
}

TEST(CoplanarDecals, DecalsLeaveTheRunwayDepthForLaterObjects) {
  const auto withDecals = samplesPassed("--variant stencil", "objects");
  const auto without = samplesPassed("--variant stencil --set decals=0", "objects");
  const auto offsetWith = samplesPassed("--variant polygon-offset", "objects");
  const auto offsetWithout = samplesPassed("--variant polygon-offset --set decals=0", "objects");
  if (!withDecals || !without || !offsetWith || !offsetWithout) GTEST_SKIP() << "no GL context or stats";
  std::cout << "[ measured ] objects' fragments: stencil " << *withDecals << " with decals, " << *without
            << " without; polygon-offset " << *offsetWith << " with, " << *offsetWithout << " without\n";
  EXPECT_GT(*without, 300) << "the aircraft and the arch should be in view";
  EXPECT_EQ(*withDecals, *without) << "the stencil recipe's decals changed what later objects see";
  // The same check sees polygon offset's written depths: the arch's feet lose fragments to
  // markings that now sit in front of the runway.
  EXPECT_LT(*offsetWith, *offsetWithout) << "polygon-offset decals should hide some arch fragments";
}
