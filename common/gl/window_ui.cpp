// The classroom window: the lesson's framebuffer shown in a GLFW window, a Dear ImGui
// panel with the lesson's toggles, pass stepping through the pass recorder, the stencil
// inspector, an orbit camera and screenshots.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupToLevel: Esc closes an open list

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <string>

#include "gl/errors.h"
#include "gl/frame_rate.h"
#include "gl/options.h"
#include "gl/session.h"
#include "gl/stencil_view.h"

namespace stencil {
namespace {

// In the order Tab cycles them, as kViewNames names them (--view).
enum class View { Colour, StencilRamp, StencilGrey, StencilBits, Depth };
constexpr int kViews = kViewCount;

struct WindowState {
  Session& session;
  double time;
  bool paused = false;
  View view = View::Colour;
  int passStep = -1;  // -1: the finished frame; k: the snapshot after the k-th pass that ran
  bool dragging = false;
  bool pointing = false;  // the right button held: Frame::pointer (a lesson's brush)
  double lastX = 0, lastY = 0;
  bool screenshot = false;        // S: the picture alone
  bool windowScreenshot = false;  // shift+S: the whole window, the panel too
  int screenshots = 0;
  bool panel = true;                               // F1 hides and shows it
  std::vector<std::filesystem::path> course = {};  // courseLessons()
  int lessonIndex = -1;                            // this lesson's place in it, -1 where it is not there
  bool sayLayout = false;                          // say the picture's size once the layout has changed
  bool sayDepthRange = false;                      // say the depth view's legend once it is shown
  float uiScale = 1.0f;                            // --ui-scale, the monitor's, or + and -
  bool scaleChanged = true;                        // the fonts and sizes are rebuilt before the next frame
  std::vector<int> keysPressed = {};               // since the panel's last frame (replayImGuiTaps)
  bool editEnding = false;                         // Esc ended a typed edit that ImGui has not yet closed
  bool closeLists = false;                         // Esc closes the open drop-down list in the next frame
  bool editing = false;                            // a panel field took typed text in the last frame
  bool listOpen = false;                           // a drop-down list was open in the last frame
  int sayCountsAfter = -1;                         // say the counts new in this frame (after a key changed an option)
  std::vector<std::string> countsBefore = {};      // the count names before the option changed
  FrameRate rate = {};
  // $STENCIL_FRAME_LOG: every frame's end on the window's clock, one a line, flushed at F2, so a
  // test can count frames over wall time itself (tests/window/frame_rate.sh).
  std::unique_ptr<std::ofstream> frameLog = {};
  // The panel's last layout: the options' height, and that of the controls below them other than the
  // views and what the two sections hold (measured; 0 before the first frame).
  float optionsHeight = 0, fixedBelow = 0;
  bool keysOpen = true, statsOpen = true;  // the two sections as the last frame showed them
  bool statsOpenedLast = false;            // of the two, the draw calls and counts were opened last
  bool sayFit = false;                     // say the layout's line (a section opened or folded)
  bool compact = false;                    // the last frame's panel gave the options all it could
  int layoutFrames = 0;                    // frames drawn since the layout changed
  float leastPanelHeight = 0;              // the panel's height folded as far as it goes (measured; 0 before)
  float leastPanelScale = 1;               // the UI scale it was measured at
  float scaleShown = 1;                    // the UI scale when the panel was last shown (F1)
  std::string status = {};                 // a line shown over the picture until statusUntil (tell)
  double statusUntil = 0;
  // The option a key stepped since the last frame drawn, and which way (+1, or -1 with shift): a
  // value the lesson refuses is stepped past, so that the key reaches every value it takes.
  std::optional<std::pair<std::size_t, int>> stepped = {};
};

// The panel's width in screen pixels at a UI scale.
int panelWidth(float uiScale) {
  return static_cast<int>(std::lround(kWindowPanelWidth * uiScale));
}

std::string scaleText(float scale) {
  char text[16];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(scale));
  return text;
}

WindowState& stateOf(GLFWwindow* w) {
  return *static_cast<WindowState*>(glfwGetWindowUserPointer(w));
}

// A variant this run cannot show (a feature the context lacks, a light the scene file does not
// have) is said in one line, and the window keeps the variant it shows.
void switchVariant(Session& s, const std::string& name) {
  try {
    s.setVariant(name);
  } catch (const UsageError& e) {
    std::cerr << "variant '" << name << "': " << e.what() << "\n";
  }
}

// What a key changed, one line on stderr (not with --quiet): the class sees it in the terminal,
// and the window tests read it.
void say(const WindowState& st, const std::string& line) {
  if (!st.session.commandLine.quiet) std::cerr << line << "\n";
}

// A line the class must read from the window itself, not only the terminal (F2's, the course's
// ends, a change refused): said, and shown over the top of the picture for a few seconds.
void tell(WindowState& st, const std::string& line) {
  say(st, line);
  st.status = line;
  st.statusUntil = glfwGetTime() + 6.0;
}

// The passes the last frame ran, in order, named as they ran (PassStats::label): the stepper goes
// through these, not through the names the lesson declares, which may run in another order, repeat
// or not run at all.
int passesRun(const Session& s) {
  return static_cast<int>(s.recorder->passStats().size());
}

std::string stepName(const Session& s, int step) {
  if (step < 0 || step >= passesRun(s)) return "finished frame";
  return s.recorder->passStats()[static_cast<std::size_t>(step)].label;
}

void sayStep(const WindowState& st) {
  const int n = passesRun(st.session);
  char held[48];  // the frame's time, which stepping holds
  std::snprintf(held, sizeof held, " (t = %.3f s, held)", st.time);
  say(st, st.passStep < 0 ? std::string("after the last pass: the finished frame")
                          : "after pass " + std::to_string(st.passStep + 1) + " of " + std::to_string(n) +
                                ": " + stepName(st.session, st.passStep) + held);
}

const char* viewName(View v) {
  return v == View::Colour        ? "colour"
         : v == View::StencilRamp ? "stencil"
         : v == View::StencilGrey ? "stencil in grey (value x 255 / the largest value present)"
         : v == View::StencilBits ? "bit planes"
                                  : "depth";
}

// What a change says, the same line whether a key or a click on the panel made it.
void sayView(WindowState& st) {
  say(st, std::string("view: ") + viewName(st.view));
  st.sayDepthRange = st.view == View::Depth;
}

// Closes this lesson's window to open the course's lesson at `index` in its place (Session::nextLesson).
void goToLesson(GLFWwindow* w, WindowState& st, int index) {
  if (st.lessonIndex < 0 || index == st.lessonIndex) return;
  if (index < 0 || index >= static_cast<int>(st.course.size())) {
    tell(st, index < 0 ? "the first lesson of the course" : "the last lesson of the course");
    return;
  }
  st.session.nextLesson = st.course[static_cast<std::size_t>(index)];
  say(st, (index > st.lessonIndex ? "next: " : "previous: ") + st.session.nextLesson->filename().string());
  glfwSetWindowShouldClose(w, GLFW_TRUE);
}

// The text an option's help gives its value: "3 B - A" in "0 A + B, 1 A * B, 2 A - B, 3 B - A",
// "keyhole" in "0 keyhole, 1 the three operations"; empty where the help names no values.
std::string valueName(const Option& o, int value) {
  if (o.min == 0 && o.max == 1) return {};
  const std::string v = std::to_string(value) + " ";
  const std::string& h = o.help;
  for (std::size_t at = h.find(v); at != std::string::npos; at = h.find(v, at + 1)) {
    // The number starts a list item: at the start, after ": ", ", " or a newline's indent.
    if (at > 0 && h[at - 1] != ' ') continue;
    if (at > 1 && h[at - 1] == ' ' && h[at - 2] != ':' && h[at - 2] != ',' && h[at - 2] != ' ') continue;
    std::size_t end = at + v.size();
    // The item runs to the next ", N " or the end (a wrapped help's newline and indent skipped).
    std::size_t stop = end;
    for (; stop < h.size(); ++stop) {
      if (h[stop] == '\n') break;
      if (h[stop] == ',' && stop + 2 < h.size() && h[stop + 1] == ' ' &&
          std::isdigit(static_cast<unsigned char>(h[stop + 2])))
        break;
    }
    std::string name = h.substr(end, stop - end);
    // The name, not its explanation: up to a bracket, a colon or a semicolon ("jittered", not
    // "jittered (one random sample a cell)").
    name = name.substr(0, std::min({name.find(" ("), name.find(':'), name.find(';')}));
    while (!name.empty() && (name.back() == ' ' || name.back() == ',')) name.pop_back();
    if (!name.empty()) return name;
  }
  return {};
}

int steppedValue(const Option& o, int way) {
  if (way > 0) return o.value >= o.max ? o.min : o.value + 1;
  return o.value <= o.min ? o.max : o.value - 1;
}

// A lesson's refusal, written for the command line, in the window's words: an option by its name
// (its key is in the panel), not --set NAME=VALUE.
std::string inWindowWords(const std::string& message) {
  std::string m = std::regex_replace(message, std::regex("--set ([a-z0-9_-]+)="), "$1 ");
  m = std::regex_replace(m, std::regex("--set ([a-z0-9_-]+)"), "$1");
  m = std::regex_replace(m, std::regex("--variant"), "the variant");
  return std::regex_replace(m, std::regex("--scene"), "the scene file");
}

std::string optionLine(const Option& o) {
  const std::string name = valueName(o, o.value);
  return o.name + " = " + std::to_string(o.value) + (name.empty() ? std::string() : " (" + name + ")");
}

// An option changed (its key, or a click on its control): its line, and what it makes the lesson
// count (lesson 14's oracle, say) after the next frame.
void optionChanged(WindowState& st, const Option& o) {
  say(st, optionLine(o));
  st.countsBefore.clear();
  for (const auto& [name, n] : st.session.recorder->counts()) st.countsBefore.push_back(name);
  st.sayCountsAfter = 1;
}

// After a refusal of the value a key stepped an option to, that option alone changed (lesson 14's
// method 0 with a scene file): the values beyond it the same way round, each drawn until one is
// taken: true then, that frame drawn; false where only the value drawn before is taken (the caller
// puts it back).
bool stepPastRefusals(WindowState& st, const std::vector<Option>& drawnOptions, const FrameRequest& request) {
  Session& s = st.session;
  Option& o = s.options[st.stepped->first];
  for (o.value = steppedValue(o, st.stepped->second); o.value != drawnOptions[st.stepped->first].value;
       o.value = steppedValue(o, st.stepped->second))
    try {
      s.renderFrame(st.time, request);
      return true;
    } catch (const UsageError&) {
    }
  return false;
}

// Why the panel at `scale` does not hold in a window ww x wh, or empty where it does: it would take
// more than half the window's width (the picture keeps the rest; said with the panel's width at the
// scale now), or, folded as far as it goes, run past its height.
std::string panelTooLarge(const WindowState& st, float scale, int ww, int wh) {
  if (panelWidth(scale) > ww / 2)
    return "the panel " + std::to_string(panelWidth(st.uiScale)) + " px, the picture at least half the window's " +
           std::to_string(ww) + " px";
  const float least = st.leastPanelHeight * scale / st.leastPanelScale;
  if (st.leastPanelHeight > 0 && least > static_cast<float>(wh))
    return "the panel folded needs " + std::to_string(static_cast<int>(std::ceil(least))) + " px at " +
           scaleText(scale) + ", the window is " + std::to_string(wh) + " px high";
  return {};
}

// `window`: the + key's change, which stops where the panel would no longer hold (panelTooLarge).
// With the panel hidden it goes on (the legends follow it too); F1 brings the panel back at the
// largest scale that holds it.
void setUiScale(WindowState& st, float scale, GLFWwindow* window = nullptr) {
  scale = std::round(scale / kUiScaleStep) * kUiScaleStep;
  if (scale < kMinUiScale || scale > kMaxUiScale) {
    tell(st, "ui scale " + scaleText(st.uiScale) + " is the " + (scale < kMinUiScale ? "smallest" : "largest") +
                 " (" + scaleText(kMinUiScale) + " to " + scaleText(kMaxUiScale) + ")");
    return;
  }
  if (window && st.panel && scale > st.uiScale) {
    int ww = 0, wh = 0;
    glfwGetWindowSize(window, &ww, &wh);
    if (const std::string why = panelTooLarge(st, scale, ww, wh); !why.empty()) {
      tell(st, "ui scale " + scaleText(st.uiScale) + " is the largest this window holds (" + why + ")");
      return;
    }
  }
  if (scale == st.uiScale) return;
  st.uiScale = scale;
  st.scaleChanged = st.sayLayout = true;
}

// F1 showing the panel: a scale raised past what the window holds while it was hidden comes back
// down to the largest that holds it (never below the scale it had when it was last shown).
void showPanelAtAScaleItHolds(GLFWwindow* window, WindowState& st) {
  int ww = 0, wh = 0;
  glfwGetWindowSize(window, &ww, &wh);
  float scale = st.uiScale;
  while (scale > st.scaleShown && !panelTooLarge(st, scale, ww, wh).empty()) scale -= kUiScaleStep;
  if (scale == st.uiScale) return;
  tell(st, "ui scale " + scaleText(scale) + ", the largest this window holds with the panel (at " +
               scaleText(st.uiScale) + ": " + panelTooLarge(st, st.uiScale, ww, wh) + ")");
  st.uiScale = scale;
  st.scaleChanged = true;
}

// ImGui before 1.87 reads keys as held or not when its frame starts, so a key pressed and
// released between two frames (a short tap at a few frames a second) never reaches it: Esc would
// not end a typed edit. Each key pressed since the last frame is held for that frame, then put back
// as it is.
void replayImGuiTaps([[maybe_unused]] GLFWwindow* w, WindowState& st, [[maybe_unused]] bool frameStarts) {
#if IMGUI_VERSION_NUM < 18700
  ImGuiIO& io = ImGui::GetIO();
  for (int key : st.keysPressed)
    if (key >= 0 && key < IM_ARRAYSIZE(io.KeysDown))
      io.KeysDown[key] = frameStarts || glfwGetKey(w, key) == GLFW_PRESS;
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
#endif
  if (frameStarts) return;
  st.keysPressed.clear();
  // WantTextInput says what the frame before this one wanted: the field is closed once it is false.
  if (!ImGui::GetIO().WantTextInput) st.editEnding = false;
}

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
  if (action != GLFW_PRESS) return;
  WindowState& st = stateOf(w);
  st.keysPressed.push_back(key);
  // While a panel field takes typed text (a slider ctrl-clicked to type a number) the keys are
  // the field's, Esc included: it ends the edit. Otherwise Esc quits and the other keys are the
  // lesson's.
  // The keys after that Esc, before the panel's next frame closes the field, are the lesson's.
  if (ImGui::GetIO().WantTextInput && !st.editEnding) {
    if (key == GLFW_KEY_ESCAPE) {
      say(st, "edit cancelled (Esc again quits)");
      st.editEnding = true;
    }
    return;
  }
  if (key == GLFW_KEY_ESCAPE && ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopup)) {
    say(st, "list closed (Esc again quits)");
    st.closeLists = true;
    return;
  }
  if (key == GLFW_KEY_ESCAPE) {
    say(st, "quit");
    glfwSetWindowShouldClose(w, GLFW_TRUE);
    return;
  }
  Session& s = st.session;
  const int passCount = passesRun(s);
  switch (key) {
    case GLFW_KEY_SPACE:
      st.paused = !st.paused;
      say(st, st.paused ? "paused" : "running");
      return;
    case GLFW_KEY_TAB:
      st.view = static_cast<View>((static_cast<int>(st.view) + ((mods & GLFW_MOD_SHIFT) ? kViews - 1 : 1)) % kViews);
      sayView(st);
      return;
    case GLFW_KEY_P:
      st.passStep = (mods & GLFW_MOD_SHIFT) ? (st.passStep < 0 ? passCount - 1 : st.passStep - 1)
                                            : (st.passStep + 1 >= passCount ? -1 : st.passStep + 1);
      sayStep(st);
      return;
    case GLFW_KEY_S: ((mods & GLFW_MOD_SHIFT) ? st.windowScreenshot : st.screenshot) = true; return;
    case GLFW_KEY_PAGE_DOWN: goToLesson(w, st, st.lessonIndex + 1); return;
    case GLFW_KEY_PAGE_UP: goToLesson(w, st, st.lessonIndex - 1); return;
    case GLFW_KEY_F1:
      st.panel = !st.panel;
      if (st.panel) showPanelAtAScaleItHolds(w, st);
      st.scaleShown = st.uiScale;
      st.sayLayout = true;
      return;
    case GLFW_KEY_R:
      s.camera = findVariant(s.info, s.variant).camera.value_or(s.info.camera);
      say(st, "camera reset");
      return;
    case GLFW_KEY_F2: {
      // The panel's figure, with the frames counted since the window opened and the window's clock,
      // so a test can set it against frames over wall time; then the lesson's time, the panel's t.
      char line[256];
      std::snprintf(line, sizeof line,
                    "frame rate: %.2f fps, %.2f ms a frame (%zu frames in the last %.2f s); frame %lld at %.3f s on "
                    "the window's clock; the lesson's t = %.3f s%s",
                    st.rate.fps(), st.rate.msPerFrame(), st.rate.intervals(),
                    st.rate.fps() > 0 ? static_cast<double>(st.rate.intervals()) / st.rate.fps() : 0.0,
                    st.rate.frames(), glfwGetTime(), st.time,
                    st.paused ? ", paused" : st.passStep >= 0 ? ", held" : "");
      if (st.frameLog) st.frameLog->flush();
      tell(st, line);
      return;
    }
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: setUiScale(st, st.uiScale + kUiScaleStep, w); return;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: setUiScale(st, st.uiScale - kUiScaleStep); return;
    case GLFW_KEY_V: {
      const auto& vs = s.info.variants;
      auto it = std::find_if(vs.begin(), vs.end(), [&](const Variant& v) { return v.name == s.variant; });
      switchVariant(s, std::next(it) == vs.end() ? vs.front().name : std::next(it)->name);
      say(st, "variant: " + s.variant);
      return;
    }
    default: break;
  }
  // An option's key steps it forward, with shift back, round from one end to the other.
  const int way = (mods & GLFW_MOD_SHIFT) ? -1 : 1;
  for (std::size_t i = 0; i < s.options.size(); ++i)
    if (Option& o = s.options[i]; std::toupper(static_cast<unsigned char>(o.key)) == key) {
      o.value = steppedValue(o, way);
      st.stepped = {i, way};
      optionChanged(st, o);
    }
}

