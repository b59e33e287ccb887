// Conservative culling for reflections: what can be seen through a planar mirror, as a
// frustum of planes in the unreflected world, so a recursive mirror renderer can skip
// objects and mirrors that no reflection shows. Pure functions on GLM types, usable alone.
//
// Planes, frustums and the conservative "outside" tests are frustum.h's (the camera's frustum is
// viewFrustum); here a mirror's plane has a unit normal pointing to its reflective side.
// Depends on: GLM, planar, frustum, bounds (C++17).
#pragma once
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/frustum.h"

namespace stencil {

// Whether a one-sided mirror shows its reflective side to an eye: strictly in front of it.
bool facesEye(glm::vec4 mirrorPlane, glm::vec3 eye);

// What `eye`, looking through `parent`, can see in a mirror: a convex polygon (its corners
// in order) lying in `mirrorPlane`, whose normal points to the reflective side. The answer
// is in the unreflected world: the objects whose mirror images the eye sees through the
// polygon. It is the pyramid from the reflected eye through the polygon's edges, beyond the
// mirror's plane, cut by the parent frustum reflected through the mirror. Mirrors seen in
// that frustum are the ones a reflection of a reflection can show: apply it again with the
// reflected eye to go one bounce deeper. The eye must face the mirror (facesEye).
Frustum throughMirror(const Frustum& parent, glm::vec3 eye, const std::vector<glm::vec3>& polygon,
                      glm::vec4 mirrorPlane);

// The scene renderings of n mirrors that all see each other, r bounces deep, when no
// mirror reflects itself: 1 + n * sum_{i=1..r} (n-1)^(i-1) (Kilgard, section 3).
std::uint64_t worstCaseRenderings(int mirrors, int depth);

// `projection` (a glm::perspective matrix) with its far plane moved to `farPlane`; the
// field of view, aspect and near plane are kept.
glm::mat4 withFarPlane(const glm::mat4& projection, float farPlane);

}  // namespace stencil
