// The lesson model. A lesson declares what it is (LessonInfo) and renders one frame at a
// time into a verified framebuffer (Lesson::render). Everything else — the command line,
// the backends, the window, stats, snapshots, goldens — is the framework's, the same for
// every lesson. The stencil, depth, colour-mask and cull calls stay in the lesson.
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/scene.h"
#include "geometry/shadow_oracle.h"
#include "gl/context.h"

namespace stencil {

// A classroom toggle: an integer the lesson reads each frame, cycled by a key in the window.
// Its range min..max is declared here and nowhere else: --help prints it, and a variant's
// setting or --set outside it is refused. 0..1 makes it an on/off switch.
struct Option {
  std::string name;
  char key;
  std::string help;
  int value = 0;
  int max = 1;
  int min = 0;

  bool operator==(const Option&) const = default;
};

// The options a run starts with, as LessonInfo::refuseOptions sees them before a context is made:
// the lesson's options with the variant's settings and --set applied, the --set settings as given
// (NAME, VALUE, in order), and --scene's scene (nullptr without one).
struct OptionsChosen {
  const std::vector<Option>& options;
  const std::vector<std::pair<std::string, int>>& settings;
  const Scene* scene;
  int value(std::string_view name) const;  // throws std::logic_error for a name the lesson lacks
  bool set(std::string_view name) const;   // given with --set
};

enum class Feature { DepthBoundsTest, PipelineStatistics, ClipControl, DepthClamp, KhrDebug, StencilExport };
const char* featureName(Feature);
bool hasFeature(const GlFeatures&, Feature);

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 6.0f;
  float azimuthDeg = 30.0f;    // around +y, 0 looks down -z
  float elevationDeg = 25.0f;  // above the xz plane
  float fovyDeg = 45.0f;
  float nearPlane = 0.1f, farPlane = 100.0f;  // farPlane infinite: the far plane at infinity (Pinf)
  bool orthographic = false;                  // a parallel view orthoHeight world units high
  float orthoHeight = 10.0f;
  bool mirrored = false;  // the picture flipped left to right: the view matrix's determinant is negative

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

// The orbit camera that sees what a scene file's camera sees (eye, target, field of view, planes,
// orthographic, mirrored). Throws std::invalid_argument for what an orbit camera cannot be: an
// up other than +y, an eye on the target or straight above or below it.
OrbitCamera orbitCameraOf(const SceneCamera&);

// The orbit camera whose eye stands at `eye` looking at `target` (world space, +y up): distance
// |eye - target|, azimuthDeg atan2(x, z) and elevationDeg asin(y / distance) of eye - target, the
// inverse of OrbitCamera::eye(). Field of view, planes and the rest keep OrbitCamera's defaults.
// The caller keeps eye off the target and off the vertical through it (no azimuth there). The
// angles are taken in double and rounded to float, so that they are the same at every optimisation
// level: glibc's float asinf and atan2f are not correctly rounded (atan2f is 2 ulps off for lesson
// 13's fill camera) while a compiler folds a call on constants correctly rounded, and an ulp in the
// camera moves pixels. The double functions are within an ulp of a double, which rounds to the
// correctly rounded float, folded or called.
inline OrbitCamera orbitCameraFrom(glm::vec3 eye, glm::vec3 target) {
  const glm::vec3 back = eye - target;
  OrbitCamera c;
  c.target = target;
  c.distance = glm::length(back);
  const double elevation = std::asin(static_cast<double>(back.y / c.distance));
  const double azimuth = std::atan2(static_cast<double>(back.x), static_cast<double>(back.z));
  c.elevationDeg = glm::degrees(static_cast<float>(elevation));
  c.azimuthDeg = glm::degrees(static_cast<float>(azimuth));  // eye() puts the eye at (sin az, ., cos az)
  return c;
}

// A named configuration of the options, e.g. "stencil-off" to show the artifact.
struct Variant {
  std::string name;
  std::string help;
  std::vector<std::pair<std::string, int>> settings;  // option name, value
  std::vector<Feature> needs = {};                    // beyond what the lesson needs
  std::optional<OrbitCamera> camera = {};             // where the variant needs the eye; else the lesson's
  std::optional<bool> reversedDepth = {};             // overrides LessonInfo::reversedDepth
};

struct LessonInfo {
  std::string id;     // "00-stencil-basics": folder, shader folder, golden folder
  std::string title;  // "Stencil basics"
  std::string summary;
  int stencilBits = 8;
  std::vector<Feature> needs;
  std::vector<Option> options;
  std::vector<Variant> variants;  // the first is the default
  std::vector<std::string> passes;
  OrbitCamera camera;
  // The option, if any, that picks one of the scene's lights by its index (the light drawn last).
  // With --scene FILE its max becomes the file's light count - 1, before the options are checked,
  // so a light the file does not have is refused.
  std::string sceneLightOption;
  // Whether the lesson makes shadow claims (overrides Lesson::shadowCheck or calls
  // Frame::shadowMask): only then do --oracle and, for scene lessons, --mask-out apply. Without
  // it they are refused, and --help does not list them.
  bool shadows = false;
  // Reversed floating-point depth where the driver has ARB_clip_control (core in 4.5): the
  // framework gives the framebuffer a 32-bit float depth buffer (GL_DEPTH32F_STENCIL8) and sets
  // Frame::reversedDepth; the lesson makes the GL calls itself (glClipControl with a zero-to-one
  // depth range, glClearDepth(0), every depth comparison flipped, geometry/projection.h's
  // reversedDepth on Frame::projection). Without clip control the run says so once and falls back
  // to the 24-bit fixed-point buffer with GL's default mapping. Off: a 24-bit buffer, as always.
  bool reversedDepth = false;
  // Whether the lesson reads Frame::pointer (a brush the right mouse button drags): the window
  // gives the right-drag hint only then.
  bool brush = false;
  // The settings a scene file is drawn with where neither the variant nor --set gives them
  // (lesson 14: method 4, as its default method 0 draws only the demo's two solids).
  std::vector<std::pair<std::string, int>> sceneSettings;
  // Refuses options that contradict each other or the scene file (exit 2, before anything is
  // drawn): returns why in one line, or an empty string. Unset: every combination draws.
  std::function<std::string(const OptionsChosen&)> refuseOptions;
};

class PassRecorder;
struct CommandLine;

// What a lesson sees while it renders one frame.
class Frame {
 public:
  Frame(double time, glm::ivec2 size, const OrbitCamera&, const std::vector<Option>&, PassRecorder&,
        const GlFeatures&, bool reversedDepth = false, unsigned framebuffer = 0);