void onMouseButton(GLFWwindow* w, int button, int action, int) {
  WindowState& st = stateOf(w);
  if (button == GLFW_MOUSE_BUTTON_RIGHT)
    st.pointing = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  st.dragging = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
  glfwGetCursorPos(w, &st.lastX, &st.lastY);
}

void onCursor(GLFWwindow* w, double x, double y) {
  WindowState& st = stateOf(w);
  if (!st.dragging) return;
  OrbitCamera& c = st.session.camera;
  c.azimuthDeg -= static_cast<float>(x - st.lastX) * 0.4f;
  c.elevationDeg = std::clamp(c.elevationDeg + static_cast<float>(y - st.lastY) * 0.4f, -89.0f, 89.0f);
  st.lastX = x, st.lastY = y;
}

void onScroll(GLFWwindow* w, double, double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  OrbitCamera& c = stateOf(w).session.camera;
  c.distance = std::clamp(c.distance * static_cast<float>(std::pow(0.9, dy)), 0.5f, 80.0f);
}

// Shows an image (top row first) in the window, scaled to fit, centred.
class Display {
 public:
  Display() {
    glGenTextures(1, &texture_);
    glGenFramebuffers(1, &fbo_);
  }
  ~Display() {
    glDeleteTextures(1, &texture_);
    glDeleteFramebuffers(1, &fbo_);
  }
  void show(const Image& image, int areaX, int areaW, int areaH) {
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    blitFit(image.width, image.height, areaX, areaW, areaH, true);
  }
  // The framebuffer bound for reading is shown as it is (bottom row first, GL's way), fitted into
  // the picture's area: the window from areaX on, areaW x areaH.
  static void blitFit(int w, int h, int areaX, int areaW, int areaH, bool flip) {
    const float scale = std::min(static_cast<float>(areaW) / static_cast<float>(w),
                                 static_cast<float>(areaH) / static_cast<float>(h));
    const int dw = static_cast<int>(static_cast<float>(w) * scale),
              dh = static_cast<int>(static_cast<float>(h) * scale);
    const int x0 = areaX + (areaW - dw) / 2, y0 = (areaH - dh) / 2;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBlitFramebuffer(0, 0, w, h, x0, flip ? y0 + dh : y0, x0 + dw, flip ? y0 : y0 + dh, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }

 private:
  GLuint texture_ = 0, fbo_ = 0;
};

// What the panel's last layout measured, for the line the window says about it.
struct PanelFit {
  float contentBottom = 0, height = 0;  // screen pixels: the last widget's bottom, the panel's height
  std::vector<std::string> cut;         // labels or choices drawn narrower than their text
  float optionsShown = 0, optionsWanted = 0;  // the options' scrolling area and what they need
  bool keysListed = false;                    // the keys' section open
};

// A combo box the panel's full width, its choice shown after `label` ("variant [V]: ops"), else
// after its keys' `hint` alone ("[PgUp/Dn] 08-shadow-volumes-counting"), else alone with the label
// on a line of its own above it: the keys' hint is never dropped. Its list is as wide as its widest
// choice: no name is cut. Returns the choice picked this frame, if any.
template <typename Names>
std::optional<std::string> fullWidthCombo(const char* id, const std::string& label, const std::string& hint,
                                          const std::string& current, const Names& names, PanelFit& fit) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float arrow = ImGui::GetFrameHeight(), width = ImGui::GetContentRegionAvail().x;
  const auto fits = [&](const std::string& text) {
    return ImGui::CalcTextSize(text.c_str()).x + style.FramePadding.x * 2 + arrow <= width;
  };
  std::string preview = label + ": " + current;
  if (!fits(preview)) preview = hint + " " + current;
  if (!fits(preview)) {
    ImGui::TextUnformatted(label.c_str());
    preview = current;
  }
  if (!fits(preview)) fit.cut.push_back(preview);
  float widest = 0;
  for (const std::string& n : names) widest = std::max(widest, ImGui::CalcTextSize(n.c_str()).x);
  ImGui::SetNextWindowSizeConstraints(
      ImVec2(std::max(width, widest + style.WindowPadding.x * 2 + style.ScrollbarSize), 0),
      ImVec2(1e6f, ImGui::GetTextLineHeightWithSpacing() * 20 + style.WindowPadding.y * 2));
  ImGui::SetNextItemWidth(width);
  std::optional<std::string> picked;
  if (ImGui::BeginCombo(id, preview.c_str())) {
    for (const std::string& n : names)
      if (ImGui::Selectable(n.c_str(), n == current)) picked = n;
    ImGui::EndCombo();
  }
  return picked;
}

