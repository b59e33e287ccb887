// Scene files (docs/scenes.md): what a good file gives, one clear FILE:LINE message for each
// kind of mistake, OBJ meshes with what breaks the shadow-volume requirements, and every file
// under tests/scenes/hard read without error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <regex>
#include <string>

#include "geometry/raycast.h"
#include "geometry/scene.h"
#include "geometry/shadow_volume.h"

namespace {

using namespace stencil;

const std::filesystem::path scenes = SCENES_DIR;

std::string errorOf(const std::string& text, const std::filesystem::path& file = "test.scene") {
  try {
    parseScene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

bool mentions(const CasterReport& report, const std::string& text) {
  return std::any_of(report.messages.begin(), report.messages.end(),
                     [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

void expectNear(const glm::mat4& a, const glm::mat4& b) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-5f) << "column " << i << " row " << j;
}

const char* const header =
    "camera eye 0 2 5 target 0 0 0 near 0.1\n"
    "light point 0 4 0\n";

TEST(SceneFile, AGoodFile) {
  const Scene s = parseScene(
      "# a comment line\n"
      "camera eye 1 2 3 target 0 1 0 up 0 1 0 fovy 60 near 0.5 far 80  # trailing comment\n"
      "ambient 0.2 0.25 0.3\n"
      "\n"
      "light point 1 5 2 color 1 0.5 0.25 radius 12\n"
      "light directional 0 2 0\n"
      "object ground plane half 6 divisions 3\n"
      "  casts no\n"
      "  color 0.5 0.5 0.5\n"
      "object ball sphere radius 0.5 slices 12 stacks 6\n"
      "\tscale 2\n"
      "  rotate 90 0 0 1\n"
      "  translate 1 2 3\n"
      "  spin 45 1 0 0\n"
      "  bob 0.25\n"
      "  receives no\n"
      "object crate box half 1 2 3\n"
      "object can cylinder radius 0.3 height 1 slices 10\n"
      "object hat cone radius 0.3 height 1 slices 10\n"
      "object ring torus major 1 minor 0.2 segments 10 sides 6\n"
      "object flight stairs steps 4 width 2 rise 0.25 run 0.5\n",
      "dir/good.scene");
  EXPECT_EQ(s.file, std::filesystem::path("dir/good.scene"));
  EXPECT_EQ(s.camera.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.camera.target, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(s.camera.fovyDeg, 60.0f);
  EXPECT_FLOAT_EQ(s.camera.nearPlane, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.farPlane, 80.0f);
  EXPECT_FALSE(s.camera.orthographic);
  EXPECT_FALSE(s.camera.mirrored);
  EXPECT_EQ(s.ambient, glm::vec3(0.2f, 0.25f, 0.3f));

  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].position, glm::vec4(1, 5, 2, 1));
  EXPECT_EQ(s.lights[0].colour, glm::vec3(1, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(s.lights[0].radius, 12.0f);
  EXPECT_EQ(s.lights[1].position, glm::vec4(0, 1, 0, 0)) << "a unit direction towards the light";
  EXPECT_EQ(s.lights[1].colour, glm::vec3(1.0f));
  EXPECT_TRUE(std::isinf(s.lights[1].radius));

  ASSERT_EQ(s.objects.size(), 7u);
  const SceneObject& ground = s.objects[0];
  EXPECT_EQ(ground.name, "ground");
  EXPECT_EQ(ground.mesh.triangleCount(), 2u * 3 * 3);
  EXPECT_FALSE(ground.casts);
  EXPECT_TRUE(ground.receives);
  EXPECT_EQ(ground.colour, glm::vec3(0.5f));
  EXPECT_TRUE(ground.caster.mesh.positions.empty()) << "only casters are prepared";

  const SceneObject& ball = s.objects[1];
  EXPECT_EQ(ball.mesh.triangleCount(), 2u * 12 * 5);
  EXPECT_TRUE(ball.casts);
  EXPECT_FALSE(ball.receives);
  // Each transform line applies after the ones above it.
  const glm::mat4 expected = glm::translate(glm::mat4(1), {1, 2, 3}) *
                             glm::rotate(glm::mat4(1), glm::radians(90.0f), {0, 0, 1}) *
                             glm::scale(glm::mat4(1), glm::vec3(2));
  expectNear(ball.model, expected);
  EXPECT_FLOAT_EQ(ball.spinDegPerSecond, 45.0f);
  EXPECT_EQ(ball.spinAxis, glm::vec3(1, 0, 0));
  EXPECT_FLOAT_EQ(ball.bob, 0.25f);
  EXPECT_TRUE(ball.caster.report.closedManifold());
  EXPECT_FALSE(ball.caster.mesh.positions.empty());

  const SceneObject& crate = s.objects[2];
  EXPECT_EQ(crate.mesh.triangleCount(), 12u);
  const auto [lo, hi] = std::minmax_element(crate.mesh.positions.begin(), crate.mesh.positions.end(),
                                            [](const glm::vec3& a, const glm::vec3& b) { return a.z < b.z; });
  EXPECT_FLOAT_EQ(lo->z, -3.0f);
  EXPECT_FLOAT_EQ(hi->z, 3.0f);
  EXPECT_EQ(crate.caster.report.weldedVertices, 8u);
  EXPECT_EQ(s.objects[3].mesh.triangleCount(), 4u * 10);
  EXPECT_EQ(s.objects[4].mesh.triangleCount(), 2u * 10);
  EXPECT_EQ(s.objects[5].mesh.triangleCount(), 2u * 10 * 6);
  EXPECT_EQ(s.objects[6].mesh.triangleCount(), 12u * 4);
  for (const SceneObject& o : s.objects)
    if (o.casts) {
      EXPECT_TRUE(o.caster.report.closedManifold()) << o.name;
    }
}

// The example at the top of docs/scenes.md reads (its OBJ model replaced by one that exists).
// A sun light: directional, towards where the sun stands at that place and local time.
TEST(SceneFile, ASunLightStandsWhereTheSunDoes) {
  const Scene scene = parseScene(
      std::string(header) + "light sun 48.2 16.37 2025-09-18 12:00 +2 color 1 1 0.9\n" + "object a box\n",
      "test.scene");
  ASSERT_EQ(scene.lights.size(), 2u);
  const SceneLight& sun = scene.lights[1];
  ASSERT_TRUE(sun.sun);
  EXPECT_EQ(sun.position.w, 0.0f);
  EXPECT_DOUBLE_EQ(sun.sun->place.latitudeDeg, double(48.2f));
  EXPECT_EQ(sun.sun->time.hour, 12);
  EXPECT_EQ(sun.sun->time.zoneHours, 2.0);
  const SunPosition p = sunPosition(sun.sun->place, sun.sun->time);
  const glm::vec3 expected = sunDirection(p.elevationDeg, p.azimuthDeg);
  EXPECT_EQ(glm::vec3(sun.position), expected);
  // Near noon (12:00 CEST is 10:00 UT, the sun at 16.37 E culminates about 10:50 UT): south-east, and
  // 90 - 48.2 + its declination (+1.8 degrees on 18 September) high at most.
  EXPECT_GT(sun.position.x, 0.0f);
  EXPECT_GT(sun.position.z, 0.0f);
  EXPECT_GT(p.elevationDeg, 35.0);
  EXPECT_LT(p.elevationDeg, 90.0 - 48.2 + 1.9);
  EXPECT_FALSE(scene.lights[0].sun);
}

// A sun below the horizon lights nothing: refused for a still picture, read for a shadow profile
// (--shadow-hours moves the sun; its steps at night are night, not shadow), pointing below.
TEST(SceneFile, ASunBelowTheHorizonIsReadOnlyForAShadowProfile) {
  const std::string text = std::string(header) + "light sun 48.2 16.37 2025-09-18 21:00 2\nobject a box\n";
  EXPECT_THROW(parseScene(text, "test.scene"), SceneError);
  const Scene scene = parseScene(text, "test.scene", readObjFile, true);
  ASSERT_EQ(scene.lights.size(), 2u);
  ASSERT_TRUE(scene.lights[1].sun);
  EXPECT_EQ(scene.lights[1].sun->time.hour, 21);
  EXPECT_EQ(scene.lights[1].position.w, 0.0f);
  EXPECT_LT(scene.lights[1].position.y, 0.0f);
}

TEST(SceneFile, TheDocumentedExampleReads) {
  std::ifstream in(std::filesystem::path(DOCS_DIR) / "scenes.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string fence = "```text\n";  // the page's first block: the example
  const auto begin = doc.find(fence);
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("```", begin + fence.size());
  ASSERT_NE(end, std::string::npos);
  std::string example = doc.substr(begin + fence.size(), end - begin - fence.size());
  const std::string model = "models/bunny.obj";
  ASSERT_NE(example.find(model), std::string::npos);
  example.replace(example.find(model), model.size(), "meshes/split-cube.obj");
  const Scene s = parseScene(example, scenes / "example.scene");
  EXPECT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.objects.size(), 3u);
}

TEST(SceneFile, ParametersHaveDefaultsAndTheOrthographicMirroredCamera) {
  const Scene s = parseScene(
      "camera eye 0 5 5 target 0 0 0 near 1 far 30 orthographic 8 mirrored\n"
      "light directional 1 1 0 color 0.5 0.5 0.5\n"
      "object a sphere\n",
      "x.scene");
  EXPECT_TRUE(s.camera.orthographic);
  EXPECT_FLOAT_EQ(s.camera.orthoHeight, 8.0f);
  EXPECT_TRUE(s.camera.mirrored);
  EXPECT_FLOAT_EQ(s.camera.fovyDeg, 45.0f);
  EXPECT_EQ(s.ambient, glm::vec3(0.1f));
  EXPECT_NEAR(glm::length(glm::vec3(s.lights[0].position)), 1.0f, 1e-6f);
  EXPECT_EQ(s.objects[0].mesh.triangleCount(), 2u * 32 * 15);
  EXPECT_EQ(s.objects[0].model, glm::mat4(1.0f));
}

TEST(SceneFile, TheOracleSeesTheObjectsWhereTheyAreAtThatTime) {
  const Scene s = parseScene(
      std::string(header) + "object ground plane\n  casts no\nobject ball sphere\n  bob 0.5\n  receives no\n",
      "x.scene");
  const std::vector<OracleObject> objects = oracleObjects(s, 2.0);
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].mesh, &s.objects[0].mesh);
  EXPECT_FALSE(objects[0].casts);
  EXPECT_TRUE(objects[0].receives);
  EXPECT_TRUE(objects[1].casts);
  EXPECT_FALSE(objects[1].receives);
  EXPECT_FLOAT_EQ(objects[1].model[3][1], 0.5f * std::sin(2.0f));
  EXPECT_EQ(objects[1].model, s.objects[1].modelAt(2.0));
}

TEST(SceneFile, EveryMistakeIsOneLineWithFileLineAndWhatWasExpected) {
  const std::string h = header;
  const struct {
    std::string text, message;
  } cases[] = {
      {h + "lamp 1 2 3\n",
       "test.scene:3: unknown keyword 'lamp'; expected camera, ambient, light, object or csg"},
      {"  translate 1 2 3\n" + h,
       "test.scene:1: an indented line is an object's setting, and no object line"},
      {h + "object a box\nlight point 1 2 3\n  translate 1 2 3\n",
       "test.scene:5: an indented line is an object's setting, and no object line is above it"},
      {h + "object a box half 1 2\n", "test.scene:3: expected one or three numbers after half, got 2"},
      {h + "object a sphere slices 8 9\n", "test.scene:3: expected one number after slices, got 2"},
      {"camera eye 0 2 5 target 0 0 0\nlight point 0 4 0\nobject a box\n",
       "test.scene:1: expected the camera's eye, target and near"},
      {"camera eye 0 2 x target 0 0 0 near 1\n",
       "test.scene:1: expected the eye z (a finite number), got 'x'"},
      {"camera eye 0 2 5 target 0 0 0 near 1 zoom 2\n", "test.scene:1: unknown camera setting 'zoom'"},
      {"camera eye 0 2 5 target 0 0 0 near 1 up 1 0 0\n", "test.scene:1: expected up 0 1 0"},
      {"camera eye 0 2 5 target 0 0 0 near 1 orthographic 5\n",
       "test.scene:1: expected far with orthographic"},
      {"camera eye 0 2 5 target 0 0 0 near 1 far 0.5\n", "test.scene:1: expected far beyond near"},
      {"camera eye 0 5 0 target 0 0 0 near 1\n", "test.scene:1: expected the eye off the vertical"},
      {"camera eye 0 2 5 target 0 0 0 near -1\n",
       "test.scene:1: expected the near plane's distance greater than 0"},
      {"camera eye 0 2 5 target 0 0 0 near 1 near 2\n", "test.scene:1: camera setting 'near' given twice"},
      {h + "camera eye 0 2 5 target 0 0 0 near 1\n", "test.scene:3: a second camera line"},
      {h + "light spot 1 2 3\n",
       "test.scene:3: expected the light's type (point, directional or sun), got 'spot'"},
      {h + "light sun 91 16 2025-09-18 12:00 2\n",
       "test.scene:3: expected a latitude of -90 to 90 degrees, got 91"},
      {h + "light sun 48.2 -181 2025-09-18 12:00 2\n",
       "test.scene:3: expected a longitude of -180 to 180 degrees, got -181"},
      {h + "light sun 48.2 16 2025-9-18 12:00 2\n",
       "test.scene:3: expected a date YYYY-MM-DD and a local time HH:MM, got '2025-9-18 12:00'"},
      {h + "light sun 48.2 16 2025-09-18 noon 2\n",
       "test.scene:3: expected a date YYYY-MM-DD and a local time HH:MM, got '2025-09-18 noon'"},
      {h + "light sun 48.2 16 2025-02-29 12:00 2\n",
       "test.scene:3: expected a date and time that exist: day 29 does not exist in month 2 of 2025"},
      {h + "light sun 48.2 16 2025-09-18 25:00 2\n",
       "test.scene:3: expected a date and time that exist: the time must be 00:00 to 23:59:59"},
      {h + "light sun 48.2 16 2025-09-18 12:00 15\n",
       "test.scene:3: expected a date and time that exist: the time zone must be -14 to +14 hours"},
      {h + "light sun 48.2 16 2025-09-18 12:00\n", "test.scene:3: expected the time zone in hours from UTC"},
      {h + "light sun 48.2 16 2025-09-18 12:00 +-2\n",
       "test.scene:3: expected the time zone in hours from UTC (+2 for CEST), got '+-2'"},
      {h + "light sun 48.2 16 2025-09-18 12:00 CEST\n",
       "test.scene:3: expected the time zone in hours from UTC (+2 for CEST), got 'CEST'"},
      {h + "light sun 48.2 16 2025-09-18 23:00 2\n", "test.scene:3: the sun is below the horizon then"},
      {h + "light sun 48.2 16 2025-09-18 12:00 2 radius 3\n",
       "test.scene:3: a directional light has no radius"},
      {h + "light directional 0 0 0\n",
       "test.scene:3: expected the direction towards the light to be a direction"},
      {h + "light directional 0 1 0 radius 5\n", "test.scene:3: a directional light has no radius"},
      {h + "light point 0 1 0 color 1 1\n", "test.scene:3: expected the colour's B at the end of the line"},
      {h + "light point 0 1 0 color 1 -1 1\n", "test.scene:3: expected a colour R G B of 0 or more each"},
      {h + "ambient 1 1 1 1\n", "test.scene:3: unexpected '1' at the end of the line"},
      {h + "object a blob\n", "test.scene:3: unknown shape 'blob'; expected plane, box, sphere"},
      {h + "object a sphere radius 0\n", "test.scene:3: expected radius greater than 0, got 0"},
      {h + "object a sphere slices 2\n",
       "test.scene:3: expected slices to be a whole number, at least 3 and at most 16777216, got 2"},
      {h + "object a sphere slices 1e12\n", "test.scene:3: expected slices to be a whole number"},
      {h + "object a sphere radius 1 radius 2\n", "test.scene:3: parameter 'radius' given twice"},
      {h + "object a sphere size 2\n",
       "test.scene:3: unknown parameter 'size' for sphere; expected radius, slices, stacks"},
      {h + "object a torus major 1 minor 1\n",
       "test.scene:3: expected the torus's minor radius less than its major"},
      {h + "object a box\nobject a box\n", "test.scene:4: a second object named 'a'"},
      {h + "object a box\n  scale 0\n", "test.scene:4: expected a scale other than 0"},
      {h + "object a box\n  casts maybe\n",
       "test.scene:4: expected whether it casts shadows (yes or no), got 'maybe'"},
      {h + "object a box\n  wobble 1\n", "test.scene:4: unknown object setting 'wobble'; expected translate"},
      {h + "object a box\n  rotate 30 0 0 0\n", "test.scene:4: expected the axis to be a direction"},
      {h + "object a box\n  translate 1 2\n",
       "test.scene:4: expected the translation z at the end of the line"},
      {h + "object a box\n  translate 1 2 nan\n",
       "test.scene:4: expected the translation z (a finite number)"},
      {h + "object a mesh\n", "test.scene:3: expected an OBJ file name after 'mesh'"},
      {h + "object a mesh missing.obj\n", "test.scene:3: cannot read mesh 'missing.obj': no such file"},
      {"camera eye 0 2 5 target 0 0 0 near 1\nobject a box\n", "test.scene:2: the scene has no light"},
      {h, "test.scene:2: the scene has no object"},
      {"light point 0 4 0\nobject a box\n", "test.scene:2: the scene has no camera line"},
  };
  for (const auto& c : cases) {
    const std::string error = errorOf(c.text);
    EXPECT_EQ(error.rfind(c.message, 0), 0u)
        << "got: " << error << "\nexpected it to start with: " << c.message;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

// Messages quote the file as printable ASCII: any other byte is written \xNN, and a long word
// is cut short.
TEST(SceneFile, MessagesArePrintable) {
  EXPECT_EQ(errorOf(std::string(header) + "l\x1b[2Jamp\x01\xff 1\n"),
            "test.scene:3: unknown keyword 'l\\x1b[2Jamp\\x01\\xff'; expected camera, ambient, light, object "
            "or csg "
            "(settings of an object are indented)");
  EXPECT_EQ(errorOf(std::string(header) + std::string(100, 'x') + "\n")
                .rfind("test.scene:3: unknown keyword '" + std::string(40, 'x') + "...';", 0),
            0u);
  EXPECT_EQ(errorOf(std::string(header) + "object caf\xc3\xa9 box\n"),
            "test.scene:3: expected the object's name in printable ASCII, got 'caf\\xc3\\xa9'");
  EXPECT_EQ(errorOf(std::string("\0\0\0\n", 4), "x\n.scene"),
            "x\\x0a.scene:1: unknown keyword '\\x00\\x00\\x00'; "
            "expected camera, ambient, light, object or csg (settings of an object are indented)");
}

// Limits keep a scene a lesson's size: lights, objects, triangles (docs/scenes.md).
TEST(SceneFile, ScenesBeyondTheLimitsAreRefusedAtTheLineThatCrossesThem) {
  std::string lights = header;
  for (std::size_t i = 1; i < kMaxSceneLights; ++i) lights += "light point 1 2 3\n";
  lights += "object a box\n";
  EXPECT_EQ(parseScene(lights, "x.scene").lights.size(), kMaxSceneLights);
  EXPECT_EQ(errorOf(lights + "light point 1 2 3\n"),
            "test.scene:19: more than 16 lights; a scene has at most 16");

  std::string objects = header;
  for (std::size_t i = 0; i < kMaxSceneObjects; ++i) objects += "object o" + std::to_string(i) + " box\n";
  EXPECT_EQ(parseScene(objects, "x.scene").objects.size(), kMaxSceneObjects);
  EXPECT_EQ(errorOf(objects + "object last box\n"),
            "test.scene:1027: more than 1024 objects; a scene has at most 1024");

  const std::string plane = std::string(header) + "object a plane divisions 707\n  casts no\n";
  EXPECT_EQ(parseScene(plane, "x.scene").objects[0].mesh.triangleCount(), 999698u);
  EXPECT_EQ(errorOf(plane + "object b sphere\n"),
            "test.scene:5: a sphere of 960 triangles; a scene holds at most 1000000 (302 left)");
  EXPECT_EQ(
      errorOf(std::string(header) + "object a torus segments 16777216 sides 16777216\n"),
      "test.scene:3: a torus of 562949953421312 triangles; a scene holds at most 1000000 (1000000 left)");
  EXPECT_EQ(errorOf(std::string(header) + "object a torus major 3e38 minor 2e38\n"),
            "test.scene:3: expected major from 1e-06 to 1e+06 scene units, got 3e+38");
}

// Each line may be within the limits and still combine with the others into a scene the float
// maths cannot carry (scene.h's kMaxSceneCoordinate, kMinSceneScale): refused at the line that
// makes it so, whatever the time (spin, bob) the lesson renders it at.
TEST(SceneFile, WhatTheTransformsMakeIsCheckedAtTheLineThatMakesIt) {
  const std::string h = std::string(header) + "object a sphere\n";
  const struct {
    std::string text, message;
  } cases[] = {
      {h + "  scale 1e30\n  scale 1e30\n",
       "test.scene:4: the transforms up to this line scale the object by 1e+30; a scene's scales lie within "
       "1e-06 to 1e+06"},
      {h + "  scale 1000\n  scale 1000\n  scale 1000\n",
       "test.scene:6: the transforms up to this line scale the object by 1e+09; a scene's scales lie within "
       "1e-06 to 1e+06"},
      {h + "  scale 1e20\n", "test.scene:4: the transforms up to this line scale the object by 1e+20; a "
                             "scene's scales lie within 1e-06 to 1e+06"},
      {h + "  scale 1e-20\n", "test.scene:4: the transforms up to this line scale the object by 1e-20; a "
                              "scene's scales lie within 1e-06 to 1e+06"},
      {h + "  scale 1 1 1e-7\n", "test.scene:4: the transforms up to this line scale the object by 1e-07 to 1; a "
                                 "scene's scales lie within 1e-06 to 1e+06"},
      {h + "  translate 3e38 0 0\n  translate 3e38 0 0\n",
       "test.scene:4: the object reaches 3e+38 from the origin; a scene lies within 1e+06 of the origin on each axis"},
      {h + "  translate 0 6e5 0\n  translate 0 6e5 0\n",
       "test.scene:5: the object reaches 1200001 from the origin; a scene lies within 1e+06 of the origin on each "
       "axis"},
      // A box's corners lie sqrt(3) half sizes from its origin: spinning, it reaches that far.
      {std::string(header) + "object a box half 1\n  scale 2000\n  translate 997000 0 0\n  spin 10\n",
       "test.scene:6: the object reaches 1000464.1 from the origin as it moves; a scene lies within 1e+06 of "
       "the origin on each axis"},
      {h + "  bob 2e6\n", "test.scene:4: the object reaches 2000001 from the origin as it moves; a scene lies "
                           "within 1e+06 of the origin on each axis"},
      {h + "  spin 1e38\n",
       "test.scene:4: a spin of 1e+38 degrees per second turns past what a float holds by 1e+06 s"},
      {std::string(header) + "light directional 1e-46 0 0\n",
       "test.scene:3: expected the direction towards the light x (a number a float holds: 0, or from about "
       "1.4e-45 to 3.4e+38 in size), got '1e-46'"},
      {std::string(header) + "object a box half 1 1 1e-40\n",
       "test.scene:3: expected half from 1e-06 to 1e+06 scene units, got 1e-40"},
      {std::string(header) + "object a box half 1e13\n",
       "test.scene:3: expected half from 1e-06 to 1e+06 scene units, got 1e+13"},
      {std::string(header) + "object a box half 0 1 1\n", "test.scene:3: expected half sizes greater than 0, got 0"},
      {std::string(header) + "object a sphere radius 1e-20\n",
       "test.scene:3: expected radius from 1e-06 to 1e+06 scene units, got 1e-20"},
      {"camera eye 0 3 1e38 target 0 0.5 0 near 0.3\n",
       "test.scene:1: expected the eye within 1e+06 of the origin on each axis, got 0 3 1e+38"},
      {"camera eye 0 3 6 target 2e6 0 0 near 0.3\n",
       "test.scene:1: expected the target within 1e+06 of the origin on each axis, got 2e+06 0 0"},
      {"camera eye 0 3 6 target 0 0 0 near 0.3\nlight point 0 1e30 0\n",
       "test.scene:2: expected the light's position within 1e+06 of the origin on each axis, got 0 1e+30 0"},
  };
  for (const auto& c : cases) EXPECT_EQ(errorOf(c.text), c.message) << c.text;
  // Within the limits: a mirror, and the largest and smallest scales.
  for (const char* fine : {"  scale -1 1 1\n", "  scale 1e5\n", "  scale 1e-5\n  scale 1 1 1\n", "  spin 1e30\n"})
    EXPECT_EQ(errorOf(h + fine), "(no error)") << fine;
}

// Directions are normalised in double: a float's squared length overflows past 1.8e19 and
// underflows below 1e-19, and neither changes which way an axis points.
TEST(SceneFile, DirectionsOfAnyFiniteLengthAreTheirDirection) {
  const std::string h = std::string(header);
  const Scene big = parseScene(h + "light directional 0 3e19 0\nlight directional 1e-30 0 0\n"
                                   "object a box\n  rotate 45 1e20 0 0\n  spin 30 0 0 -1e25\n",
                               "x.scene");
  EXPECT_EQ(big.lights[1].position, glm::vec4(0, 1, 0, 0));
  EXPECT_EQ(big.lights[2].position, glm::vec4(1, 0, 0, 0));
  expectNear(big.objects[0].model, glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(1, 0, 0)));
  EXPECT_EQ(big.objects[0].spinAxis, glm::vec3(0, 0, -1));
  EXPECT_EQ(errorOf(h + "light directional 0 0 0\n"),
            "test.scene:3: expected the direction towards the light to be a direction, got 0 0 0");
}

// A scale's three numbers are x, y and z in the order the file gives them, whichever order the
// compiler evaluates a call's arguments in (GCC and clang differ).
TEST(SceneFile, AScaleReadsXYAndZInTheFilesOrder) {
  const Scene s = parseScene(std::string(header) + "object a box\n  scale 0.8 1.6 1.2\n", "x.scene");
  expectNear(s.objects[0].model, glm::scale(glm::mat4(1.0f), glm::vec3(0.8f, 1.6f, 1.2f)));
}

// parseScene reads OBJ files through the reader it is given; the default reads the disk.
TEST(SceneFile, OBJFilesComeFromTheReaderGiven) {
  const auto reader = [](const std::filesystem::path& path) -> std::string {
    if (path == std::filesystem::path("d/t.obj"))
      return "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    throw std::runtime_error("not served");
  };
  const Scene s = parseScene(std::string(header) + "object t mesh t.obj\n", "d/x.scene", reader);
  EXPECT_EQ(s.objects[0].mesh.triangleCount(), 4u);
  EXPECT_EQ(s.objects[0].line, 3);
  try {
    parseScene(std::string(header) + "object t mesh u.obj\n", "d/x.scene", reader);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "d/x.scene:3: cannot read mesh 'd/u.obj': not served");
  }
}

TEST(SceneFile, ADirectoryIsNotAScene) {
  try {
    loadScene(scenes / "bad");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              (scenes / "bad").string() + ": cannot open the scene file: it is a directory");
  }
  EXPECT_EQ(errorOf(std::string(header) + "object m mesh meshes\n", scenes / "x.scene"),
            (scenes / "x.scene").string() + ":3: cannot read mesh '" + (scenes / "meshes").string() +
                "': it is a directory");
}

TEST(SceneFile, AMissingFileIsNamed) {
  try {
    loadScene(scenes / "no-such.scene");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("no-such.scene: cannot open the scene file"), std::string::npos);
  }
}

// OBJ meshes, relative to the scene file, and what breaks the requirements of shadow volumes.
Scene withMesh(const std::string& obj, const std::string& settings = "") {
  return parseScene(std::string(header) + "object m mesh meshes/" + obj + "\n" + settings,
                    scenes / "x.scene");
}

TEST(SceneFileObj, ACubeSplitAtSeamsIsWelded) {
  const Scene s = withMesh("split-cube.obj");
  const SceneObject& m = s.objects[0];
  EXPECT_EQ(m.mesh.triangleCount(), 12u) << "quads fanned into triangles";
  EXPECT_EQ(m.mesh.positions.size(), 36u)
      << "no normals in the file: each triangle drawn with its own vertices";
  EXPECT_EQ(m.mesh.normals.size(), m.mesh.positions.size());
  EXPECT_EQ(m.caster.report.inputVertices, 24u) << "the file's vertices, as its faces share them";
  EXPECT_EQ(m.caster.report.weldedVertices, 8u);
  EXPECT_TRUE(m.caster.report.closedManifold());
  EXPECT_TRUE(mentions(m.caster.report, "welded 24 vertices into 8 (vertices split at seams)"));
  EXPECT_GT(signedVolume(m.mesh), 7.99);  // 2^3, wound outwards
}

// A mesh without seams has nothing to weld, and its report says so by saying nothing of welding,
// whether or not the file gives normals (drawn, each triangle has its own vertices either way).
TEST(SceneFileObj, AMeshWithoutSeamsReportsNoWelding) {
  const Scene s = withMesh("tetrahedron.obj");
  const SceneObject& m = s.objects[0];
  EXPECT_EQ(m.mesh.positions.size(), 12u) << "drawn flat: each triangle its own vertices";
  EXPECT_EQ(m.caster.report.inputVertices, 4u);
  EXPECT_EQ(m.caster.report.weldedVertices, 4u);
  EXPECT_TRUE(m.caster.report.closedManifold());
  EXPECT_FALSE(mentions(m.caster.report, "welded")) << m.caster.report.messages.front();
  EXPECT_TRUE(m.caster.report.messages.empty());

  // Normals at every corner, each face its own: drawn split by normal, the caster still shares.
  const ObjMesh smooth = parseObj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 1 1 1\n"
      "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\nf 1//3 4//3 3//3\nf 2//4 3//4 4//4\n",
      "t.obj");
  EXPECT_EQ(smooth.drawn.positions.size(), 12u);
  EXPECT_EQ(smooth.shared.positions.size(), 4u);
  const PreparedCaster c = prepareCaster(smooth.shared);
  EXPECT_TRUE(c.report.closedManifold());
  EXPECT_TRUE(c.report.messages.empty());
}