  const double time;  // seconds; every animation is a function of it
  const glm::ivec2 size;
  // projection is always in GL's default convention (clip z from -w at the near plane to +w at
  // the far plane), whatever the depth buffer: frustum planes, bounds and the oracle read it so.
  const glm::mat4 view, projection;
  const glm::vec3 eye;
  const GlFeatures& features;
  // The framebuffer's depth is 32-bit float and the lesson draws with reversed depth
  // (LessonInfo::reversedDepth, and the driver has clip control); false: 24-bit, GL's mapping.
  const bool reversedDepth;

  // The framework's framebuffer (a GL framebuffer name), size wide and high, with the verified
  // stencil: the one render starts with bound, and the one the finished frame is read from
  // (--out, --stencil-out, goldens, the window). A lesson that draws passes into a target of
  // its own binds this one again to finish the frame.
  unsigned framebuffer() const { return framebuffer_; }

  int option(std::string_view name) const;  // unknown names throw: a typo is a bug
  bool on(std::string_view name) const { return option(name) != 0; }
  // Marks the end of a named pass. A pass the frame repeats may say which repeat it is in
  // `detail` ("light 2", "level 3"): the window's pass stepper and --stats show it beside the name.
  // The pass's snapshot (the pass stepper, --passes, the docs' figures) shows the framebuffer
  // bound for drawing now, read at the frame's size, if its colour, depth and stencil can all be
  // read (a read buffer, a depth and a stencil attachment); else framebuffer(). It changes no GL
  // binding: the draw and read framebuffers, the viewport and the pack alignment stay as they are.
  void pass(std::string_view name, std::string_view detail = {});
  // Adds to a named count of the lesson's own (e.g. "scene_renderings"), reported per frame
  // under "counts" in --stats: work that draw calls and triangles do not show.
  void count(std::string_view name, std::uint64_t amount = 1);
  // The lesson's own check of this frame (an option such as lesson 14's `oracle`) found the
  // picture wrong: a headless run writes what it was asked to, prints `what` (one line naming the
  // check and the pixels) and exits 1, as --oracle does for the shadows.
  void checkFailed(std::string what);
  // Runs draw while the pass's own occlusion query (--stats) is paused, so draw may run
  // GL_SAMPLES_PASSED queries of its own (GL allows one active query per target). The fragments
  // draw produces are left out of the pass's samples_passed.
  void ownOcclusionQueries(const std::function<void()>& draw);
  // Saves framebuffer()'s stencil as it is now as the shadow mask NAME.png under --mask-out DIR (white where
  // the stencil is 0, lit; black elsewhere), in the last frame of a headless run or of a window
  // run with --frames; does nothing otherwise. Scene lessons call it once per light with "light-<i>", i the
  // light's index in the scene, after that light's shadow is in the stencil: tests compare it with a ray
  // cast. Like pass, it changes no GL binding.
  void shadowMask(std::string_view name);

  // How the session saves shadow masks; empty when they are not wanted.
  using ShadowMaskWriter = std::function<void(std::string_view name)>;
  void setShadowMaskWriter(ShadowMaskWriter writer) { shadowMaskWriter_ = std::move(writer); }

