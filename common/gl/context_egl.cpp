// EGL without a window: the device platform (a GPU where one exists), else Mesa's
// surfaceless platform (llvmpipe on a machine without a GPU).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/errors.h"

namespace stencil {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  std::string padded = std::string(" ") + list + " ";
  return padded.find(std::string(" ") + name + " ") != std::string::npos;
}

// A display on a hardware device if there is one, else surfaceless, else a software device.
// LIBGL_ALWAYS_SOFTWARE (Mesa's switch for software rendering) skips the hardware devices: the
// golden tests set it, with glvnd's vendor pinned to Mesa, so they compare llvmpipe's pictures.
EGLDisplay openDisplay() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return eglGetDisplay(EGL_DEFAULT_DISPLAY);

  std::vector<EGLDeviceEXT> devices;
  auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto queryDeviceString =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (hasExtension(client, "EGL_EXT_platform_device") && queryDevices && queryDeviceString) {
    EGLint count = 0;
    if (queryDevices(0, nullptr, &count) && count > 0) {
      devices.resize(static_cast<size_t>(count));
      queryDevices(count, devices.data(), &count);
    }
  }
  const char* software = std::getenv("LIBGL_ALWAYS_SOFTWARE");
  const bool hardware = !software || !*software || std::string(software) == "0";
  for (EGLDeviceEXT device : devices) {
    if (!hardware) break;
    if (hasExtension(queryDeviceString(device, EGL_EXTENSIONS), "EGL_MESA_device_software")) continue;
    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) return d;
  }
  if (!devices.empty()) return getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices.front(), nullptr);
  return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

class EglContext final : public Context {
 public:
  EglContext() {
    display_ = openDisplay();
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr))
      throw NoContextError("EGL found no display to initialise");
    if (!eglBindAPI(EGL_OPENGL_API)) throw NoContextError("EGL has no desktop OpenGL API");

    // Surface type: pbuffer if offered (for the fallback below), else any.
    EGLConfig config = nullptr;
    EGLint found = 0;
    for (EGLint surfaceType : {EGL_PBUFFER_BIT, 0}) {
      const EGLint attribs[] = {EGL_RENDERABLE_TYPE,
                                EGL_OPENGL_BIT,
                                EGL_SURFACE_TYPE,
                                surfaceType,
                                EGL_RED_SIZE,
                                8,
                                EGL_GREEN_SIZE,
                                8,
                                EGL_BLUE_SIZE,
                                8,
                                EGL_NONE};
      if (eglChooseConfig(display_, attribs, &config, 1, &found) && found > 0) break;
    }
    if (found == 0) throw NoContextError("EGL offers no OpenGL config");

    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
    if (context_ == EGL_NO_CONTEXT) throw NoContextError("EGL could not create a GL 3.3 core context");

    // Lessons render into their own framebuffer object, so no surface is needed where
    // the driver allows it; otherwise a 1x1 pbuffer.
    EGLSurface surface = EGL_NO_SURFACE;
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
      const EGLint pbuffer[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface_ = surface = eglCreatePbufferSurface(display_, config, pbuffer);
    }
    if (!eglMakeCurrent(display_, surface, surface, context_)) throw NoContextError("eglMakeCurrent failed");
    loadGl([](const char* name) { return reinterpret_cast<GlProc>(eglGetProcAddress(name)); });
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  Backend backend() const override { return Backend::Egl; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
};

}  // namespace

std::unique_ptr<Context> createEglContext() {
  return std::make_unique<EglContext>();
}

}  // namespace stencil