// An integer slider `width` wide with `label` beside it, its text beside its grab rather than over
// it: in the wider of the two parts of the frame the grab leaves, `text` where it fits there, else
// (`textBelow`) `shortText` there and `text` wrapped on a line of its own under the slider, else as
// much of it as fits with "..." (said as cut where `keepFull`: a value's name), else `shortText`
// (else that, clipped, and said as cut). While a typed edit is open (ctrl+click) ImGui draws the
// field. Returns whether the value changed; `hovered` says whether the pointer is on it.
bool sliderBesideGrab(const std::string& label, int* value, int min, int max, const std::string& text,
                      const std::string& shortText, float width, bool& hovered, PanelFit& fit,
                      bool textBelow = false, bool keepFull = false) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const std::string id = "##" + label;
  const bool typing = ImGui::TempInputIsActive(ImGui::GetID(id.c_str()));
  // ImGui's own text (the number) drawn invisible: it would sit centred, over the grab.
  if (!typing) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0, 0, 0, 0));
  ImGui::SetNextItemWidth(width);
  const bool changed = ImGui::SliderInt(id.c_str(), value, min, max, "%d");
  if (!typing) ImGui::PopStyleColor();
  hovered = ImGui::IsItemHovered();
  bool below = false;
  if (!typing) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    // The grab as ImGui 1.86 places it (SliderBehaviorT): 2 px in from the frame, an integer
    // slider's grab 1 / (range + 1) of the frame wide, at least GrabMinSize.
    const float padding = 2.0f, track = b.x - a.x - 2 * padding;
    const int range = std::max(max - min, 0);
    const float grab = std::min(std::max(track / static_cast<float>(range + 1), style.GrabMinSize), track);
    const float t = range > 0 ? static_cast<float>(std::clamp(*value, min, max) - min) / static_cast<float>(range) : 0.0f;
    const float grabLeft = a.x + padding + t * (track - grab), grabRight = grabLeft + grab;
    const float leftFrom = a.x + style.FramePadding.x, leftTo = grabLeft - style.FramePadding.x;
    const float rightFrom = grabRight + style.FramePadding.x, rightTo = b.x - style.FramePadding.x;
    const bool right = rightTo - rightFrom >= leftTo - leftFrom;
    const float from = right ? rightFrom : leftFrom, to = right ? rightTo : leftTo;
    // Else the longest start of `text` that fits with "..." (the number first: "8: shadows (li..."),
    // else the short text.
    std::string shown = text;
    if (ImGui::CalcTextSize(shown.c_str()).x > to - from && textBelow && text != shortText) {
      shown = shortText;
      below = true;
    } else if (ImGui::CalcTextSize(shown.c_str()).x > to - from) {
      shown = shortText;
      for (std::size_t n = text.size(); n-- > shortText.size();)
        if (const std::string start = text.substr(0, n) + "..."; ImGui::CalcTextSize(start.c_str()).x <= to - from) {
          shown = start;
          break;
        }
      if (keepFull) fit.cut.push_back(label + " " + shown);
    }
    const float w = ImGui::CalcTextSize(shown.c_str()).x;
    if (w > to - from) fit.cut.push_back(label + " " + shown);
    const float x = w > to - from ? from : from + (to - from - w) / 2;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(ImVec2(from, a.y), ImVec2(std::max(from, to), b.y), true);
    draw->AddText(ImVec2(x, a.y + style.FramePadding.y), ImGui::GetColorU32(ImGuiCol_Text), shown.c_str());
    draw->PopClipRect();
  }
  ImGui::SameLine(0, style.ItemInnerSpacing.x);
  ImGui::TextUnformatted(label.c_str());
  hovered = hovered || ImGui::IsItemHovered();
  if (below) {
    ImGui::TextWrapped("%s", text.c_str());
    hovered = hovered || ImGui::IsItemHovered();
  }
  return changed;
}

