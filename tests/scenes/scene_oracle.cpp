// Checks a scene lesson's shadows against a CPU ray cast, light by light:
//
//   scene_oracle [--expect-failure] [--keep] [--variant NAME] [--shadow-hours HH:MM-HH:MM MINUTES]
//                LESSON SCENE WxH [TIME]
//
// runs LESSON --headless --quiet --scene SCENE --size WxH --time TIME --mask-out DIR (and
// --variant NAME when given), then for each light i compares DIR/light-<i>.png (white: lit) with
// classifyPixels for that light, seen through the scene's camera as the framework converts it
// (orbitCameraOf). Only pixels where the ray cast sees a receiver the light reaches (within a point
// light's radius) are judged; pixels on an edge of its picture are forgiven. One line per light; exit 0 when
// all agree, 1 when one does not (with
// --expect-failure the other way round: the scene shows an artifact of the lesson), 2 for bad
// input, 77 when the lesson cannot get a GL context. DIR (a folder per run under the temporary
// folder) is removed when every light agrees, unless --keep.
//
// --shadow-hours SPAN STEP: a shadow profile instead. The lesson runs with --shadow-hours
// DIR/hours.png --shadow-span SPAN --shadow-step STEP --mask-out DIR; each step's mask
// DIR/step-HHMM.png is compared with the ray cast for the scene's sun light where it stands then
// (the scene's other lights are left out), and the raw counts DIR/hours.raw.png must equal, pixel
// for pixel, the number of steps whose mask is in shadow there.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "geometry/scene.h"
#include "geometry/shadow_oracle.h"
#include "gl/image.h"
#include "gl/lesson.h"

using namespace stencil;

namespace {

std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string describe(const glm::vec4& light) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s %g %g %g", light.w == 0.0f ? "directional" : "point", light.x, light.y,
                light.z);
  return buf;
}

// One light's mask against the ray cast: 0 agrees, 1 does not, 2 no usable mask.
int compareLight(const Scene& scene, const glm::vec4& light, float radius,
                 const std::filesystem::path& maskFile, const std::string& name, glm::ivec2 size,
                 double time) {
  const OrbitCamera camera = orbitCameraOf(scene.camera);
  const glm::mat4 viewProjection =
      camera.projection(static_cast<float>(size.x) / static_cast<float>(size.y)) * camera.view();
  const std::vector<OracleObject> objects = oracleObjects(scene, time);
  if (!std::filesystem::exists(maskFile)) {
    std::cout << name << " (" << describe(light) << "): no mask " << maskFile.string()
              << " (the lesson calls Frame::shadowMask(\"light-<i>\") once that light's shadow is in the "
                 "stencil)\n";
    return 2;
  }
  const Image mask = readPng(maskFile, 1);
  if (mask.width != size.x || mask.height != size.y) {
    std::cout << name << ": the mask is " << mask.width << "x" << mask.height << ", not the size asked for\n";
    return 2;
  }
  std::vector<int> surfaces;
  std::vector<bool> ties;
  const std::vector<PixelClass> oracle =
      classifyPixels(objects, light, viewProjection, size, radius, &surfaces, &ties);
  std::vector<bool> lit(oracle.size());
  for (std::size_t p = 0; p < lit.size(); ++p) {
    const bool receiver = oracle[p] == PixelClass::Lit || oracle[p] == PixelClass::Shadowed;
    lit[p] = receiver && mask.pixels[p] == 255;
  }
  const OracleReport r = compareWithOracle(oracle, lit, size, &surfaces, &ties);
  Image picture(size.x, size.y, 4);
  picture.pixels = oraclePicture(oracle, lit, size, &surfaces, &ties);
  const std::filesystem::path pictureFile = maskFile.parent_path() / (name + "-oracle.png");
  writePng(pictureFile, picture);
  std::cout << name << " (" << describe(light) << "): " << (r.passed() ? "ok" : "FAILED") << ", "
            << r.receiverPixels << " receiver pixels, " << r.shadowedPixels << " shadowed; "
            << r.disagreements << " disagree, " << r.onEdges << " of them on edges (" << pictureFile.string()
            << ")\n";
  return r.passed() ? 0 : 1;
}

// 0: every light agrees, 1: one does not, 2: the lesson wrote no mask for a light.
int compareLights(const Scene& scene, const std::filesystem::path& masks, glm::ivec2 size, double time) {
  int result = 0;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const std::string name = "light-" + std::to_string(i);
    const int r = compareLight(scene, scene.lights[i].position, scene.lights[i].radius,
                               masks / (name + ".png"), name, size, time);
    if (r == 2) result = 2;
    if (r == 1 && result == 0) result = 1;
  }
  return result;
}

