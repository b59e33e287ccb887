// Runs a lesson binary headless at the golden size and time and reads back what it wrote:
// the colour image, the raw stencil values and, when asked, the --stats JSON.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "../lesson_stats.h"
#include "gl/image.h"

namespace stencil::testing {

struct LessonRun {
  Image colour, stencil;
  LessonStats stats;  // empty unless asked for

  // A count under "counts" in the --stats JSON; -1 when absent.
  long long count(const std::string& name) const { return stats.count(name); }
};

// Each test writes into its own folder: ctest runs the tests of a file in parallel. Returns
// nothing when no GL context can be made (exit 77), so the caller can skip. The run must exit
// with `exitCode`: 1 where the lesson's own check (an oracle option) is to find the picture wrong.
inline std::optional<LessonRun> runLesson(const std::string& binary, const std::string& name,
                                          const std::string& args, bool stats = false, int exitCode = 0) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("stencil-" + std::filesystem::path(binary).filename().string()) /
                                    (std::string(test->test_suite_name()) + "." + test->name());
  std::filesystem::create_directories(dir);
  const auto colour = dir / (name + ".png"), stencil = dir / (name + "-stencil.png"),
             json = dir / (name + ".json");
  const std::string command = binary + " --headless --quiet --size 320x240 --time 1 " + args + " --out " +
                              colour.string() + " --stencil-out " + stencil.string() +
                              (stats ? " --stats > " + json.string() : "");
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) return std::nullopt;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == exitCode) << command << ": exit " << status;
  LessonRun run{readPng(colour, 4), readPng(dir / (name + "-stencil.raw.png"), 1), {}};
  if (stats) run.stats = LessonStats::read(json);
  return run;
}

// Whether pixel i differs between two colour images by more than `tolerance` in a channel.
inline bool differs(const Image& a, const Image& b, std::size_t i, int tolerance = 5) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])) > tolerance) return true;
  return false;
}

}  // namespace stencil::testing
