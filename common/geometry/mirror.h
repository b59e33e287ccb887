// Conservative culling for reflections: what can be seen through a planar mirror, as a
// frustum of planes in the unreflected world, so a recursive mirror renderer can skip
// objects and mirrors that no reflection shows. Pure functions on GLM types, usable alone.
//
// Conventions: a plane (a, b, c, d) with unit normal keeps the points with a x + b y + c z + d
// >= 0 ("inside"); a frustum is the intersection of its planes' insides. Every test is
// conservative: "outside" is answered only when one plane has everything strictly behind it.
#pragma once
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/bounds.h"

namespace stencil {

struct Frustum {
  std::vector<glm::vec4> planes;  // inward-facing, unit normals
};

// The view frustum of a projection * view matrix (Gribb and Hartmann's row sums): left,
// right, bottom, top, near and, when withFar, far. Without it the frustum reaches to
// infinity, as deep reflections need.
Frustum frustumOf(const glm::mat4& viewProjection, bool withFar = true);

// The plane that the points of `plane` land on after an invertible affine `matrix`, with its
// inside carried along: dot(result, M x) = dot(plane, x) up to a positive scale (renormalised).
glm::vec4 transformPlane(glm::vec4 plane, const glm::mat4& matrix);

// True when the sphere is certainly outside (wholly behind one plane).
bool outside(const Frustum&, const BoundingSphere&);
// True when every point is behind one and the same plane (a polygon or a box's corners).
bool outside(const Frustum&, const std::vector<glm::vec3>& points);

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
