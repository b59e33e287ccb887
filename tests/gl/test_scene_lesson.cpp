// What runSceneLesson gives a lesson, measured on the scene test lesson's output: the scene
// from --scene (or none), the scene's camera, and the per-light shadow masks of --mask-out.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "lesson_run.h"

using stencil::Image;
using stencil::readPng;
using stencil::testing::LessonRun;
using stencil::testing::runLesson;

namespace {

const std::string scenes = SCENES_DIR;

std::filesystem::path maskDir(const std::string& name) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::temp_directory_path() / "stencil-scene-masks" / (test->name() + name);
  std::filesystem::remove_all(dir);
  return dir;
}

// The mask is the stencil read back as "zero or not": compare it with the raw stencil.
void expectMaskIsStencilZero(const Image& mask, const Image& stencil) {
  ASSERT_EQ(mask.pixels.size(), stencil.pixels.size());
  std::size_t lit = 0, mismatches = 0;
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    lit += mask.pixels[i] == 255;
    mismatches += mask.pixels[i] != (stencil.pixels[i] == 0 ? 255 : 0);
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(lit, 0u);
  EXPECT_LT(lit, mask.pixels.size());  // some shadow
}

}  // namespace

TEST(SceneLesson, WithoutASceneTheLessonDrawsItsOwn) {
  const auto dir = maskDir("");
  const auto run = runLesson(SCENE_LESSON, "builtin", "--mask-out " + dir.string(), true);
  if (!run) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(run->count("scene_objects"), 2);
  EXPECT_EQ(run->count("scene_lights"), 1);
  expectMaskIsStencilZero(readPng(dir / "light-0.png", 1), run->stencil);
}

TEST(SceneLesson, NoMasksWithoutMaskOut) {
  const auto dir = maskDir("");
  const auto run = runLesson(SCENE_LESSON, "nomask", "");
  if (!run) GTEST_SKIP() << "no GL context";
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(SceneLesson, TheSceneFromTheFileWithOneMaskPerLight) {
  const auto dir = maskDir("");
  const auto run = runLesson(SCENE_LESSON, "two-lights",
                             "--scene " + scenes + "/two-lights.scene --mask-out " + dir.string(), true);
  if (!run) GTEST_SKIP() << "no GL context";
  EXPECT_EQ(run->count("scene_objects"), 3);
  EXPECT_EQ(run->count("scene_lights"), 2);
  const Image first = readPng(dir / "light-0.png", 1), second = readPng(dir / "light-1.png", 1);
  expectMaskIsStencilZero(second, run->stencil);  // the last light's stencil is the final one
  std::size_t differ = 0;
  for (std::size_t i = 0; i < first.pixels.size(); ++i) differ += first.pixels[i] != second.pixels[i];
  EXPECT_GT(differ, 1000u);  // two lights, two different shadows
  EXPECT_FALSE(std::filesystem::exists(dir / "light-2.png"));
}

TEST(SceneLesson, TheFilesCameraReplacesTheLessons) {
  // The built-in scene written as a file renders the same picture; mirrored, it renders it
  // flipped left to right.
  const auto own = runLesson(SCENE_LESSON, "own", "");
  if (!own) GTEST_SKIP() << "no GL context";
  const auto file = runLesson(SCENE_LESSON, "file", "--scene " + scenes + "/builtin.scene");
  const auto mirrored = runLesson(SCENE_LESSON, "mirrored", "--scene " + scenes + "/builtin-mirrored.scene");
  ASSERT_TRUE(file && mirrored);
  EXPECT_EQ(file->colour.pixels, own->colour.pixels);
  EXPECT_EQ(file->stencil.pixels, own->stencil.pixels);
  const int w = own->colour.width, h = own->colour.height;
  std::size_t differ = 0, unlike = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const std::size_t flipped = static_cast<std::size_t>(y) * w + static_cast<std::size_t>(w - 1 - x);
      differ += stencil::testing::differs(own->colour, mirrored->colour, i);
      // The mirror swaps front and back faces, so the counts change sign: compare "in shadow".
      bool same = (own->stencil.pixels[i] == 0) == (mirrored->stencil.pixels[flipped] == 0);
      for (int c = 0; c < 3; ++c)
        same &=
            std::abs(int(own->colour.pixels[4 * i + c]) - int(mirrored->colour.pixels[4 * flipped + c])) <= 5;
      unlike += !same;
    }
  EXPECT_GT(differ, static_cast<std::size_t>(w * h / 20));  // not symmetric to begin with
  EXPECT_LT(unlike, static_cast<std::size_t>(w * h / 200)) << "the mirrored picture is not the flipped one";
}

TEST(SceneLesson, OracleAgreesOnTheSceneFromTheFile) {
  const auto dir = maskDir("");
  const auto run =
      runLesson(SCENE_LESSON, "oracle",
                "--scene " + scenes + "/builtin.scene --oracle " + (dir / "oracle.png").string());
  if (!run) GTEST_SKIP() << "no GL context";
}

// What preparing the casters did is printed, one line each, unless --quiet.
TEST(SceneLesson, CasterNotesArePrintedUnlessQuiet) {
  const auto dir = maskDir("");
  std::filesystem::create_directories(dir);
  const std::string scene = scenes + "/hard/split-cube.scene", log = (dir / "log.txt").string();
  const std::string base = std::string(SCENE_LESSON) + " --headless --size 32x24 --scene " + scene;
  const int status = std::system((base + " 2> " + log).c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) GTEST_SKIP() << "no GL context";
  ASSERT_EQ(status, 0);
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(scene + ": object 'cube': welded 24 vertices into 8 (vertices split at seams)\n"),
            std::string::npos)
      << text;
  ASSERT_EQ(std::system((base + " --quiet 2> " + log).c_str()), 0);
  std::ifstream quiet(log);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(quiet)), std::istreambuf_iterator<char>()), "");
}
