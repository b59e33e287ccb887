// The uniforms of shaders/common/light.vert and light.frag that one pass shares across all the
// objects it draws: the camera, one light, the ambient term. Each object then sets "model" (a
// rigid model matrix, object to world) and "colour" (its albedo), and "shininess" where it has its
// own. Drawing with lightColour 0 gives the ambient term alone (the unlit pass of a shadow
// volume lesson); with ambient 0, the light's share alone, to add onto what is drawn.
#pragma once
#include <glm/glm.hpp>
#include <limits>

#include "geometry/projection.h"
#include "gl/shader.h"

namespace stencil {

// Shaders with an "origin" uniform (common/light.vert, common/extrude.vert,
// 15-robust-zfail/volume.vert) subtract it from the world position and draw with
// viewProjectionFrom(viewProjection, origin); drawingOrigin (geometry/projection.h) says why.
struct LightShading {
  glm::mat4 viewProjection{1.0f};  // world to clip, the matrix the frame draws with
  glm::vec3 origin{0.0f};          // world, drawingOrigin: the shader draws from there
  glm::vec3 eye{0.0f};             // world, for the highlight
  // World, homogeneous: w = 1 a point, w = 0 the direction towards the light.
  glm::vec4 light{0.0f, 1.0f, 0.0f, 0.0f};
  glm::vec3 lightColour{0.0f};  // 0 turns the light off
  glm::vec3 ambient{0.0f};
  float shininess = 32.0f;  // Blinn-Phong exponent
  // A point light's bounds (world units, docs/scenes.md): its light reaches exactly zero there.
  // Infinite: no bounds, the fall-off with distance alone.
  float radius = std::numeric_limits<float>::infinity();
  bool twoSided = false;  // a face seen from its back is lit on the side the eye sees (rooms)
};

// Sets them on `program` (a program of light.vert and light.frag) and leaves it bound.
void setLightShading(const Program& program, const LightShading& shading);

}  // namespace stencil