// The shadow profile's steps, each against the ray cast with the sun where it stands then, and
// the raw counts against the sum of the steps' masks.
int compareShadowHours(const Scene& scene, const std::filesystem::path& masks, glm::ivec2 size, double time,
                       int from, int to, int step) {
  const auto sun =
      std::find_if(scene.lights.begin(), scene.lights.end(), [](const SceneLight& l) { return l.sun; });
  if (sun == scene.lights.end()) {
    std::cout << "the scene has no sun light\n";
    return 2;
  }
  std::vector<int> sum(static_cast<std::size_t>(size.x) * size.y, 0);
  int result = 0, steps = 0, nights = 0;
  for (int minutes = from; minutes <= to; minutes += step, ++steps) {
    CivilTime t = sun->sun->time;
    t.hour = minutes / 60;
    t.minute = minutes % 60;
    t.second = 0.0;
    const SunPosition p = sunPosition(sun->sun->place, t);
    char name[40];
    std::snprintf(name, sizeof name, "step-%02d%02d", t.hour, t.minute);
    const std::filesystem::path maskFile = masks / (std::string(name) + ".png");
    if (p.elevationDeg > 0.0) {
      const int r = compareLight(scene, glm::vec4(sunDirection(p.elevationDeg, p.azimuthDeg), 0.0f),
                                 sun->radius, maskFile, name, size, time);
      if (r == 2) return 2;
      if (r == 1) result = 1;
    }
    if (!std::filesystem::exists(maskFile)) {
      std::cout << name << ": no mask " << maskFile.string() << "\n";
      return 2;
    }
    const Image mask = readPng(maskFile, 1);
    for (std::size_t i = 0; i < sum.size() && i < mask.pixels.size(); ++i) sum[i] += mask.pixels[i] == 0;
    if (p.elevationDeg <= 0.0) {  // night: the sun casts no shadow, and night is not shadow
      ++nights;
      const auto shadowed = std::count(mask.pixels.begin(), mask.pixels.end(), std::uint8_t{0});
      if (shadowed != 0) {
        std::cout << name << ": the sun is down, yet " << shadowed << " pixels are in its shadow\n";
        result = 1;
      }
    }
  }
  const Image counts = readPng(masks / "hours.raw.png", 1);
  if (counts.width != size.x || counts.height != size.y) {
    std::cout << "hours.raw.png is " << counts.width << "x" << counts.height << ", not the size asked for\n";
    return 2;
  }
  std::size_t differ = 0;
  for (std::size_t i = 0; i < sum.size(); ++i) differ += counts.pixels[i] != sum[i];
  std::cout << "hours.raw.png: " << steps << " steps, " << nights << " at night; " << differ
            << " pixels whose count is not the number of steps their masks are in shadow\n";
  return differ == 0 ? result : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  bool expectFailure = false;
  std::string variant;
  bool keep = false;
  std::string span, step;
  while (!args.empty() && args.front().starts_with("--")) {
    if (args.front() == "--expect-failure") {
      expectFailure = true;
    } else if (args.front() == "--keep") {
      keep = true;
    } else if (args.front() == "--shadow-hours" && args.size() > 2) {
      span = args[1];
      step = args[2];
      args.erase(args.begin(), args.begin() + 2);
    } else if (args.front() == "--variant" && args.size() > 1) {
      args.erase(args.begin());
      variant = args.front();
    } else {
      break;
    }
    args.erase(args.begin());
  }
  if (args.size() < 3 || args.size() > 4) {
    std::cerr
        << "usage: scene_oracle [--expect-failure] [--keep] [--variant NAME] [--shadow-hours HH:MM-HH:MM "
           "MINUTES] LESSON SCENE WxH [TIME]\n";
    return 2;
  }
  const std::string lesson = args[0], sceneFile = args[1], sizeText = args[2];
  const double time = args.size() == 4 ? std::atof(args[3].c_str()) : 1.0;
  glm::ivec2 size;
  if (std::sscanf(sizeText.c_str(), "%dx%d", &size.x, &size.y) != 2 || size.x < 1 || size.y < 1) {
    std::cerr << "scene_oracle: error: the size is WxH, got '" << sizeText << "'\n";
    return 2;
  }
  Scene scene;
  try {
    scene = loadScene(sceneFile, !span.empty());  // a profile may start or end at night
  } catch (const SceneError& e) {
    std::cerr << "scene_oracle: error: " << e.what() << "\n";
    return 2;
  }

  const std::filesystem::path masks =
      std::filesystem::temp_directory_path() /
      ("scene-oracle-" + std::filesystem::path(lesson).filename().string() + "-" +
       std::filesystem::path(sceneFile).stem().string() + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(masks);
  const std::string command =
      shellQuoted(lesson) + " --headless --quiet --scene " + shellQuoted(sceneFile) + " --size " + sizeText +
      " --time " + std::to_string(time) + " --mask-out " + shellQuoted(masks.string()) +
      (variant.empty() ? std::string() : std::string(" --variant ") + shellQuoted(variant)) +
      (span.empty() ? std::string()
                    : " --shadow-hours " + shellQuoted((masks / "hours.png").string()) + " --shadow-span " +
                          shellQuoted(span) + " --shadow-step " + shellQuoted(step));
  const int status = std::system(command.c_str());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 77) {
    std::cout << "no GL context: skipped\n";
    return 77;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::cout << "the lesson failed: " << command << "\n";
    return 1;
  }
  int result = 0;
  if (span.empty()) {
    result = compareLights(scene, masks, size, time);
  } else {
    int from = 0, to = 0, minutes = 0;
    {
      int h0, m0, h1, m1;
      if (std::sscanf(span.c_str(), "%d:%d-%d:%d", &h0, &m0, &h1, &m1) != 4 ||
          std::sscanf(step.c_str(), "%d", &minutes) != 1 || minutes < 1) {
        std::cerr << "scene_oracle: error: --shadow-hours takes HH:MM-HH:MM and minutes\n";
        return 2;
      }
      from = h0 * 60 + m0;
      to = h1 * 60 + m1;
    }
    result = compareShadowHours(scene, masks, size, time, from, to, minutes);
  }
  if (result == 0 && !keep) {  // nothing to look at: the folder goes, unless --keep
    std::filesystem::remove_all(masks);
    std::cout << "(the masks and pictures are removed when the ray cast agrees; --keep keeps them)\n";
  }
  if (result == 2) return 1;  // a missing mask is a lesson's bug, whatever was expected
  if (expectFailure) {
    std::cout << (result == 1 ? "the ray cast disagrees, as expected\n"
                              : "expected the ray cast to disagree, and it agrees\n");
    return result == 1 ? 0 : 1;
  }
  return result;
}
