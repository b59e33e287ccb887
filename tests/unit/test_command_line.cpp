// The shared command line: names scripts rely on, and one clear error for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

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
                                             {"--time", "nan"},
                                             {"--time", "inf"},
                                             {"--time", "1e300"},
                                             {"--time", "999999", "--frames", "120"},
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

TEST(CommandLine, OptionsTakeTheirDeclaredRange) {
  LessonInfo i = info();
  i.options.push_back({"slices", 'S', "at least 4", 24, 256, 4});
  EXPECT_EQ(optionsFor(i, "", {{"slices", 4}}).back().value, 4);
  EXPECT_THROW(optionsFor(i, "", {{"slices", 3}}), UsageError);
  EXPECT_THROW(optionsFor(i, "", {{"slices", 257}}), UsageError);
  EXPECT_NE(helpText(i, "lesson").find("slices [S] 4..256"), std::string::npos);
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

TEST(CommandLine, SceneFlagsAreParsedAndListedOnlyForSceneLessons) {
  const CommandLine cl = parse({"--scene", "a.scene", "--mask-out", "masks"});
  EXPECT_EQ(cl.scene, std::filesystem::path("a.scene"));
  EXPECT_EQ(cl.maskOut, std::filesystem::path("masks"));
  EXPECT_FALSE(parse({}).scene.has_value());
  EXPECT_THROW(parse({"--scene"}), UsageError);
  LessonInfo shadows = info();
  shadows.shadows = true;
  const std::string plain = helpText(shadows, "lesson"), scenes = helpText(shadows, "lesson", true);
  for (const char* s : {"--scene FILE", "--mask-out DIR"}) {
    EXPECT_EQ(plain.find(s), std::string::npos) << s;
    EXPECT_NE(scenes.find(s), std::string::npos) << s;
  }
}

// --oracle and --mask-out are listed only for a lesson that makes shadow claims.
TEST(CommandLine, ShadowFlagsAreListedOnlyForLessonsWithShadows) {
  LessonInfo shadows = info();
  shadows.shadows = true;
  for (const bool readsScenes : {false, true}) {
    const std::string without = helpText(info(), "lesson", readsScenes);
    EXPECT_EQ(without.find("--oracle"), std::string::npos);
    EXPECT_EQ(without.find("--mask-out"), std::string::npos);
    EXPECT_NE(helpText(shadows, "lesson", readsScenes).find("--oracle FILE.png"), std::string::npos);
  }
}

// A number too large for its flag is out of range, not "not a number"; for an option, its own range.
TEST(CommandLine, NumbersThatDoNotFitAreOutOfRange) {
  try {
    parse({"--set", "depth=2147483648"});
    ADD_FAILURE() << "depth=2147483648 was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("option 'depth' takes 0..3, got 2147483648"), std::string::npos)
        << e.what();
  }
  // --frames names its own range, which starts at 1.
  for (const char* n : {"99999999999", "0"}) {
    try {
      parse({"--frames", n});
      ADD_FAILURE() << n << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--frames must be between 1 and 2147483647"), std::string::npos)
          << e.what();
    }
  }
}

// A scene file's camera as an orbit camera sees what the file's eye sees: the same view matrix.
TEST(OrbitCameraOf, SeesFromTheScenesEyeTowardsItsTarget) {
  SceneCamera c;
  c.eye = {3.0f, -2.0f, -4.0f};
  c.target = {0.5f, 1.0f, 1.0f};
  c.fovyDeg = 60.0f;
  c.nearPlane = 0.25f;
  const OrbitCamera o = orbitCameraOf(c);
  const glm::mat4 expected = glm::lookAt(c.eye, c.target, glm::vec3(0, 1, 0));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(o.view()[i][j], expected[i][j], 1e-5f) << i << "," << j;
  EXPECT_NEAR(glm::length(o.eye() - c.eye), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(o.fovyDeg, 60.0f);
  EXPECT_FLOAT_EQ(o.nearPlane, 0.25f);
  EXPECT_TRUE(std::isinf(o.farPlane));
  EXPECT_FALSE(o.orthographic);

  c.orthographic = true;
  c.orthoHeight = 7.0f;
  c.farPlane = 50.0f;
  c.mirrored = true;
  const OrbitCamera ortho = orbitCameraOf(c);
  EXPECT_TRUE(ortho.orthographic);
  EXPECT_FLOAT_EQ(ortho.orthoHeight, 7.0f);
  EXPECT_FLOAT_EQ(ortho.farPlane, 50.0f);
  EXPECT_LT(glm::determinant(ortho.view()), 0.0f) << "mirrored";
  EXPECT_GT(glm::determinant(o.view()), 0.0f);
}

TEST(OrbitCameraOf, RefusesWhatAnOrbitCameraCannotBe) {
  SceneCamera c;
  c.up = {1, 0, 0};
  EXPECT_THROW(orbitCameraOf(c), std::invalid_argument);
  c = SceneCamera{};
  c.eye = c.target;
  EXPECT_THROW(orbitCameraOf(c), std::invalid_argument);
  c.eye = c.target + glm::vec3(0, 5, 0);
  EXPECT_THROW(orbitCameraOf(c), std::invalid_argument) << "straight above: +y cannot be up";
}

// An orbit camera placed by its eye sees from that eye towards the target, whichever quadrant and
// height the eye is in, and leaves the rest of the camera at its defaults.
TEST(OrbitCameraFrom, SeesFromTheEyeTowardsTheTarget) {
  const glm::vec3 target(0.5f, 1.0f, -1.0f);
  for (const glm::vec3 eye : {glm::vec3(3.0f, -2.0f, -4.0f), glm::vec3(-2.0f, 4.0f, 3.0f),
                              glm::vec3(-1.0f, 0.2f, -6.0f), glm::vec3(4.0f, 1.0f, 0.5f)}) {
    const OrbitCamera o = orbitCameraFrom(eye, target);
    EXPECT_NEAR(glm::length(o.eye() - eye), 0.0f, 1e-5f) << eye.x << " " << eye.y << " " << eye.z;
    const glm::mat4 expected = glm::lookAt(eye, target, glm::vec3(0, 1, 0));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(o.view()[i][j], expected[i][j], 1e-5f) << i << "," << j;
    EXPECT_EQ(o.target, target);
    EXPECT_FLOAT_EQ(o.fovyDeg, OrbitCamera{}.fovyDeg);
    EXPECT_FLOAT_EQ(o.farPlane, OrbitCamera{}.farPlane);
  }
}

TEST(ShaderLog, MesaAndNvidiaLinesBecomeFileLine) {
  EXPECT_EQ(formatCompileLog("s.frag", "0:12(5): error: `x' undeclared\n0:12(5): error: more\n"),
            "s.frag:12: error: `x' undeclared (and 1 more)");
  EXPECT_EQ(formatCompileLog("s.vert", "0(7) : error C1008: undefined variable \"x\"\n"),
            "s.vert:7: error C1008: undefined variable \"x\"");
  EXPECT_EQ(formatCompileLog("s.vert", ""), "s.vert: compile failed with an empty log");
}

TEST(ShaderLog, AngleLinesBecomeFileLine) {
  EXPECT_EQ(formatCompileLog("s.frag", "ERROR: 0:9: 'x' : undeclared identifier\nERROR: 0:9: '=' : dimension mismatch\n"),
            "s.frag:9: 'x' : undeclared identifier (and 1 more)");
}

// The browser's one rule: a 330 core shader becomes GLSL ES 3.00 with its line numbers kept.
TEST(ShaderForWebGl, VersionLineBecomesEsWithPrecisionAndLineKept) {
  EXPECT_EQ(glslForWebGl("#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n").source,
            "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n#line 2\n"
            "out vec4 c;\nvoid main() { c = vec4(1.0); }\n");
}

TEST(ShaderForWebGl, ClipDistanceAsksForTheExtension) {
  const std::string es = glslForWebGl("#version 330 core\nvoid main() { gl_ClipDistance[0] = 1.0; }\n").source;
  EXPECT_EQ(es.substr(0, es.find("precision")),
            "#version 300 es\n#extension GL_ANGLE_clip_cull_distance : enable\n");
}

// Without WEBGL_clip_cull_distance the planes become an output, and the fragment shader of the same
// program discards by them on main's line, so that the line numbers stay.
TEST(ShaderForWebGl, ClipDistanceWithoutTheExtensionBecomesADiscard) {
  const WebGlShader vs = glslForWebGl(
      "#version 330 core\nvoid main() {\n  gl_ClipDistance[0] = 1.0;\n  gl_ClipDistance[1] = -1.0;\n}\n", false);
  EXPECT_EQ(vs.clipPlanes, 2);
  EXPECT_EQ(vs.source.find("#extension"), std::string::npos);
  EXPECT_EQ(vs.source.substr(vs.source.find("precision highp sampler2D;\n") + 27),
            "out float stencil_clipDistance[2];\n#line 2\nvoid main() {\n  stencil_clipDistance[0] = 1.0;\n"
            "  stencil_clipDistance[1] = -1.0;\n}\n");
  const WebGlShader fs = glslForWebGl("#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n", false, 2);
  EXPECT_EQ(fs.source.substr(fs.source.find("precision highp sampler2D;\n") + 27),
            "in float stencil_clipDistance[2];\n#line 2\nout vec4 c;\nvoid main() { if (stencil_clipDistance[0] < 0.0 || "
            "stencil_clipDistance[1] < 0.0) discard; c = vec4(1.0); }\n");
  // With the extension, nothing changes but the extension line.
  EXPECT_EQ(glslForWebGl("#version 330 core\nvoid main() { gl_ClipDistance[0] = 1.0; }\n").clipPlanes, 0);
}

// A desktop extension asked for where present is dropped (WebGL has none of the ARB ones, and GLSL ES
// wants no #extension after the precision lines); its line stays, blank. One that is required stays,
// so the compile error names it.
TEST(ShaderForWebGl, DesktopExtensionsAskedForWherePresentAreDropped) {
  const std::string es = glslForWebGl(
      "#version 330 core\n#extension GL_ARB_shader_stencil_export : enable\n"
      "#extension GL_ARB_shader_image_load_store : require\nvoid main() {}\n").source;
  EXPECT_EQ(es.substr(es.find("#line 2\n") + 8), "\n#extension GL_ARB_shader_image_load_store : require\nvoid main() {}\n");
}

TEST(ShaderForWebGl, IntegerSamplersGetAPrecision) {
  const std::string es = glslForWebGl("#version 330 core\nuniform usampler2D ids;\nvoid main() {}\n").source;
  EXPECT_EQ(es.substr(es.find("precision highp sampler2D;\n") + 27), "precision highp usampler2D;\n#line 2\n"
            "uniform usampler2D ids;\nvoid main() {}\n");
}

// GLSL ES has no uniform initialisers: the value is kept for the Program to set, the line stays.
TEST(ShaderForWebGl, UniformInitialisersBecomeDefaults) {
  const WebGlShader es = glslForWebGl(
      "#version 330 core\nuniform float radius = 1e30;  // bounds\nuniform int twoSided = 0;\nuniform vec3 c;\n");
  EXPECT_EQ(es.source.substr(es.source.find("#line 2\n") + 8),
            "uniform float radius;  // bounds\nuniform int twoSided;\nuniform vec3 c;\n");
  EXPECT_EQ(es.defaults, (std::vector<UniformDefault>{{"radius", false, 1e30}, {"twoSided", true, 0}}));
}

TEST(ShaderForWebGl, OtherSourcesAreLeftAsTheyAre) {
  EXPECT_EQ(glslForWebGl("#version 450 core\nvoid main() {}\n").source, "#version 450 core\nvoid main() {}\n");
  EXPECT_EQ(glslForWebGl("#version 330 core compatibility\nvoid main() {}\n").source,
            "#version 330 core compatibility\nvoid main() {}\n");
  EXPECT_EQ(glslForWebGl("#version 330 core").source, "#version 330 core");
}

// --list-variants is read by CMake one line a variant (tests/variants.cmake): a help that breaks
// the line would make a test of half a sentence.
TEST(CommandLine, VariantListIsOneLineAVariant) {
  LessonInfo i = info();
  EXPECT_EQ(variantList(i), "default\tas declared\noff\tstencil off\n");
  i.variants[1].help = "two\nlines";
  EXPECT_THROW(variantList(i), std::logic_error);
  i.variants[1] = {"with space", "help", {}};
  EXPECT_THROW(variantList(i), std::logic_error);
}

// --shadow-span as the pages write it (9:00-17:00) and zero-padded; a step longer than the span is
// refused, since its one step would count for more time than the span has.
TEST(CommandLine, ShadowSpanTakesHMmOrHhMm) {
  const CommandLine a = parse({"--shadow-hours", "h.png", "--shadow-span", "9:00-17:30"});
  EXPECT_EQ(a.shadowFrom, 9 * 60);
  EXPECT_EQ(a.shadowTo, 17 * 60 + 30);
  const CommandLine b =
      parse({"--shadow-hours", "h.png", "--shadow-span", "06:20-19:40", "--shadow-step", "20"});
  EXPECT_EQ(b.shadowFrom, 6 * 60 + 20);
  EXPECT_EQ(b.shadowTo, 19 * 60 + 40);
  EXPECT_THROW(parse({"--shadow-hours", "h.png", "--shadow-span", "900-1700"}), UsageError);
  EXPECT_THROW(parse({"--shadow-hours", "h.png", "--shadow-span", "9:00-10:00", "--shadow-step", "61"}),
               UsageError);
}