// Lays the panel out to fit the window. The options take the room the controls below them leave
// and scroll within it where they need more; below them the views, the pass stepper, pause and the
// frame rate always show. What else there is folds to give the options the room they want: the
// views as a list in one row instead of radio buttons, then the keys, then the draw calls and the
// lesson's counts (each a section under a header, open where there is room; a click opens or folds
// it until the layout next changes). Two-state options sit side by side where they fit. Returns
// what it measured.
PanelFit drawPanel(GLFWwindow* window, WindowState& st, float height) {
  Session& s = st.session;
  PanelFit fit;
  fit.height = height;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(panelWidth(st.uiScale)), height));
  // No keyboard navigation in the panel: Tab is the lesson's (the view), never a jump into a
  // slider's text field that would keep the keys from then on. The lesson's title in the title bar,
  // which a compact panel leaves out (the lesson list names the lesson).
  ImGui::Begin((s.info.title + "###panel").c_str(), nullptr,
               ImGuiWindowFlags_NoNavInputs | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_NoCollapse | (st.compact ? ImGuiWindowFlags_NoTitleBar : 0));
  ImGui::PushAllowKeyboardFocus(false);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float full = ImGui::GetContentRegionAvail().x;
  const auto label = [](const Option& o) { return o.name + " [" + o.key + "]"; };
  // Sliders leave room for the widest label beside them.
  float widestLabel = ImGui::CalcTextSize("after pass [P]").x;
  for (const Option& o : s.options)
    if (!(o.min == 0 && o.max == 1)) widestLabel = std::max(widestLabel, ImGui::CalcTextSize(label(o).c_str()).x);
  const float stepperWidth = std::max(full - widestLabel - style.ItemInnerSpacing.x, full * 0.4f);
  // Cut: drawn past the right edge of the window (or child) it is in, taken where a row starts.
  float edge = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
  const auto rightEdge = [&] { return edge; };
  const auto checkCut = [&](const std::string& text) {
    if (ImGui::GetItemRectMax().x > rightEdge() + 0.5f) fit.cut.push_back(text);
  };

  if (st.lessonIndex >= 0) {
    std::vector<std::string> names;
    for (const auto& l : st.course) names.push_back(l.filename().string());
    const std::string current = names[static_cast<std::size_t>(st.lessonIndex)];
    if (const auto n = fullWidthCombo("##lesson", "lesson [PgUp PgDn]", "[PgUp/Dn]", current, names, fit))
      goToLesson(window, st, static_cast<int>(std::find(names.begin(), names.end(), *n) - names.begin()));
  }
  std::vector<std::string> variants;
  for (const Variant& v : s.info.variants) variants.push_back(v.name);
  if (const auto n = fullWidthCombo("##variant", "variant [V]", "[V]", s.variant, variants, fit);
      n && *n != s.variant) {
    switchVariant(s, *n);
    say(st, "variant: " + s.variant);
  }

  // What the controls below the options need (the heights of rows, a wrapped text and the views'
  // radio buttons computed; the rest measured in the last frame, the first frame's guess corrected
  // by the second), and what folds where the options want the room.
  const std::string keys = std::string("drag: orbit, wheel: zoom, R: reset, S: screenshot (shift: with the panel), "
                                       "PgDn PgUp: next, previous lesson, F1: hide the panel, + -: UI scale, "
                                       "F2: say the frame rate and time, Esc: quit") +
                           (s.info.brush ? ", right drag: the lesson's brush" : "");
  const float row = ImGui::GetFrameHeightWithSpacing(), line = ImGui::GetTextLineHeightWithSpacing();
  const float keysBody = ImGui::CalcTextSize(keys.c_str(), nullptr, false, full).y + style.ItemSpacing.y;
  const float statsBody = line * static_cast<float>(1 + s.recorder->counts().size());
  float radioRows = 1;
  float x = ImGui::CalcTextSize("view [Tab]").x;
  for (int v = 0; v < kViews; ++v) {
    const float w = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(kViewNames[v]).x;
    if (x + style.ItemSpacing.x + w <= full)
      x += style.ItemSpacing.x + w;
    else
      x = w, radioRows += 1;
  }
  const float room = height - style.WindowPadding.y - ImGui::GetCursorPosY();
  const float fixed = st.fixedBelow > 0 ? st.fixedBelow : 4 * row;
  const float wanted = st.optionsHeight > 0 ? st.optionsHeight : (s.options.empty() ? 0.0f : 1e6f);
  // Full (the title bar, the radio buttons, separators) where the options then have the room they
  // want, else compact: decided on the room with the title bar, so the choice does not flip.
  const float separator = style.ItemSpacing.y;  // a separator's height in the layout
  const float titled = room - (st.compact ? ImGui::GetFrameHeight() : 0.0f);
  if (st.optionsHeight > 0 || s.options.empty())  // the first frame keeps the title bar: nothing measured yet
    st.compact = wanted + fixed + 2 * separator + radioRows * row > titled;
  const bool radios = !st.compact;
  const float views = radios ? radioRows * row + 2 * separator : row;
  // The sections open or fold when the layout changes (F1, a resize, the UI scale); in between a
  // click on a header decides.
  const bool relayout = st.sayLayout;
  if (relayout) {
    st.keysOpen = wanted + fixed + views + keysBody <= room;
    st.statsOpen = wanted + fixed + views + (st.keysOpen ? keysBody : 0.0f) + statsBody <= room;
  }
  // A section a click opened keeps the panel within the window: where both sections do not fit
  // above the options' least (two rows), the one opened earlier folds, and one still too tall
  // scrolls in the room left (the spacing after its region counted in it).
  const float optionsLeast = s.options.empty() ? 0.0f : std::min(wanted, 2 * row);
  const float sectionRoom = std::max(line, room - fixed - views - optionsLeast);
  if (!relayout && st.keysOpen && st.statsOpen && keysBody + statsBody > sectionRoom) {
    (st.statsOpenedLast ? st.keysOpen : st.statsOpen) = false;
    say(st, st.statsOpenedLast ? "the keys folded (room for the draw calls and counts)"
                               : "the draw calls and counts folded (room for the keys)");
  }
  const float keysShown = std::min(keysBody, sectionRoom), statsShown = std::min(statsBody, sectionRoom);
  const float optionsTop = ImGui::GetCursorPosY() - (st.compact ? 0.0f : ImGui::GetFrameHeight());
  if (!s.options.empty()) {
    const float open = (st.keysOpen ? keysShown : 0.0f) + (st.statsOpen ? statsShown : 0.0f);
    const float shown = std::max(std::min(wanted, room - fixed - views - open), 2 * row);
    fit.optionsShown = shown, fit.optionsWanted = st.optionsHeight;  // 0 until measured: not said
    ImGui::BeginChild("##options", ImVec2(0, shown), false, ImGuiWindowFlags_NoNavInputs);
    const float inner = ImGui::GetContentRegionAvail().x, panelEdge = edge;
    edge = ImGui::GetCursorScreenPos().x + inner;
    const float sliderWidth = std::max(inner - widestLabel - style.ItemInnerSpacing.x, inner * 0.4f);
    bool sameRow = false;  // the last widget was a checkbox that may take one beside it
    for (Option& o : s.options) {
      const std::string text = label(o);
      bool hovered = false;
      if (o.min == 0 && o.max == 1) {
        const float w = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(text.c_str()).x;
        if (sameRow && ImGui::GetItemRectMax().x + style.ItemSpacing.x + w <= rightEdge())
          ImGui::SameLine();
        bool on = o.value != 0;
        if (ImGui::Checkbox(text.c_str(), &on)) {
          o.value = on ? 1 : 0;
          optionChanged(st, o);
        }
        hovered = ImGui::IsItemHovered();
        sameRow = true;
      } else {
        // The value's name where it fits beside the grab, else the number there and the name on a
        // line of its own under the slider: a named value is never shortened.
        const std::string name = valueName(o, o.value), number = std::to_string(o.value);
        if (sliderBesideGrab(text, &o.value, o.min, o.max, name.empty() ? number : number + ": " + name, number,
                             sliderWidth, hovered, fit, true, true))
          optionChanged(st, o);
        sameRow = false;
      }
      checkCut(text);
      if (hovered) {  // wrapped to the window's width: a long help stays on screen
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(std::max(ImGui::GetFontSize() * 10.0f,
                                        ImGui::GetIO().DisplaySize.x - ImGui::GetIO().MousePos.x - ImGui::GetFontSize() * 2.0f));
        ImGui::TextUnformatted(o.help.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
    }
    st.optionsHeight = ImGui::GetCursorPosY() - style.ItemSpacing.y;
    ImGui::EndChild();
    edge = panelEdge;
  }
  const float bottomStart = ImGui::GetCursorPosY();

  float separators = 0;  // their height, measured: the fixed part below does not count them
  const auto separate = [&] {
    if (st.compact) return;
    const float top = ImGui::GetCursorPosY();
    ImGui::Separator();
    separators += ImGui::GetCursorPosY() - top;
  };
  separate();
  const float viewsStart = ImGui::GetCursorPosY();
  const View viewBefore = st.view;
  if (radios) {
    ImGui::AlignTextToFramePadding();  // on the radio buttons' line
    ImGui::TextUnformatted("view [Tab]");
    int view = static_cast<int>(st.view);
    for (int v = 0; v < kViews; ++v) {
      const float w = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(kViewNames[v]).x;
      if (ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + style.ItemSpacing.x + w <= style.WindowPadding.x + full)
        ImGui::SameLine();
      ImGui::RadioButton(kViewNames[v], &view, v);
    }
    st.view = static_cast<View>(view);
  } else {
    const std::vector<std::string> names(std::begin(kViewNames), std::end(kViewNames));
    if (const auto n = fullWidthCombo("##view", "view [Tab]", "[Tab]", kViewNames[static_cast<int>(st.view)], names, fit))
      st.view = static_cast<View>(std::find(names.begin(), names.end(), *n) - names.begin());
  }
  if (st.view != viewBefore) sayView(st);
  const float viewsEnd = ImGui::GetCursorPosY();
  const std::string passName = stepName(s, st.passStep);
  bool hovered = false;
  const std::string stepNumber = std::to_string(st.passStep + 1);
  if (sliderBesideGrab("after pass [P]", &st.passStep, -1, passesRun(s) - 1,
                       st.passStep < 0 ? passName : stepNumber + ": " + passName,
                       st.passStep < 0 ? "finished" : stepNumber, stepperWidth, hovered, fit))
    sayStep(st);
  if (hovered) ImGui::SetTooltip("%s", passName.c_str());  // the name the slider may have shortened
  checkCut("after pass [P]");
  if (ImGui::Checkbox("pause [Space]", &st.paused)) say(st, st.paused ? "paused" : "running");
  ImGui::SameLine();
  ImGui::Text(st.passStep >= 0 ? "t = %.2f s, held" : "t = %.2f s", st.time);
  separate();
  // Frames in the last second, not a smoothed 1/dt: right within a second of any change of rate.
  // Under it the draw calls and the lesson's own counts (Frame::count: what an option such as
  // lesson 14's oracle found), opened when an option brought counts of its own (lesson 14's K).
  bool newCounts = false;
  for (const auto& [name, n] : s.recorder->counts())
    newCounts = newCounts || std::find(st.countsBefore.begin(), st.countsBefore.end(), name) == st.countsBefore.end();
  if (st.sayCountsAfter == 0 && newCounts) st.statsOpen = true;
  char rate[96];
  std::snprintf(rate, sizeof rate, "%.1f fps, %.1f ms a frame###stats", st.rate.fps(), st.rate.msPerFrame());
  ImGui::SetNextItemOpen(st.statsOpen);
  float bodies = 0;
  // A click on a header says its line, as every other click does.
  const bool statsWere = st.statsOpen;
  st.statsOpen = ImGui::CollapsingHeader(rate);
  if (st.statsOpen != statsWere) {
    say(st, st.statsOpen ? "the draw calls and counts shown" : "the draw calls and counts folded");
    st.statsOpenedLast = st.statsOpen;
    st.sayFit = true;
  }
  if (st.statsOpen) {
    const float top = ImGui::GetCursorPosY();
    const bool scrolls = statsBody > statsShown + 0.5f;
    if (scrolls) ImGui::BeginChild("##stats", ImVec2(0, statsShown - style.ItemSpacing.y), false, ImGuiWindowFlags_NoNavInputs);
    std::uint64_t draws = 0, triangles = 0;
    for (const PassStats& p : s.recorder->passStats()) draws += p.drawCalls, triangles += p.triangles;
    ImGui::Text("%llu draw calls, %llu triangles", static_cast<unsigned long long>(draws),
                static_cast<unsigned long long>(triangles));
    for (const auto& [name, n] : s.recorder->counts())
      ImGui::TextWrapped("%s %llu", name.c_str(), static_cast<unsigned long long>(n));
    if (scrolls) ImGui::EndChild();
    bodies += ImGui::GetCursorPosY() - top;
  }
  ImGui::SetNextItemOpen(st.keysOpen);
  const bool keysWere = st.keysOpen;
  st.keysOpen = ImGui::CollapsingHeader("keys");
  if (st.keysOpen != keysWere) {
    say(st, st.keysOpen ? "the keys listed" : "the keys folded");
    if (st.keysOpen) st.statsOpenedLast = false;
    st.sayFit = true;
  }
  if (st.keysOpen) {
    const float top = ImGui::GetCursorPosY();
    const bool scrolls = keysBody > keysShown + 0.5f;
    if (scrolls) ImGui::BeginChild("##keys", ImVec2(0, keysShown - style.ItemSpacing.y), false, ImGuiWindowFlags_NoNavInputs);
    ImGui::TextWrapped("%s", keys.c_str());
    if (scrolls) ImGui::EndChild();
    bodies += ImGui::GetCursorPosY() - top;
  }
  fit.keysListed = st.keysOpen;
  st.fixedBelow = ImGui::GetCursorPosY() - bottomStart - bodies - (viewsEnd - viewsStart) - separators;
  // Compact, without a title bar, the options two rows, the views a list and both sections folded.
  st.leastPanelScale = st.uiScale;
  st.leastPanelHeight = optionsTop + (s.options.empty() ? 0.0f : 2 * row + style.ItemSpacing.y) + row + st.fixedBelow +
                        style.WindowPadding.y;
  fit.contentBottom = ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y;
  ImGui::PopAllowKeyboardFocus();
  ImGui::End();
  return fit;
}

// The line tell() shows: wrapped across the top of the picture's area (from x = left, width wide;
// the legends are at its foot) in the panel's font, on the panel's background, taking no clicks.
void drawStatus(const std::string& line, float left, float width) {
  const float pad = ImGui::GetStyle().WindowPadding.x;
  ImGui::SetNextWindowPos(ImVec2(left + pad, pad));
  ImGui::SetNextWindowSize(ImVec2(std::max(width - 2 * pad, 1.0f), 0));  // 0: as high as the text
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoSavedSettings);
  // Broken at spaces only: ImGui's own wrapping also breaks after a full stop, inside a number.
  const float wrap = ImGui::GetContentRegionAvail().x;
  std::string row;
  for (std::size_t at = 0; at < line.size();) {
    const std::size_t end = std::min(line.find(' ', at), line.size());
    const std::string word = line.substr(at, end - at), longer = row.empty() ? word : row + " " + word;
    if (!row.empty() && ImGui::CalcTextSize(longer.c_str()).x > wrap) {
      ImGui::TextUnformatted(row.c_str());
      row = word;
    } else {
      row = longer;
    }
    at = end + 1;
  }
  ImGui::TextUnformatted(row.c_str());
  ImGui::End();
}

