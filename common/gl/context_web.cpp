// The browser's context (the Emscripten build): WebGL 2 on the page's canvas, its extensions
// enabled where the browser has them, and the GL 3.3 features they stand for reported in
// GlFeatures so that lessons fall back as they do on a desktop driver without them.
#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include "gl/context.h"
#include "gl/errors.h"
#include "gl/gl.h"

// EXT_clip_control's entry point (Emscripten's GL library predates it).
EM_JS(void, stencil_clip_control, (GLenum origin, GLenum depth), {
  GLctx.getExtension('EXT_clip_control').clipControlEXT(origin, depth);
});

namespace stencil {
namespace {

EMSCRIPTEN_WEBGL_CONTEXT_HANDLE current = 0;
bool clipDistanceExtension = false;  // the current context's WEBGL_clip_cull_distance

class WebContext final : public Context {
 public:
  WebContext(int width, int height) {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    // The lesson draws into its own framebuffer with a verified stencil; the canvas only shows it.
    attributes.alpha = EM_FALSE;
    attributes.depth = EM_FALSE;
    attributes.stencil = EM_FALSE;
    attributes.antialias = EM_FALSE;
    attributes.preserveDrawingBuffer = EM_TRUE;  // a screenshot of the page shows the frame
    emscripten_set_canvas_element_size("#canvas", width, height);
    handle_ = emscripten_webgl_create_context("#canvas", &attributes);
    if (handle_ <= 0) throw NoContextError("the browser gives no WebGL 2 context");
    emscripten_webgl_make_context_current(handle_);
    current = handle_;
    detectWebGl();
  }
  ~WebContext() override {
    if (current == handle_) current = 0;
    emscripten_webgl_destroy_context(handle_);
  }
  Backend backend() const override { return Backend::Web; }

 private:
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE handle_ = 0;
};

bool enable(const char* extension) {
  return emscripten_webgl_enable_extension(current, extension) == EM_TRUE;
}

}  // namespace

void Context::detectWebGl() {
  GlFeatures& f = features_;
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "");
  };
  f.vendor = str(GL_VENDOR);
  f.renderer = str(GL_RENDERER);
  f.version = str(GL_VERSION);
  f.major = 3;  // WebGL 2 stands for the 3.3 core subset the lessons use
  f.minor = 3;
  f.webgl = true;
  f.depthBoundsTest = false;
  f.pipelineStatistics = false;
  f.khrDebug = false;
  f.samplesPassed = false;
  f.stencilReadPixels = false;
  f.depthClamp = enable("EXT_depth_clamp");
  f.clipControl = enable("EXT_clip_control");
  f.clipDistance = clipDistanceExtension = enable("WEBGL_clip_cull_distance");
  f.timerQuery = enable("EXT_disjoint_timer_query_webgl2");
  const bool colourBufferFloat = enable("EXT_color_buffer_float");
  f.floatColour = colourBufferFloat && enable("EXT_float_blend");
}

bool webClipDistance() {
  return clipDistanceExtension;
}

#undef glEnable
#undef glDisable
void webEnable(GLenum cap) {
  if (clipDistanceExtension || cap < GL_CLIP_DISTANCE0 || cap > GL_CLIP_DISTANCE0 + 7) glEnable(cap);
}
void webDisable(GLenum cap) {
  if (clipDistanceExtension || cap < GL_CLIP_DISTANCE0 || cap > GL_CLIP_DISTANCE0 + 7) glDisable(cap);
}

std::unique_ptr<Context> createWebContext(int width, int height) {
  return std::make_unique<WebContext>(width, height);
}

// The desktop backends do not exist in the browser.
std::unique_ptr<Context> createOsmesaContext(int, int) {
  throw NoContextError("no OSMesa in the browser");
}
std::unique_ptr<Context> createEglContext() {
  throw NoContextError("no EGL in the browser");
}
std::unique_ptr<Context> createWindowContext(int, int, const std::string&) {
  throw NoContextError("no GLFW window in the browser: the page's canvas is the window");
}

}  // namespace stencil

void glClipControl(GLenum origin, GLenum depth) {
  stencil_clip_control(origin, depth);
}
#endif
