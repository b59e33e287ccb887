// The classroom window: the lesson's framebuffer shown in a GLFW window, a Dear ImGui
// panel with the lesson's toggles, pass stepping through the pass recorder, the stencil
// inspector, an orbit camera and screenshots.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "gl/errors.h"
#include "gl/session.h"
#include "gl/stencil_view.h"

namespace stencil {
namespace {

enum class View { Colour, StencilRamp, StencilBits, Depth };
constexpr int kViews = 4;

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
};

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
         : v == View::StencilBits ? "bit planes"
                                  : "depth";
}

// Closes this lesson's window to open the course's lesson at `index` in its place (Session::nextLesson).
void goToLesson(GLFWwindow* w, WindowState& st, int index) {
  if (st.lessonIndex < 0 || index == st.lessonIndex) return;
  if (index < 0 || index >= static_cast<int>(st.course.size())) {
    say(st, index < 0 ? "the first lesson of the course" : "the last lesson of the course");
    return;
  }
  st.session.nextLesson = st.course[static_cast<std::size_t>(index)];
  say(st, "next: " + st.session.nextLesson->filename().string());
  glfwSetWindowShouldClose(w, GLFW_TRUE);
}

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
  if (action != GLFW_PRESS) return;
  // Esc always quits. Every other key is the lesson's, except while a panel field takes typed
  // text (a slider ctrl-clicked to type a number): then the keys are the field's.
  if (key == GLFW_KEY_ESCAPE) {
    glfwSetWindowShouldClose(w, GLFW_TRUE);
    return;
  }
  if (ImGui::GetIO().WantTextInput) return;
  WindowState& st = stateOf(w);
  Session& s = st.session;
  const int passCount = passesRun(s);
  switch (key) {
    case GLFW_KEY_SPACE:
      st.paused = !st.paused;
      say(st, st.paused ? "paused" : "running");
      return;
    case GLFW_KEY_TAB:
      st.view = static_cast<View>((static_cast<int>(st.view) + 1) % kViews);
      say(st, std::string("view: ") + viewName(st.view));
      st.sayDepthRange = st.view == View::Depth;
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
      st.sayLayout = true;
      return;
    case GLFW_KEY_R: s.camera = findVariant(s.info, s.variant).camera.value_or(s.info.camera); return;
    case GLFW_KEY_V: {
      const auto& vs = s.info.variants;
      auto it = std::find_if(vs.begin(), vs.end(), [&](const Variant& v) { return v.name == s.variant; });
      switchVariant(s, std::next(it) == vs.end() ? vs.front().name : std::next(it)->name);
      say(st, "variant: " + s.variant);
      return;
    }
    default: break;
  }
  for (Option& o : s.options)
    if (std::toupper(static_cast<unsigned char>(o.key)) == key) {
      o.value = o.value >= o.max ? o.min : o.value + 1;
      say(st, o.name + " = " + std::to_string(o.value));
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

void drawPanel(GLFWwindow* window, WindowState& st, double fps, float height) {
  Session& s = st.session;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(kWindowPanelWidth), height));
  // No keyboard navigation in the panel: Tab is the lesson's (the view), never a jump into a
  // slider's text field that would keep the keys from then on.
  ImGui::Begin(s.info.id.c_str(), nullptr,
               ImGuiWindowFlags_NoNavInputs | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_NoCollapse);
  ImGui::PushAllowKeyboardFocus(false);
  ImGui::PushItemWidth(-120.0f);  // the widgets leave room for their labels in the strip
  ImGui::TextUnformatted(s.info.title.c_str());
  if (st.lessonIndex >= 0 &&
      ImGui::BeginCombo("lesson [PgUp PgDn]",
                        st.course[static_cast<std::size_t>(st.lessonIndex)].filename().c_str())) {
    for (std::size_t i = 0; i < st.course.size(); ++i)
      if (ImGui::Selectable(st.course[i].filename().c_str(), static_cast<int>(i) == st.lessonIndex))
        goToLesson(window, st, static_cast<int>(i));
    ImGui::EndCombo();
  }
  if (ImGui::BeginCombo("variant [V]", s.variant.c_str())) {
    for (const Variant& v : s.info.variants)
      if (ImGui::Selectable(v.name.c_str(), v.name == s.variant)) switchVariant(s, v.name);
    ImGui::EndCombo();
  }
  for (Option& o : s.options) {
    const std::string label = o.name + " [" + o.key + "]";
    if (o.min == 0 && o.max == 1) {
      bool on = o.value != 0;
      if (ImGui::Checkbox(label.c_str(), &on)) o.value = on ? 1 : 0;
    } else {
      ImGui::SliderInt(label.c_str(), &o.value, o.min, o.max);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", o.help.c_str());
  }
  ImGui::Separator();
  int view = static_cast<int>(st.view);
  ImGui::RadioButton("colour", &view, 0);
  ImGui::SameLine();
  ImGui::RadioButton("stencil", &view, 1);
  ImGui::SameLine();
  ImGui::RadioButton("bits", &view, 2);
  ImGui::SameLine();
  ImGui::RadioButton("depth [Tab]", &view, 3);
  st.view = static_cast<View>(view);
  const std::string passName = stepName(s, st.passStep);
  ImGui::SliderInt("after pass [P]", &st.passStep, -1, passesRun(s) - 1, passName.c_str());
  ImGui::Checkbox("pause [Space]", &st.paused);
  ImGui::SameLine();
  ImGui::Text(st.passStep >= 0 ? "t = %.2f s, held" : "t = %.2f s", st.time);
  ImGui::Separator();
  std::uint64_t draws = 0, triangles = 0;
  for (const PassStats& p : s.recorder->passStats()) draws += p.drawCalls, triangles += p.triangles;
  ImGui::Text("%.0f fps, %llu draw calls, %llu triangles", fps, static_cast<unsigned long long>(draws),
              static_cast<unsigned long long>(triangles));
  ImGui::TextWrapped(
      "drag: orbit  wheel: zoom  R: reset  S: screenshot (shift: with the panel)  "
      "PgDn PgUp: next, previous lesson  F1: hide the panel  Esc: quit");
  ImGui::TextWrapped("right drag: the lesson's brush, where it has one");
  ImGui::PopItemWidth();
  ImGui::PopAllowKeyboardFocus();
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
  std::snprintf(name, sizeof name, "screenshot-%s-%03d.png", st.session.info.id.c_str(), st.screenshots++);
  writePng(name, image);
  std::cerr << "saved " << name << "\n";
}

}  // namespace