// Columns x0 .. x0 + width of an image.
Image crop(const Image& image, int x0, int width) {
  Image out(width, image.height, image.channels);
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.at(x0, y), static_cast<std::size_t>(width * image.channels), out.at(0, y));
  return out;
}

void saveScreenshot(WindowState& st, const Image& image) {
  char name[128];
  do  // the next number free in the folder: an earlier run's screenshots are kept
    std::snprintf(name, sizeof name, "screenshot-%s-%03d.png", st.session.info.id.c_str(), st.screenshots++);
  while (std::filesystem::exists(name));
  writePng(name, image);
  st.status = "saved " + (std::filesystem::current_path() / name).string();
  st.statusUntil = glfwGetTime() + 6.0;
  std::cerr << st.status << "\n";
}

// The fonts and sizes for a UI scale: the default font rebuilt at 13 px x scale (crisp, not
// stretched), the style's sizes scaled from the defaults. Between frames only.
void applyUiScale(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImFontConfig font;
  font.SizePixels = std::round(13.0f * scale);
  io.Fonts->AddFontDefault(&font);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGuiStyle& style = ImGui::GetStyle();
  style = ImGuiStyle();
  ImGui::StyleColorsDark(&style);
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;  // an open list hides the panel under it (projected, see-through reads as noise)
  style.ScaleAllSizes(scale);
}

