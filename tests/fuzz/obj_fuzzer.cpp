// libFuzzer target: an OBJ file's bytes through parseObj, then prepareCaster on the file's shared
// vertices, as a scene's caster is prepared. A SceneError is the expected answer to bad input;
// any other exception, crash or sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "geometry/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const stencil::ObjMesh mesh = stencil::parseObj(text, "fuzz.obj");
    stencil::validateMesh(mesh.drawn);
    if (!stencil::allFinite(mesh.drawn) || mesh.drawn.triangleCount() != mesh.shared.triangleCount())
      __builtin_trap();
    const stencil::PreparedCaster caster = stencil::prepareCaster(mesh.shared);
    stencil::validateMesh(caster.mesh);
  } catch (const stencil::SceneError& e) {
    stencil::fuzz::checkMessage(e.what(), "fuzz.obj");
  }
  return 0;
}