int runWindow(Session& s) {
  GLFWwindow* window = s.context->window();
  const CommandLine& cl = s.commandLine;
  WindowState st{.session = s, .time = cl.time};
  st.course = courseLessons();
  st.panel = !cl.frames;  // a --frames run is a test: the window is the picture alone
  st.sayLayout = true;
  for (std::size_t i = 0; i < st.course.size(); ++i)
    if (st.course[i].filename() == s.info.id) st.lessonIndex = static_cast<int>(i);
  say(st, "lesson " + s.info.id + ": " + s.info.title +
              (st.lessonIndex >= 0 ? " (" + std::to_string(st.lessonIndex + 1) + " of " +
                                         std::to_string(st.course.size()) + " in the course)"
                                   : std::string()));
  glfwSetWindowUserPointer(window, &st);
  // Ours first: ImGui chains to the callbacks installed before it.
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exitCode = 0;
  {
    Display display;
    double last = glfwGetTime(), fps = 0;
    for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
      glfwPollEvents();
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
      const int areaX = st.panel ? std::min(static_cast<int>(kWindowPanelWidth * sx), w - 1) : 0;
      const int areaW = w - areaX;
      if (areaW != s.framebuffer->width() || h != s.framebuffer->height()) s.resize(areaW, h);
      if (st.sayLayout) {
        say(st, std::string(st.panel ? "panel shown" : "panel hidden") + ": the picture is " +
                    std::to_string(areaW) + "x" + std::to_string(h) +
                    (st.panel ? " beside it, from x = " + std::to_string(areaX) : std::string()));
        st.sayLayout = false;
      }

      // With --frames the window steps time exactly like a headless run, so its pixels
      // can be compared with a golden.
      const double now = glfwGetTime();
      fps = 0.9 * fps + 0.1 / std::max(now - last, 1e-6);
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
      // A variant switched to may run fewer passes: the step stays among those the last frame ran.
      st.passStep = std::min(st.passStep, passesRun(s) - 1);
      const int step = st.passStep;
      s.saveShadowMasks = cl.frames && frame + 1 >= *cl.frames;  // --mask-out: the last frame, as headless
      s.renderFrame(st.time, {.measure = false,
                              .captureAll = false,
                              .captureOnly = step >= 0 ? std::optional<std::size_t>(step) : std::nullopt});
      const Snapshot* snap = nullptr;
      if (step >= 0)
        for (const Snapshot& sn : s.recorder->snapshots()) snap = &sn;

      Image shown;
      if (st.view == View::Colour && !snap) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, s.framebuffer->id());
        Display::blitFit(s.framebuffer->width(), s.framebuffer->height(), areaX, areaW, h, false);
      } else if (st.view == View::Depth) {
        DepthRange range;
        shown = depthPicture(snap ? snap->depth : s.framebuffer->readDepth(), s.framebuffer->width(),
                             s.framebuffer->height(), s.projection, s.reversedDepth, &range);
        if (st.sayDepthRange) say(st, depthLegendLine(range));
        st.sayDepthRange = false;
        display.show(shown, areaX, areaW, h);
      } else {
        const Image stencil = snap ? snap->stencil : s.framebuffer->readStencil();
        shown = st.view == View::Colour        ? snap->colour
                : st.view == View::StencilRamp ? stencilRamp(stencil)
                                               : stencilBitPlanes(stencil);
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
      ImGui::NewFrame();
      if (st.panel) drawPanel(window, st, fps, static_cast<float>(wh));
      ImGui::Render();
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glViewport(0, 0, w, h);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (st.windowScreenshot) {  // the window as the class sees it, the panel too
        saveScreenshot(st, readColourPixels(0, w, h));
        st.windowScreenshot = false;
      }
      glfwSwapBuffers(window);
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return exitCode;
}

}  // namespace stencil
