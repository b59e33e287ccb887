// The shared command line: names scripts rely on, and one clear error for bad input.
#include <gtest/gtest.h>

#include "gl/errors.h"
#include "gl/options.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

LessonInfo info() {
  LessonInfo i;
  i.id = "99-test";
  i.title = "test";
  i.options = {{"stencil", 'T', "on/off", 1}, {"depth", 'D', "0..3", 2, 3}};
  i.variants = {{"default", "as declared", {}}, {"off", "stencil off", {{"stencil", 0}}}};
  i.passes = {"a"};
  return i;
}

CommandLine parse(std::vector<std::string> args) {
  args.insert(args.begin(), "lesson");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return parseCommandLine(info(), static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST(CommandLine, ParsesTheDocumentedFlags) {
  const CommandLine cl = parse({"--headless",
                                "--backend",
                                "egl",
                                "--size",
                                "320x240",
                                "--time",
                                "1.5",
                                "--frames",
                                "3",
                                "--variant",
                                "off",
                                "--set",
                                "depth=3",
                                "--out",
                                "a.png",
                                "--stencil-out",
                                "s.png",
                                "--stencil-view",
                                "bits",
                                "--passes",
                                "p",
                                "--stats",
                                "--golden",
                                "g",
                                "--stencil-bits",
                                "0"});
  EXPECT_TRUE(cl.headless);
  EXPECT_EQ(cl.backend, Backend::Egl);
  EXPECT_EQ(cl.width, 320);
  EXPECT_EQ(cl.height, 240);
  EXPECT_DOUBLE_EQ(cl.time, 1.5);
  EXPECT_EQ(cl.frames, 3);
  EXPECT_EQ(cl.variant, "off");
  EXPECT_TRUE(cl.stencilBitPlanes);
  EXPECT_TRUE(cl.stats);
  EXPECT_EQ(cl.stencilBits, 0);
  EXPECT_EQ(cl.out->string(), "a.png");
}

TEST(CommandLine, BadInputThrowsUsageError) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"--bogus"},
                                             {"--size", "640"},
                                             {"--size", "0x10"},
                                             {"--time", "soon"},
                                             {"--frames", "0"},
                                             {"--backend", "vulkan"},
                                             {"--variant", "nope"},
                                             {"--set", "depth=4"},
                                             {"--set", "nope=1"},
                                             {"--set", "depth"},
                                             {"--stencil-bits", "4"},
                                             {"--update-golden"},
                                             {"--headless", "--backend", "window"},
                                             {"--out"}})
    EXPECT_THROW(parse(args), UsageError) << args.front();
}

TEST(CommandLine, VariantSettingsThenSetOverrides) {
  auto options = optionsFor(info(), "off", {{"depth", 1}});
  EXPECT_EQ(options[0].value, 0);  // from the variant
  EXPECT_EQ(options[1].value, 1);  // from --set
  options = optionsFor(info(), "", {});
  EXPECT_EQ(options[0].value, 1);  // the first variant keeps the declared defaults
  EXPECT_EQ(options[1].value, 2);
}

TEST(CommandLine, HelpNamesEveryFlagAndVariant) {
  const std::string help = helpText(info(), "lesson");
  for (const char* s :
       {"--headless", "--backend", "--size", "--time", "--frames", "--variant", "--list-variants", "--out",
        "--stencil-out", "--passes", "--stats", "--golden", "--update-golden", "depth [D]", "off"})
    EXPECT_NE(help.find(s), std::string::npos) << s;
}

TEST(ShaderLog, MesaAndNvidiaLinesBecomeFileLine) {
  EXPECT_EQ(formatCompileLog("s.frag", "0:12(5): error: `x' undeclared\n0:12(5): error: more\n"),
            "s.frag:12: error: `x' undeclared (and 1 more)");
  EXPECT_EQ(formatCompileLog("s.vert", "0(7) : error C1008: undefined variable \"x\"\n"),
            "s.vert:7: error C1008: undefined variable \"x\"");
  EXPECT_EQ(formatCompileLog("s.vert", ""), "s.vert: compile failed with an empty log");
}
