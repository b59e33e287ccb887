// A GLFW window for students and classrooms. The lesson still renders into a verified
// Framebuffer; the window only shows it (and the panel).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

#include "gl/context.h"
#include "gl/errors.h"

namespace stencil {
namespace {

std::string lastGlfwError;

class WindowContext final : public Context {
 public:
  WindowContext(int width, int height, const std::string& title) {
    glfwSetErrorCallback([](int, const char* message) { lastGlfwError = message; });
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const char* x11 = std::getenv("DISPLAY");
    const bool hasWayland = wayland && *wayland, hasX11 = x11 && *x11;
    if (!hasWayland && !hasX11)
      throw NoContextError("no display: neither DISPLAY nor WAYLAND_DISPLAY is set");
#ifdef GLFW_PLATFORM
    // GLFW 3.4 tries Wayland first, and libwayland prints a line of its own where there is none.
    if (!hasWayland) glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
#endif
    if (!glfwInit()) throw NoContextError("GLFW could not start: " + lastGlfwError);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw NoContextError("GLFW could not open a GL 3.3 core window: " + lastGlfwError);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    loadGl([](const char* name) { return reinterpret_cast<GlProc>(glfwGetProcAddress(name)); });
  }
  ~WindowContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  Backend backend() const override {
    return Backend::Window;
  }
  GLFWwindow* window() override {
    return window_;
  }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title) {
  return std::make_unique<WindowContext>(width, height, title);
}

}  // namespace stencil