  // Long CPU work inside a frame (lesson 10's converged ray cast) says how far it has come: DONE
  // of TOTAL WHAT ("pixels ray cast"). A headless frame that runs past a few seconds prints it on its "still
  // rendering" line (WorkProgress in session.h). May be called from several threads at once.
  void progress(std::string_view what, std::size_t done, std::size_t total) const;
  using ProgressSink = std::function<void(std::string_view what, std::size_t done, std::size_t total)>;
  void setProgressSink(ProgressSink sink) { progressSink_ = std::move(sink); }

  // In the window, while the right mouse button is held over the picture: the framebuffer pixel
  // under the pointer (x right, y up from the bottom left corner, in pixels). Empty otherwise, and
  // always in headless runs. Lessons that paint (lesson 12's brush) read it; others ignore it.
  std::optional<glm::vec2> pointer;
  // The window's UI scale (1 headless): a lesson's overlay text (lesson 13's legend) grows with it.
  float uiScale = 1.0f;

 private:
  const std::vector<Option>& options_;
  PassRecorder& recorder_;
  unsigned framebuffer_;
  ShadowMaskWriter shadowMaskWriter_;
  ProgressSink progressSink_;
};

// The GL state every frame starts from, so that any frame can be reproduced alone; the framework
// calls it before each Lesson::render. It sets:
//   framebuffer bound for drawing and reading (GL_FRAMEBUFFER), the viewport its whole size;
//   GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE and GL_SCISSOR_TEST disabled;
//   glColorMask all GL_TRUE, glDepthMask GL_TRUE, glStencilMask 0xFF;
//   glStencilFunc(GL_ALWAYS, 0, 0xFF), glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
//   glDepthFunc(GL_LESS), glClearDepth(1);
//   glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE) where the driver has clip control.
// Everything else stays as the last frame left it: the clear colour and clear stencil, the cull
// face and front face, blend function, polygon offset, the bound program, vertex array and
// textures. A lesson sets those itself before it relies on them. framebuffer is a GL name of a
// framebuffer width x height.
void resetFrameState(unsigned framebuffer, glm::ivec2 size, const GlFeatures&);

// What --oracle needs to check a lesson's shadows against a CPU ray cast of the same scene
// (geometry/shadow_oracle.h): the scene as the lesson drew it in that frame, the light, and
// how to read the frame's final stencil value as "a lit receiver".
struct ShadowCheck {
  std::vector<OracleObject> objects;
  glm::vec4 light;
  std::function<bool(std::uint8_t stencil)> litInStencil;
  // Shadow-volume lessons keep only the shadow in the stencil; where a receiver is visible is
  // the depth buffer's business. Then only the pixels where the oracle sees a receiver are judged.
  bool judgeReceiversOnly = false;
  // A bounded point light's reach (SceneLight::radius): beyond it no shadow is claimed.
  float lightRadius = std::numeric_limits<float>::infinity();
};

class Lesson {
 public:
  virtual ~Lesson() = default;
  // Draws one frame into Frame::framebuffer(). It is called with the GL state resetFrameState
  // leaves (that framebuffer bound, the tests off, every write on: the list is there) and the
  // buffers holding what the last frame left in them: the lesson clears.
  virtual void render(Frame&) = 0;
  // The frame's shadows as an oracle can check them; nothing where the current options make
  // no shadow claim (a variant that shows an artifact, say).
  virtual std::optional<ShadowCheck> shadowCheck(const Frame&) const { return std::nullopt; }
};

// The lesson's constructor runs with a current context (it creates its GL objects).
using LessonFactory = std::function<std::unique_ptr<Lesson>()>;

// The whole program: parse the command line, make a context, run headless or in a window.
// --scene and --mask-out are refused: the lesson draws only its own scene.
int runLesson(const LessonInfo&, const LessonFactory&, int argc, char** argv);

// A lesson that renders any scene from a file (geometry/scene.h). fromFile is the scene given
// with --scene, read (and its casters prepared) before the lesson is made, and alive as long as
// the lesson; nullptr without --scene, when the lesson draws its built-in scene.
using SceneLessonFactory = std::function<std::unique_ptr<Lesson>(const Scene* fromFile)>;

// runLesson for such lessons: also takes --scene FILE (its camera replaces the lesson's and the
// variants'; a file that cannot be read is one line "FILE:LINE: ...", exit 2) and, where the
// lesson makes shadow claims (LessonInfo::shadows), --mask-out DIR (Frame::shadowMask).
int runSceneLesson(const LessonInfo&, const SceneLessonFactory&, int argc, char** argv);

// Reads --scene's file (cl.scene, set) before the lesson is made: its camera replaces `info`'s and
// the variants', its lights bound the option that picks one (LessonInfo::sceneLightOption). Throws
// UsageError, one line naming the file (and line) and what is wrong.
Scene readScene(const CommandLine& cl, LessonInfo& info);
// What preparing the scene's casters did and found (welded seams, dropped triangles), a line each
// on stderr naming cl.scene's file, unless cl.quiet.
void sayWhatTheCastersNeeded(const CommandLine& cl, const Scene& scene);

}  // namespace stencil
