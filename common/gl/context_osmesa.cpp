// OSMesa: Mesa's off-screen software context. Deterministic pixels, so it is the default
// for tests. Newer Mesa releases dropped it, hence the build-time switch.
#include "gl/context.h"
#include "gl/errors.h"

#ifdef STENCIL_HAVE_OSMESA
#include <GL/osmesa.h>

#include <vector>

namespace stencil {
namespace {

class OsmesaContext final : public Context {
 public:
  OsmesaContext() {
    // Core 3.3; the default framebuffer's depth/stencil are unused: lessons render into
    // a Framebuffer object whose stencil bits the framework verifies.
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_) throw NoContextError("OSMesa could not create a GL 3.3 core context");
    // A 1x1 buffer is enough to make the context current.
    buffer_.resize(4);
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw NoContextError("OSMesaMakeCurrent failed");
    loadGl([](const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); });
  }
  ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }
  Backend backend() const override { return Backend::Osmesa; }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<Context> createOsmesaContext(int, int) {
  return std::make_unique<OsmesaContext>();
}

}  // namespace stencil

#else

namespace stencil {
std::unique_ptr<Context> createOsmesaContext(int, int) {
  throw UsageError("this build has no OSMesa backend (libosmesa6-dev was not found); use --backend egl");
}
}  // namespace stencil

#endif