// The legends' digits, 5 dots high, as high as the panel's text (13 px x the UI scale): pixels a dot.
int legendDot(float uiScale) {
  return std::max(2, static_cast<int>(std::lround(13.0f * uiScale / 5.0f)));
}

// The stencil views' pictures, the framebuffer's size: the values in grey (stretched: the largest
// value present white) or each in its colour, with the legend below, its digits and counts the
// panel's text size (legendDot) and at most a fifth (a third above scale 1) of
// the height, the values past that counted as "+N"; or the bit planes. The legend keeps its size
// on screen: the picture above it is shrunk to make its room, not the legend with it.
Image stencilViewPicture(View view, const Image& stencil, float uiScale) {
  if (view == View::StencilBits) return stencilBitPlanes(stencil, uiScale);
  const int k = std::max(1, static_cast<int>(std::lround(uiScale))), dot = legendDot(uiScale);
  // An entry row is 7 dots and 4 px x k: as many rows as fit in a fifth of the picture at scale 1,
  // a third above it (the larger digits need the rows), at least one.
  const int share = k > 1 ? 3 : 5;
  const Image ramp = stencilRamp(stencil, {.legendScale = k,
                                           .maxLegendRows = std::max(1, stencil.height / share / (7 * dot + 4 * k)),
                                           .grey = view == View::StencilGrey,
                                           .textPixels = dot});
  const int band = ramp.height - stencil.height, room = std::max(1, stencil.height - band);
  // The picture fitted into the room above the band (nearest pixel), centred, on the window's grey.
  const float fit = std::min(1.0f, static_cast<float>(room) / static_cast<float>(stencil.height));
  const int w = std::max(1, static_cast<int>(static_cast<float>(stencil.width) * fit)),
            h = std::max(1, static_cast<int>(static_cast<float>(stencil.height) * fit));
  const int x0 = (stencil.width - w) / 2, y0 = (room - h) / 2;
  Image out(stencil.width, stencil.height, 4);
  for (std::size_t i = 0; i < out.pixels.size(); i += 4)
    out.pixels[i] = out.pixels[i + 1] = out.pixels[i + 2] = 25, out.pixels[i + 3] = 255;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      std::copy_n(ramp.at(x * stencil.width / w, y * stencil.height / h), 4, out.at(x0 + x, y0 + y));
  for (int y = 0; y < band && room + y < out.height; ++y)
    std::copy_n(ramp.at(0, stencil.height + y), static_cast<std::size_t>(4 * stencil.width), out.at(0, room + y));
  return out;
}