// The caster prepared from the file's shared vertices is the one the drawn (split) mesh gives.
TEST(SceneFileObj, TheCasterIsTheSameFromTheFilesVerticesAsFromTheDrawnMesh) {
  for (const char* file : {"split-cube.obj", "degenerate-cube.obj", "open-box.obj", "tetrahedron.obj"}) {
    const Scene s = withMesh(file, "  casts no\n");
    const Scene c = withMesh(file);
    const PreparedCaster fromDrawn = prepareCaster(s.objects[0].mesh);
    EXPECT_EQ(c.objects[0].caster.mesh.positions, fromDrawn.mesh.positions) << file;
    EXPECT_EQ(c.objects[0].caster.mesh.indices, fromDrawn.mesh.indices) << file;
  }
}

std::string objErrorOf(const std::string& text) {
  try {
    parseObj(text, "m.obj");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// Every index is checked against what the file defines, with the OBJ line that is wrong; nothing
// out of range reaches the mesh.
TEST(SceneFileObj, EveryBadIndexIsRefusedWithItsLine) {
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
  const struct {
    std::string text, message;
  } cases[] = {
      {tet + "f 2 4 100000000\n", "m.obj:8: vertex index 100000000 is past the file's 4 vertices"},
      {tet + "f 2 4 5\n", "m.obj:8: vertex index 5 is past the file's 4 vertices"},
      {tet + "f -3 -1 -50\n",
       "m.obj:8: vertex index -50 counts back past the first vertex: 4 defined above it"},
      {"v 0 0 0\nf -1 -2 1\nv 1 0 0\nv 0 1 0\n",
       "m.obj:2: vertex index -2 counts back past the first vertex: 1"},
      {tet + "f 2 4 2147483648\n", "m.obj:8: vertex index '2147483648' is too large"},
      {tet + "f 2 4 -99999999999999999999999\n",
       "m.obj:8: vertex index '-99999999999999999999999' is too large"},
      {tet + "f 2 4 0\n", "m.obj:8: vertex index 0: OBJ counts from 1"},
      {tet + "f 2 4 x\n", "m.obj:8: expected a vertex index, got 'x'"},
      {tet + "f 2/1 4 3\n", "m.obj:8: texture coordinate index 1 is past the file's 0 texture coordinates"},
      {tet + "vt 0 0\nf 2/-2 4 3\n", "m.obj:9: texture coordinate index -2 counts back past the first"},
      {tet + "vn 0 0 1\nf 2//2 4//1 3//1\n", "m.obj:9: normal index 2 is past the file's 1 normal"},
      {tet + "vn 0 0 1\nf 2/1/1 4 3\n", "m.obj:9: texture coordinate index 1 is past"},
      {tet + "vt 0 0\nf 2/1/3 4 3\n", "m.obj:9: normal index 3 is past the file's 0 normals"},
      {"v 0 0 0\rv 1 0 0\r\nv 0 1 0\rf 1 2 4\r", "m.obj:4: vertex index 4 is past the file's 3 vertices"},
      {"v 0 0 0\nv 1 0 -1e999\nv 0 1 0\nf 1 2 3\n", "m.obj:2: vertex 2 is not finite"},
      {"v inf 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m.obj:1: the number 'inf' is not finite"},
      {"v 0 0 0\nv 1 0 +Infinity\nv 0 1 0\nf 1 2 3\n", "m.obj:2: the number '+Infinity' is not finite"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -iNf\nf 1//1 2//1 3//1\n",
       "m.obj:4: the number '-iNf' is not finite"},
      {"v 0 0 0\nv 1 0 2e6\nv 0 1 0\nf 1 2 3\n", "m.obj:2: vertex 2 has a coordinate beyond +-1000000"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1e999\nf 1//1 2//1 3//1\n", "m.obj:4: normal 1 is not finite"},
      {"v 0 0 0\nv 1 0 0\n", "m.obj: no faces"},
      {"v 0 0 0\nf" +
           [] {
             std::string corners;
             for (int i = 0; i < 257; ++i) corners += " 1";
             return corners;
           }() +
           "\n",
       "m.obj:2: a face of more than 256 corners"},
  };
  for (const auto& c : cases) {
    const std::string error = objErrorOf(c.text);
    EXPECT_EQ(error.rfind(c.message, 0), 0u)
        << "got: " << error << "\nexpected it to start with: " << c.message;
  }
}

// Found by tests/fuzz (regressions/obj_fuzzer/exponent-overflow.obj): an exponent of ten
// digits overflowed an int in tinyobjloader's number reader. Such numbers are refused first.
TEST(SceneFileObj, ANumberWithAnAbsurdExponentIsRefused) {
  EXPECT_EQ(objErrorOf("# vhv\n 3ert u\x8bth v\nv 0e-2147483648990erom \xa3(\n"),
            "m.obj:3: the number '0e-2147483648990erom' has an exponent of more than 4 digits");
  EXPECT_EQ(objErrorOf("v 0 0 0\nv 1 0 0\nvt 1E+000099999 0\nv 0 1 0\nf 1 2 3\n"),
            "m.obj:3: the number '1E+000099999' has an exponent of more than 4 digits");
  EXPECT_EQ(objErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 1e9999\nf 1 2 3\n"), "m.obj:3: vertex 3 is not finite");
  const ObjMesh m = parseObj("v 0 0 0\nv 1e-0001 0 0\nv 0 1E+0000 1e-9999\nf 1 2 3\n", "m.obj");
  EXPECT_EQ(m.shared.positions[1], glm::vec3(0.1f, 0, 0));
  EXPECT_EQ(m.shared.positions[2], glm::vec3(0, 1, 0));
}

// Found by tests/fuzz (regressions/obj_fuzzer/skin-weight-nan-joint.obj): tinyobjloader converts
// a skin weight's joint (a vw line) to int even when it is not a number. Only the v, vt, vn and
// f lines reach it; the rest, groups and materials included, change nothing of the mesh.
TEST(SceneFileObj, OnlyVerticesAndFacesReachTheReader) {
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const ObjMesh plain = parseObj(tet + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", "m.obj");
  const ObjMesh extras = parseObj(
      "mtllib ../../../../etc/passwd\no thing\n" + tet +
          "vw 1 0e999 1\nvw 2 1e30 1\nt crease 2/1/0 1 2 nan\ng one\nusemtl x\ns 1\nf 1 3 2\nf 1 2 4\n"
          "l 1 2\np 3\ng two\nf 1 4 3\nf 2 3 4\n",
      "m.obj");
  EXPECT_EQ(extras.drawn.positions, plain.drawn.positions);
  EXPECT_EQ(extras.drawn.normals, plain.drawn.normals);
  EXPECT_EQ(extras.drawn.indices, plain.drawn.indices);
  EXPECT_EQ(extras.shared.indices, plain.shared.indices);
}

TEST(SceneFileObj, AnOpenBoxIsKeptWithItsBorderEdgesReported) {
  const Scene s = withMesh("open-box.obj");
  const SceneObject& m = s.objects[0];
  EXPECT_EQ(m.mesh.triangleCount(), 10u);
  EXPECT_EQ(m.caster.report.borderEdges, 4u);
  EXPECT_TRUE(m.caster.report.usable());
  EXPECT_FALSE(m.caster.report.closedManifold());
  EXPECT_TRUE(mentions(m.caster.report, "open: 4 border edges extrude as silhouette edges"));
}

// Open meshes are kept, and handled: their border edges are silhouette edges whatever the light.
TEST(SceneFileObj, AnOpenBoxsBorderEdgesAreOnEverySilhouette) {
  const Scene s = withMesh("open-box.obj");
  const PreparedCaster& c = s.objects[0].caster;
  ASSERT_EQ(c.adjacency.borderEdgeIndices.size(), 4u);
  for (const glm::vec4& light :
       {glm::vec4(0, 5, 0, 1), glm::vec4(0, -5, 0, 1), glm::vec4(1, 0.2f, 0.3f, 0)}) {
    const std::vector<SilhouetteEdge> silhouette =
        possibleSilhouetteEdges(c.adjacency, facesLight(c.mesh, light));
    for (std::uint32_t e : c.adjacency.borderEdgeIndices) {
      const Edge& border = c.adjacency.edges[e];
      const bool found = std::any_of(silhouette.begin(), silhouette.end(), [&](const SilhouetteEdge& edge) {
        return (edge.v0 == border.v0 && edge.v1 == border.v1) ||
               (edge.v0 == border.v1 && edge.v1 == border.v0);
      });
      EXPECT_TRUE(found) << "border edge " << border.v0 << "-" << border.v1;
    }
  }
}

TEST(SceneFileObj, AnEdgeWithThreeFacesIsRefusedForACaster) {
  const std::string error = [] {
    try {
      withMesh("three-faces.obj");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  }();
  EXPECT_NE(
      error.find("x.scene:3: object 'm' cannot cast shadow volumes: not two-manifold: 1 edge shared by three "
                 "or more faces"),
      std::string::npos)
      << error;
  // Drawn only, it may stay.
  const Scene s = withMesh("three-faces.obj", "  casts no\n");
  EXPECT_EQ(s.objects[0].mesh.triangleCount(), 5u);
}

TEST(SceneFileObj, DegenerateTrianglesInsideAClosedMeshAreDropped) {
  const Scene s = withMesh("degenerate-cube.obj");
  const SceneObject& m = s.objects[0];
  EXPECT_EQ(m.mesh.triangleCount(), 14u) << "drawn as written";
  EXPECT_EQ(m.caster.report.droppedDegenerate, 2u);
  EXPECT_EQ(m.caster.mesh.triangleCount(), 12u);
  EXPECT_TRUE(m.caster.report.closedManifold());
  EXPECT_TRUE(mentions(m.caster.report, "dropped 2 degenerate triangles"));
}

// The staircase's claim, counted: the winding of a caster's shadow volume at a point is the
// number of times the way to the light enters the caster (crosses a face that faces the light).
// On the strip in front of the stairs that is 256, one more than 8 bits count; a little further
// up the slope the ray stays inside the flight and enters it once.
TEST(SceneFile, TheStaircaseNests256VolumesOnItsStrip) {
  const Scene s = loadScene(scenes / "hard" / "staircase-256-nested-volumes.scene");
  const SceneObject& stairs = s.objects[1];
  ASSERT_EQ(stairs.name, "stairs");
  const glm::vec4 light = s.lights[0].position;
  const Mesh world = transformed(stairs.caster.mesh, stairs.model);
  const std::vector<bool> lit = facesLight(world, light);
  const auto entries = [&](float x) {
    const Ray ray{{x, 0.0f, 0.37f}, glm::vec3(light)};  // off the treads' diagonals, which count twice
    int n = 0;
    for (std::size_t t = 0; t < world.triangleCount(); ++t) {
      const std::uint32_t* i = &world.indices[3 * t];
      if (lit[t] &&
          intersectTriangle(ray, world.positions[i[0]], world.positions[i[1]], world.positions[i[2]]))
        ++n;
    }
    return n;
  };
  EXPECT_EQ(entries(-14.05f), 256);
  EXPECT_EQ(entries(-14.02f), 256);
  EXPECT_EQ(entries(-13.9f), 1);
  EXPECT_EQ(entries(-14.3f), 0) << "in front of the shadow";
}

// Every hard case is a file that reads: a broken one fails here, not in a lesson's test.
TEST(SceneFile, EveryHardCaseReads) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes / "hard")) {
    if (entry.path().extension() != ".scene") continue;
    ++files;
    try {
      const Scene s = loadScene(entry.path());
      EXPECT_FALSE(s.lights.empty()) << entry.path();
    } catch (const SceneError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(files, 15u);
}

}  // namespace
