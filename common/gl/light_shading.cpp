#include "gl/light_shading.h"

#include <cmath>

namespace stencil {

void setLightShading(const Program& program, const LightShading& shading) {
  program.set("viewProjection", viewProjectionFrom(shading.viewProjection, shading.origin));
  program.set("origin", shading.origin);
  program.set("ambient", shading.ambient);
  program.set("light", shading.light);
  program.set("lightColour", shading.lightColour);
  // GLSL need not keep an infinity: the shader's own default, 1e30, stands for no bounds.
  program.set("radius", std::isinf(shading.radius) ? 1e30f : shading.radius);
  program.set("twoSided", shading.twoSided ? 1 : 0);
  program.set("eye", shading.eye);
  program.set("shininess", shading.shininess);
}

}  // namespace stencil
