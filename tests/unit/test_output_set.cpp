// A run's outputs written as one (gl/image.h's OutputSet): all of them or none, the files already
// there kept when the set fails, no name left but the targets, links at a target replaced rather
// than followed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "gl/errors.h"
#include "gl/image.h"

using namespace stencil;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("stencil-unit-outputs-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(OutputSet, WritesEveryFileAndItsFoldersAndNothingElse) {
  const fs::path dir = freshDir("all");
  OutputSet set;
  set.add(dir / "a.txt", "alpha");
  set.add(dir / "deep/er/b.txt", "beta");
  set.add(dir / "a.txt", "again");  // staged twice: the later wins
  EXPECT_EQ(set.size(), 2u);
  set.commit();
  EXPECT_TRUE(set.empty());
  EXPECT_EQ(contents(dir / "a.txt"), "again");
  EXPECT_EQ(contents(dir / "deep/er/b.txt"), "beta");
  EXPECT_EQ(entries(dir), 4u);  // a.txt, deep, deep/er, deep/er/b.txt: no temporary name left
}

TEST(OutputSet, AFileThatCannotBeWrittenLeavesNoneAndKeepsWhatWasThere) {
  const fs::path dir = freshDir("none");
  { std::ofstream(dir / "old.txt") << "before"; }
  { std::ofstream(dir / "blocker") << "a file where a folder is needed"; }
  OutputSet set;
  set.add(dir / "old.txt", "after");
  set.add(dir / "new/one.txt", "one");
  set.add(dir / "blocker/two.txt", "two");  // its folder cannot be made
  try {
    set.commit();
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("could not write " + (dir / "blocker/two.txt").string()), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(contents(dir / "old.txt"), "before");
  EXPECT_FALSE(fs::exists(dir / "new")) << "the folder the failed set made is removed";
  EXPECT_EQ(entries(dir), 2u);  // old.txt and blocker, nothing else
}

TEST(OutputSet, ALinkAtTheTargetIsReplacedNotFollowed) {
  const fs::path dir = freshDir("link");
  { std::ofstream(dir / "victim.txt") << "victim"; }
  fs::create_symlink(dir / "victim.txt", dir / "out.txt");
  writeFile(dir / "out.txt", "written");
  EXPECT_EQ(contents(dir / "victim.txt"), "victim");
  EXPECT_FALSE(fs::is_symlink(dir / "out.txt"));
  EXPECT_EQ(contents(dir / "out.txt"), "written");
}

TEST(OutputSet, ANameBeyondTheSystemsLimitIsRefusedUpFront) {
  const fs::path dir = freshDir("long");
  EXPECT_NO_THROW(checkOutputFile(dir / (std::string(251, 'n') + ".png"), "--out"));
  EXPECT_THROW(checkOutputFile(dir / (std::string(252, 'n') + ".png"), "--out"), OutputError);
  EXPECT_THROW(checkOutputFolder(dir / std::string(256, 'd'), "--passes"), OutputError);
  writeFile(dir / (std::string(251, 'n') + ".png"), "fits");  // the temporary name is not longer
  EXPECT_EQ(entries(dir), 1u);
}

TEST(OutputSet, FoldersWrittenWithDotsAreMadeAsTheyRead) {
  const fs::path dir = freshDir("dots");
  OutputSet set;
  set.add(dir / "nd/./a.txt", "a");
  set.add(dir / "nd/x/../b.txt", "b");
  set.commit();
  EXPECT_EQ(contents(dir / "nd/a.txt"), "a");
  EXPECT_EQ(contents(dir / "nd/b.txt"), "b");
  EXPECT_FALSE(fs::exists(dir / "nd/x")) << "x is only a step of the name";
  EXPECT_EQ(entries(dir), 3u);  // nd, nd/a.txt, nd/b.txt
}
