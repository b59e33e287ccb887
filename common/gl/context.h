// One interface over the ways to get an OpenGL 3.3 core context: OSMesa (software,
// deterministic), EGL (surfaceless or device platform: a GPU where there is one), a GLFW
// window, and in the browser a WebGL 2 canvas (the Emscripten build: context_web.cpp, gl_web.h).
// Lessons never see which one they run on; they render into a Framebuffer.
#pragma once
#include <memory>
#include <optional>
#include <string>

struct GLFWwindow;

namespace stencil {

enum class Backend { Osmesa, Egl, Window, Web };

const char* backendName(Backend);
std::optional<Backend> parseBackend(const std::string&);
bool osmesaAvailable();  // false when built without libosmesa6-dev

// Optional features, detected once per context. Lessons use them only when present.
struct GlFeatures {
  std::string vendor, renderer, version;
  int major = 0, minor = 0;
  bool depthBoundsTest = false;     // EXT_depth_bounds_test
  bool pipelineStatistics = false;  // ARB_pipeline_statistics_query
  bool clipControl = false;         // ARB_clip_control (core in 4.5)
  bool khrDebug = false;            // KHR_debug (core in 4.3)
  bool depthClamp = false;          // ARB_depth_clamp (core in 3.2)
  bool stencilExport = false;       // ARB_shader_stencil_export: a fragment shader writes the stencil value
  // What GL 3.3 core always has and WebGL 2 has only through an extension, or not at all: true
  // on the desktop, detected in the browser (webgl).
  bool webgl = false;              // a WebGL 2 context (the browser build)
  bool clipDistance = true;        // gl_ClipDistance (WEBGL_clip_cull_distance)
  bool timerQuery = true;          // GL_TIME_ELAPSED queries (EXT_disjoint_timer_query_webgl2)
  bool floatColour = true;         // float colour buffers drawn into and blended (EXT_color_buffer_float, EXT_float_blend)
  bool samplesPassed = true;       // counting occlusion queries (WebGL 2's are only boolean)
  bool stencilReadPixels = true;   // glReadPixels of GL_STENCIL_INDEX (WebGL 2 reads bit planes)
  std::string summary() const;      // one line: "depth_bounds_test=no clip_control=yes ..."
};

class Context {
 public:
  virtual ~Context() = default;
  virtual Backend backend() const = 0;
  virtual GLFWwindow* window() { return nullptr; }  // only the window backend has one
  const GlFeatures& features() const { return features_; }

 protected:
  // Loads GL entry points through the backend's get-proc-address and detects features.
  // Throws NoContextError when the context is below GL 3.3.
  using GlProc = void (*)();
  void loadGl(GlProc (*getProcAddress)(const char*));
  // The browser's: WebGL 2's entry points are linked in; enables and detects its extensions.
  void detectWebGl();

 private:
  GlFeatures features_;
};

// Creates a current context of the given backend. Throws NoContextError with the reason.
std::unique_ptr<Context> createContext(Backend, int width, int height, const std::string& title);

// Keeps memory the program frees in its heap rather than handing it back to the kernel. llvmpipe
// (Mesa 22) copies its whole fragment state (33 KB) into a frame's command memory at every state
// change, in 64 KB blocks it mallocs and frees at each flush; with glibc's default trim threshold
// (128 KB) each flush returns them and the next faults every page in again, which is most of a
// frame's time in a pass-heavy lesson (lesson 14: ~2,600 page faults a frame; docs/14-csg.md).
// Called once at start by every lesson and by benchmarks' peers, so both sides run alike.
void keepFreedHeap();

struct BackendChoice {
  Backend backend;
  std::string reason;  // said in one line when the context starts
};

// A flag wins; else a window when a display exists and --headless is not given; else
// OSMesa (deterministic) where built in, else EGL.
// runLesson falls back to headlessBackend when the display opens no window.
BackendChoice chooseBackend(std::optional<Backend> requested, bool headless);
// The headless backend, OSMesa where built in, else EGL; `why` starts its reason.
BackendChoice headlessBackend(const std::string& why);

// Backend constructors, one per file.
std::unique_ptr<Context> createOsmesaContext(int width, int height);
std::unique_ptr<Context> createEglContext();
std::unique_ptr<Context> createWindowContext(int width, int height, const std::string& title);
// A WebGL 2 context on the page's <canvas id="canvas">, width x height (only in the browser build).
std::unique_ptr<Context> createWebContext(int width, int height);

}  // namespace stencil