// A window larger than the screen's work area (--size 1280x720 and the panel on a 1280x720
// projector) is shrunk to fit it, using its whole height and width, and moved onto it; one
// that fits but lies past its edge (--position) is moved onto it; one line says so. A --frames
// run (a test against a golden) keeps its size.
void fitToScreen(GLFWwindow* w, WindowState& st) {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (!monitor) return;
  int ax = 0, ay = 0, aw = 0, ah = 0, ww = 0, wh = 0, x = 0, y = 0;
  glfwGetMonitorWorkarea(monitor, &ax, &ay, &aw, &ah);
  glfwGetWindowSize(w, &ww, &wh);
  if (aw <= 0 || ah <= 0) return;
  if (ww <= aw && wh <= ah) {  // it fits: only a --position past the screen's edge moves it
    glfwGetWindowPos(w, &x, &y);
    const int onX = std::clamp(x, ax, ax + aw - ww), onY = std::clamp(y, ay, ay + ah - wh);
    if (onX == x && onY == y) return;
    glfwSetWindowPos(w, onX, onY);
    say(st, "the window is moved onto the screen's " + std::to_string(aw) + "x" + std::to_string(ah) + ": at " +
                std::to_string(onX) + "," + std::to_string(onY) + ", not " + std::to_string(x) + "," + std::to_string(y));
    return;
  }
  // Each side shrunk to the room the screen has: the picture may take another shape (a 16:9
  // picture beside the panel on a 16:9 screen), but no screen height is left unused.
  const int panel = st.panel ? std::min(panelWidth(st.uiScale), aw / 2) : 0;
  const int pictureW = std::max(1, ww - panel), pictureH = std::max(1, wh);
  const int fitW = std::clamp(aw - panel, 1, pictureW), fitH = std::clamp(ah, 1, pictureH);
  glfwSetWindowSize(w, fitW + panel, fitH);
  glfwGetWindowPos(w, &x, &y);
  glfwSetWindowPos(w, std::clamp(x, ax, ax + aw - (fitW + panel)), std::clamp(y, ay, ay + ah - fitH));
  const bool reshaped = static_cast<long long>(fitW) * pictureH != static_cast<long long>(fitH) * pictureW;
  say(st, "the window fits the screen's " + std::to_string(aw) + "x" + std::to_string(ah) + ": the picture is " +
              std::to_string(fitW) + "x" + std::to_string(fitH) + ", not " + std::to_string(pictureW) + "x" +
              std::to_string(pictureH) + (reshaped ? " (its aspect ratio changed to use the screen's room)" : ""));
}

}  // namespace

