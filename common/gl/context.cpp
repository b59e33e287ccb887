#include "gl/context.h"

#include <cstdlib>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "gl/errors.h"
#include "gl/gl.h"

namespace stencil {

void keepFreedHeap() {
#ifdef __GLIBC__
  mallopt(M_TRIM_THRESHOLD, 256 << 20);  // 256 MB: far above a frame's command memory
#endif
}

const char* backendName(Backend b) {
  switch (b) {
    case Backend::Osmesa: return "osmesa";
    case Backend::Egl: return "egl";
    case Backend::Window: return "window";
    case Backend::Web: return "webgl";
  }
  return "?";
}

std::optional<Backend> parseBackend(const std::string& name) {
  if (name == "osmesa") return Backend::Osmesa;
  if (name == "egl") return Backend::Egl;
  if (name == "window") return Backend::Window;
  return std::nullopt;
}

bool osmesaAvailable() {
#ifdef STENCIL_HAVE_OSMESA
  return true;
#else
  return false;
#endif
}

std::string GlFeatures::summary() const {
  auto yn = [](bool b) { return b ? "yes" : "no"; };
  std::string line = std::string("depth_bounds_test=") + yn(depthBoundsTest) +
                     " pipeline_statistics=" + yn(pipelineStatistics) + " clip_control=" + yn(clipControl) +
                     " khr_debug=" + yn(khrDebug) + " depth_clamp=" + yn(depthClamp) +
                     " stencil_export=" + yn(stencilExport);
  if (webgl)
    line += std::string(" clip_distance=") + yn(clipDistance) + " timer_query=" + yn(timerQuery) +
            " float_colour=" + yn(floatColour) + " samples_passed=" + yn(samplesPassed) +
            " stencil_read_pixels=" + yn(stencilReadPixels);
  return line;
}

#ifndef __EMSCRIPTEN__
void Context::loadGl(GlProc (*getProcAddress)(const char*)) {
  int version = gladLoadGL(getProcAddress);
  if (version == 0) throw NoContextError("could not load OpenGL entry points");
  GlFeatures& f = features_;
  f.major = GLAD_VERSION_MAJOR(version);
  f.minor = GLAD_VERSION_MINOR(version);
  if (f.major * 10 + f.minor < 33)
    throw NoContextError("OpenGL " + std::to_string(f.major) + "." + std::to_string(f.minor) +
                         " context; the lessons need 3.3 core");
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "");
  };
  f.vendor = str(GL_VENDOR);
  f.renderer = str(GL_RENDERER);
  f.version = str(GL_VERSION);
  bool gl45 = f.major > 4 || (f.major == 4 && f.minor >= 5);
  bool gl43 = f.major > 4 || (f.major == 4 && f.minor >= 3);
  f.depthBoundsTest = GLAD_GL_EXT_depth_bounds_test;
  f.pipelineStatistics = GLAD_GL_ARB_pipeline_statistics_query;
  f.stencilExport = GLAD_GL_ARB_shader_stencil_export;
  // Core in 4.5, where a driver need not list the extension; glad loads the entry point only
  // for the extension, so load it by name then.
  if (gl45 && !glad_glClipControl)
    glad_glClipControl = reinterpret_cast<PFNGLCLIPCONTROLPROC>(getProcAddress("glClipControl"));
  f.clipControl = (GLAD_GL_ARB_clip_control || gl45) && glad_glClipControl != nullptr;
  f.khrDebug = GLAD_GL_KHR_debug || gl43;
  f.depthClamp = true;  // core since 3.2, so guaranteed by the 3.3 floor
}

std::unique_ptr<Context> createWebContext(int, int) {
  throw NoContextError("a WebGL context exists only in the browser build (cmake --preset web)");
}
#endif

std::unique_ptr<Context> createContext(Backend b, int width, int height, const std::string& title) {
  switch (b) {
    case Backend::Osmesa: return createOsmesaContext(width, height);
    case Backend::Egl: return createEglContext();
    case Backend::Window: return createWindowContext(width, height, title);
    case Backend::Web: return createWebContext(width, height);
  }
  throw NoContextError("unknown backend");
}

BackendChoice chooseBackend(std::optional<Backend> requested, bool headless) {
  if (requested) return {*requested, "chosen by --backend"};
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  bool display = (x11 && *x11) || (wayland && *wayland);
  if (!headless && display) return {Backend::Window, "a display is available"};
  return headlessBackend(headless ? "--headless" : "no display");
}

BackendChoice headlessBackend(const std::string& why) {
  if (osmesaAvailable())
    return {Backend::Osmesa,
            why + "; OSMesa is the deterministic software default (--backend egl for a GPU)"};
  return {Backend::Egl, why + "; built without OSMesa"};
}

}  // namespace stencil
