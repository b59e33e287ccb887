// The command line every lesson shares (--help prints it).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/lesson.h"

namespace stencil {

// --time's bound in seconds, either way. A float (what the shaders and the animation use) steps by
// 1/16 s at 1e6 s, enough for a still frame; beyond it animations visibly break down.
constexpr double kMaxTime = 1e6;

struct CommandLine {
  bool help = false;
  bool listVariants = false;
  bool headless = false;
  std::optional<Backend> backend;
  int width = 640, height = 480;
  double time = 0.0;          // finite, |time| <= kMaxTime
  std::optional<int> frames;  // headless: 1 unless given; window: until closed unless given
  std::string variant;        // empty: the lesson's first
  std::vector<std::pair<std::string, int>> settings;  // --set NAME=VALUE
  std::optional<std::filesystem::path> out, stencilOut, depthOut, passesDir, golden, artifacts, shaderDir;
  std::optional<std::filesystem::path> oracle;   // --oracle FILE.png: check the shadows by ray casting
  std::optional<std::filesystem::path> scene;    // --scene FILE: a scene lesson renders this scene
  std::optional<std::filesystem::path> maskOut;  // --mask-out DIR: the shadow masks (Frame::shadowMask)
  // --shadow-hours FILE.png: the scene's sun light moved through --shadow-span (minutes after local
  // midnight, both ends) in steps of --shadow-step minutes, the steps each pixel spends in shadow.
  std::optional<std::filesystem::path> shadowHours;
  int shadowFrom = 9 * 60, shadowTo = 17 * 60, shadowStep = 60;
  int stencilBits = 8;            // --stencil-bits 0 builds a framebuffer without stencil
  bool stencilBitPlanes = false;  // --stencil-view bits
  bool stats = false;
  bool statsFrames = false;  // --stats frames: no per-pass queries, one glFinish a frame
  bool updateGolden = false;
  bool quiet = false;
  // The window (ignored headless). The next lesson of the course opens with these set to what the
  // window had (Page Down, Page Up).
  std::optional<float> uiScale;                // --ui-scale S, kMinUiScale..kMaxUiScale; else the monitor's
  std::optional<std::pair<int, int>> position;  // --position X,Y: the window's top left, screen coordinates
  int view = 0;                                 // --view: 0 colour, 1 stencil, 2 grey, 3 bits, 4 depth
  bool panelHidden = false;                     // --panel hidden
};

// The window's UI scale (panel text, widgets, the stencil legend): 1 draws the panel's text 13 px
// high. kUiScaleStep is what the + and - keys change it by.
constexpr float kMinUiScale = 0.5f, kMaxUiScale = 4.0f, kUiScaleStep = 0.25f;
// The window's views, in the order Tab cycles them (--view takes these names).
constexpr const char* kViewNames[] = {"colour", "stencil", "grey", "bits", "depth"};
constexpr int kViewCount = 5;

// Throws UsageError with one line for anything it does not understand.
CommandLine parseCommandLine(const LessonInfo&, int argc, char** argv);
// With a scene file (cl.scene), LessonInfo::sceneSettings that neither the variant nor cl.settings
// gives are added to cl.settings. parseCommandLine does it; the browser's page when it loads a scene.
void addSceneSettings(const LessonInfo&, CommandLine& cl);
// readsScenes: the lesson runs through runSceneLesson, so --scene is listed, and --mask-out where
// the lesson makes shadow claims (LessonInfo::shadows, which also lists --oracle).
std::string helpText(const LessonInfo&, const std::string& program, bool readsScenes = false);
std::string variantList(const LessonInfo&);

// The lesson's options with the variant's settings and then --set applied.
// Throws UsageError for an unknown variant, option or out-of-range value.
std::vector<Option> optionsFor(const LessonInfo&, const std::string& variant,
                               const std::vector<std::pair<std::string, int>>& settings);
const Variant& findVariant(const LessonInfo&, const std::string& name);
// The --set settings that give `options` from the variant's values: those away from them (NAME,
// VALUE, in the lesson's order).
std::vector<std::pair<std::string, int>> settingsAwayFromVariant(const LessonInfo&, const std::string& variant,
                                                                 const std::vector<Option>& options);

}  // namespace stencil
