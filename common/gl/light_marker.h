// A small sphere where a point light stands, drawn in one flat colour (shaders/common/flat.*), so
// that the student sees where the shadows come from. It neither casts nor receives a shadow.
#pragma once
#include <glm/glm.hpp>

#include "geometry/mesh.h"
#include "gl/gpu_mesh.h"
#include "gl/shader.h"

namespace stencil {

class LightMarker {
 public:
  // With a current context: a sphere of `radius` (world units) in slices x stacks facets.
  explicit LightMarker(float radius = 0.08f, int slices = 12, int stacks = 6);

  // The sphere about the origin, object space: for an oracle's ray cast, moved to the light.
  const Mesh& mesh() const { return mesh_; }

  // One draw call: the sphere centred on `position` (world), seen through viewProjection (world
  // to clip), in `colour` (RGBA). Sets no GL state but the flat program.
  void draw(const glm::mat4& viewProjection, const glm::vec3& position, const glm::vec4& colour) const;

 private:
  Program flat_;
  Mesh mesh_;
  GpuMesh gpu_;
};

}  // namespace stencil
