#include "gl/light_marker.h"

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/shapes.h"

namespace stencil {

LightMarker::LightMarker(float radius, int slices, int stacks)
    : flat_("common/flat.vert", "common/flat.frag"), mesh_(makeSphere(radius, slices, stacks)), gpu_(mesh_) {}

void LightMarker::draw(const glm::mat4& viewProjection, const glm::vec3& position,
                       const glm::vec4& colour) const {
  flat_.set("transform", viewProjection * glm::translate(glm::mat4(1), position));
  flat_.set("colour", colour);
  gpu_.draw();
}

}  // namespace stencil
