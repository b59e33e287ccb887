// Planes and frustums for culling: the view frustum of a camera (Gribb and Hartmann, "Fast
// Extraction of Viewing Frustum Planes from the World-View-Projection Matrix"), a plane carried
// through a matrix, and the conservative "certainly outside" tests that mirrors (lesson 03), the
// occlusion pyramid (fast_shadows.h, lesson 16) and light bounds share.
//
// Conventions, as planar.h: a plane (a, b, c, d) keeps the points with a x + b y + c z + d >= 0
// ("inside"); its normal (a, b, c) need not be unit length unless a function says so. A frustum is
// the intersection of its planes' insides. "Outside" is answered only when one plane has
// everything strictly behind it, so a test never culls what may be seen.
//
// Depends on: GLM, bounds (C++17); of bounds only its BoundingSphere struct.
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "geometry/bounds.h"

namespace stencil {

// A plane n . p + d >= 0 inside, stored as (n, d).
using Plane = glm::vec4;

struct Frustum {
  std::vector<Plane> planes;  // inward-facing
};

// The view frustum of a projection * view matrix (GL clip conventions), from the matrix's row
// sums: left, right, bottom, top, near and, when withFar, far, in world space with unit normals.
// Without the far plane the frustum reaches to infinity, as an infinite far plane, deep
// reflections and z-fail's dark caps need.
Frustum viewFrustum(const glm::mat4& viewProjection, bool withFar = true);

// The plane that the points of `plane` land on after an invertible affine `matrix`, with its
// inside carried along: dot(result, M x) = dot(plane, x) up to a positive scale; unit normal.
Plane transformPlane(Plane plane, const glm::mat4& matrix);

// True when the sphere lies wholly behind one of the planes (of any normal length; a plane with a
// zero normal is skipped).
bool outside(const Frustum&, const BoundingSphere&);
// True when every point is strictly behind one and the same plane (a polygon or a box's corners).
bool outside(const Frustum&, const std::vector<glm::vec3>& points);

}  // namespace stencil