int runWindow(Session& s) {
  GLFWwindow* window = s.context->window();
  const CommandLine& cl = s.commandLine;
  WindowState st{.session = s, .time = cl.time};
  st.course = courseLessons();
  st.panel = !cl.frames && !cl.panelHidden;  // a --frames run is a test: the window is the picture alone
  st.view = static_cast<View>(std::clamp(cl.view, 0, kViews - 1));
  st.sayLayout = true;
  if (const char* log = std::getenv("STENCIL_FRAME_LOG"); log && *log)
    st.frameLog = std::make_unique<std::ofstream>(log);
  for (std::size_t i = 0; i < st.course.size(); ++i)
    if (st.course[i].filename() == s.info.id) st.lessonIndex = static_cast<int>(i);
  // With the panel hidden nothing else on screen names the lesson (Page Down's, Page Up's): shown too.
  const std::string opened = "lesson " + s.info.id + ": " + s.info.title +
                             (st.lessonIndex >= 0 ? " (" + std::to_string(st.lessonIndex + 1) + " of " +
                                                        std::to_string(st.course.size()) + " in the course)"
                                                  : std::string());
  if (st.panel || cl.frames)
    say(st, opened);
  else
    tell(st, opened);
  // The UI scale: --ui-scale, else the monitor's content scale (a HiDPI screen's, or what the
  // desktop sets for a projector). The window opened --size plus the panel at --ui-scale or 1.
  float monitorScale = 1.0f, unused = 1.0f;
  glfwGetWindowContentScale(window, &monitorScale, &unused);
  st.uiScale = std::clamp(cl.uiScale.value_or(monitorScale), kMinUiScale, kMaxUiScale);
  st.scaleShown = st.uiScale;
  if (st.panel && st.uiScale != cl.uiScale.value_or(1.0f))
    glfwSetWindowSize(window, cl.width + panelWidth(st.uiScale), cl.height);
  if (cl.position) glfwSetWindowPos(window, cl.position->first, cl.position->second);
  if (!cl.frames) fitToScreen(window, st);
  if (st.view != View::Colour) say(st, std::string("view: ") + viewName(st.view));
  glfwSetWindowUserPointer(window, &st);
  // Ours first: ImGui chains to the callbacks installed before it.
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  glfwSetWindowSizeCallback(window, [](GLFWwindow* w, int, int) { stateOf(w).sayLayout = true; });
  glfwSetWindowContentScaleCallback(window, [](GLFWwindow* w, float x, float) {
    if (!stateOf(w).session.commandLine.uiScale) setUiScale(stateOf(w), x);
  });
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exitCode = 0;
  {
    Display display;
    double last = glfwGetTime();
    // The variant and options of the last frame drawn: a change the lesson refuses (lesson 14's
    // method 0 with a scene file, say) is said in one line and undone, and the window goes on.
    std::string drawnVariant = s.variant;
    std::vector<Option> drawnOptions = s.options;
    OrbitCamera drawnCamera = s.camera;
    for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
      glfwPollEvents();
      if (st.scaleChanged) {
        applyUiScale(st.uiScale);
        st.scaleChanged = false;
      }
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      if (w == 0 || h == 0) {  // minimised: nothing to draw until it comes back
        glfwWaitEvents();
        continue;
      }
      // The picture's area: the window right of the panel, in framebuffer pixels (a HiDPI window
      // counts its panel in screen coordinates).
      int ww = 1, wh = 1;
      glfwGetWindowSize(window, &ww, &wh);
      const float sx = static_cast<float>(w) / static_cast<float>(std::max(ww, 1)),
                  sy = static_cast<float>(h) / static_cast<float>(std::max(wh, 1));
      const int areaX = st.panel ? std::min(static_cast<int>(static_cast<float>(panelWidth(st.uiScale)) * sx), w - 1) : 0;
      const int areaW = w - areaX;
      if (areaW != s.framebuffer->width() || h != s.framebuffer->height()) s.resize(areaW, h);

      // With --frames the window steps time exactly like a headless run, so its pixels
      // can be compared with a golden.
      const double now = glfwGetTime();
      if (cl.frames)
        st.time = cl.time + frame / 60.0;
      else if (!st.paused && st.passStep < 0)  // stepping holds time: the passes stay the ones shown
        st.time += now - last;
      last = now;

      // The pointer in framebuffer pixels (the framebuffer is the window's size; a HiDPI window
      // counts its cursor in screen coordinates), y up.
      s.pointer.reset();
      if (st.pointing) {
        double cx = 0, cy = 0;
        glfwGetCursorPos(window, &cx, &cy);
        s.pointer = glm::vec2(static_cast<float>(cx) * sx - static_cast<float>(areaX),
                              static_cast<float>(h) - static_cast<float>(cy) * sy);
      }
      // A variant switched to may run fewer passes: the step stays among those the last frame ran
      // (none yet in a framebuffer just made for a new size: the step is kept).
      if (passesRun(s) > 0) st.passStep = std::min(st.passStep, passesRun(s) - 1);
      const int step = st.passStep;
      s.uiScale = st.uiScale;
      s.saveShadowMasks = cl.frames && frame + 1 >= *cl.frames;  // --mask-out: the last frame, as headless
      const FrameRequest request{.measure = false,
                                 .captureAll = false,
                                 .captureOnly = step >= 0 ? std::optional<std::size_t>(step) : std::nullopt};
      try {
        s.renderFrame(st.time, request);
      } catch (const UsageError& e) {
        // A view the lesson refuses (lesson 14: the near plane inside the solid) is undone as a
        // variant or a setting is.
        const bool sameView = s.camera.view() == drawnCamera.view() &&
                              s.camera.projection(1.0f) == drawnCamera.projection(1.0f);
        if (s.variant == drawnVariant && s.options == drawnOptions && sameView) throw;  // nothing to undo
        const std::string refused = s.info.id + ": " + inWindowWords(e.what());
        // The change was a key's step of one option alone: its values beyond are tried.
        if (st.stepped) {
          std::vector<Option> others = s.options;
          others[st.stepped->first] = drawnOptions[st.stepped->first];
          if (others != drawnOptions || s.variant != drawnVariant || !sameView) st.stepped.reset();
        }
        const Option* stepped = st.stepped ? &drawnOptions[st.stepped->first] : nullptr;
        const std::string tried = stepped ? s.options[st.stepped->first].name + " " +
                                                std::to_string(s.options[st.stepped->first].value) : std::string();
        if (stepped && stepPastRefusals(st, drawnOptions, request)) {
          tell(st, refused + " (" + tried + " skipped)");
          optionChanged(st, s.options[st.stepped->first]);
        } else {
          tell(st, refused + (stepped ? " (" + stepped->name + " kept at " + std::to_string(stepped->value) + ")"
                                      : " (kept variant " + drawnVariant + ", its settings and the view)"));
          if (s.variant != drawnVariant) s.setVariant(drawnVariant);
          s.options = drawnOptions;
          s.camera = drawnCamera;
          s.renderFrame(st.time, request);
        }
      }
      st.stepped.reset();
      drawnVariant = s.variant;
      drawnOptions = s.options;
      drawnCamera = s.camera;
      const Snapshot* snap = nullptr;
      if (step >= 0)
        for (const Snapshot& sn : s.recorder->snapshots()) snap = &sn;
      if (st.sayCountsAfter == 0) {
        // The counts an option change brought (lesson 14's oracle_*), in one line.
        std::string line;
        for (const auto& [name, n] : s.recorder->counts())
          if (std::find(st.countsBefore.begin(), st.countsBefore.end(), name) == st.countsBefore.end())
            line += (line.empty() ? "" : ", ") + name + " " + std::to_string(n);
        if (!line.empty()) say(st, "counts: " + line);
      }

      Image shown;
      if (st.view == View::Colour && !snap) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, s.framebuffer->id());
        Display::blitFit(s.framebuffer->width(), s.framebuffer->height(), areaX, areaW, h, false);
      } else if (st.view == View::Depth) {
        DepthRange range;
        shown = depthPicture(snap ? snap->depth : s.framebuffer->readDepth(), s.framebuffer->width(),
                             s.framebuffer->height(), s.projection, s.reversedDepth, &range, legendDot(st.uiScale),
                             true);
        if (st.sayDepthRange) say(st, depthLegendLine(range));
        st.sayDepthRange = false;
        display.show(shown, areaX, areaW, h);
      } else {
        const Image stencil = snap ? snap->stencil : s.framebuffer->readStencil();
        shown = st.view == View::Colour ? snap->colour : stencilViewPicture(st.view, stencil, st.uiScale);
        display.show(shown, areaX, areaW, h);
      }

      const bool lastFrame = cl.frames && frame + 1 >= *cl.frames;
      if (st.screenshot || lastFrame) {
        // What the window shows, without the panel: read back from the window itself.
        const Image screen = crop(readColourPixels(0, w, h), areaX, areaW);
        if (st.screenshot) {
          saveScreenshot(st, screen);
          st.screenshot = false;
        }
        if (lastFrame) {
          exitCode = finishRun(s, screen, s.framebuffer->readStencil(), {});
          break;
        }
      }

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      replayImGuiTaps(window, st, true);
      ImGui::NewFrame();
      if (st.closeLists) ImGui::ClosePopupToLevel(0, true);
      st.closeLists = false;
      PanelFit fit;
      if (st.panel) fit = drawPanel(window, st, static_cast<float>(wh));
      if (glfwGetTime() < st.statusUntil) {
        const float left = st.panel ? static_cast<float>(panelWidth(st.uiScale)) : 0.0f;
        drawStatus(st.status, left, static_cast<float>(ww) - left);
      }
      if (st.sayCountsAfter >= 0) --st.sayCountsAfter;
      ImGui::Render();
      // A typed edit's start and end (Enter; Esc says its own line).
      if (ImGui::GetIO().WantTextInput && !st.editing) say(st, "editing a value: Enter sets it, Esc cancels");
      if (!ImGui::GetIO().WantTextInput && st.editing && !st.editEnding) say(st, "value set");
      st.editing = ImGui::GetIO().WantTextInput;
      replayImGuiTaps(window, st, false);
      const bool listOpen = ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopup);
      if (listOpen && !st.listOpen) say(st, "a list is open: click a choice, Esc closes it");
      st.listOpen = listOpen;
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, w, h);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (st.windowScreenshot) {  // the window as the class sees it, the panel too
        saveScreenshot(st, readColourPixels(0, w, h));
        st.windowScreenshot = false;
      }
      // Said two frames after the change: the panel's layout uses the heights its last frame
      // measured, and whether it is compact (no title bar) the frame before.
      if ((st.sayLayout || st.sayFit) && ++st.layoutFrames >= 3) {
        st.layoutFrames = 0;
        // One line for what changed the layout (F1, a resize, the UI scale): the picture's size,
        // and whether the panel's widgets fit its height and width.
        std::string line = std::string(st.panel ? "panel shown" : "panel hidden") + ": the picture is " +
                           std::to_string(areaW) + "x" + std::to_string(h) +
                           (st.panel ? " beside it, from x = " + std::to_string(areaX) : std::string());
        int wx = 0, wy = 0;
        glfwGetWindowPos(window, &wx, &wy);
        line += "; window " + std::to_string(ww) + "x" + std::to_string(wh) + " at " + std::to_string(wx) + "," +
                std::to_string(wy);
        line += "; ui scale " + scaleText(st.uiScale) + ", text " +
                std::to_string(static_cast<int>(std::round(13.0f * st.uiScale))) + " px";
        if (st.panel) {
          char room[96];
          if (fit.contentBottom <= fit.height)
            std::snprintf(room, sizeof room, "; the panel fits (%.0f of %.0f px)", fit.contentBottom, fit.height);
          else
            std::snprintf(room, sizeof room, "; the panel runs %.0f px past the bottom (it scrolls)",
                          fit.contentBottom - fit.height);
          line += room;
          if (fit.optionsShown + 0.5f < fit.optionsWanted)
            line += "; the options scroll (" + std::to_string(static_cast<int>(fit.optionsShown)) + " of " +
                    std::to_string(static_cast<int>(fit.optionsWanted)) + " px shown)";
          line += fit.keysListed ? "; the keys listed" : "; the keys folded";
          for (const std::string& c : fit.cut) line += "; cut: " + c;
        }
        say(st, line);
        st.sayLayout = st.sayFit = false;
      }
      glfwSwapBuffers(window);
      const double ended = glfwGetTime();
      st.rate.frameEnded(ended);
      if (st.frameLog) *st.frameLog << std::fixed << ended << "\n";
    }
  }
  // What the next lesson opens with: this window's picture size, place, scale, view and panel.
  if (s.nextLesson) {
    int ww = 0, wh = 0, x = 0, y = 0;
    glfwGetWindowSize(window, &ww, &wh);
    glfwGetWindowPos(window, &x, &y);
    const int pictureW = std::max(1, ww - (st.panel ? panelWidth(st.uiScale) : 0));
    s.nextLessonFlags = {"--size",     std::to_string(pictureW) + "x" + std::to_string(std::max(1, wh)),
                         "--position", std::to_string(x) + "," + std::to_string(y),
                         "--ui-scale", scaleText(st.uiScale),
                         "--view",     kViewNames[static_cast<int>(st.view)],
                         "--panel",    st.panel ? "shown" : "hidden"};
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return exitCode;
}

}  // namespace stencil
