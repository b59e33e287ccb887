// Matrices that flatten or mirror the world through a plane (Kilgard, appendices A and B).
// A plane is (a, b, c, d) with a*x + b*y + c*z + d = 0; its normal (a, b, c) points to the
// side it faces. Pure functions on GLM types, usable alone.
//
// Depends on: GLM (C++17).
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace stencil {

// The plane through `point` facing `normal` (normalised here).
glm::vec4 planeFrom(glm::vec3 point, glm::vec3 normal);

// Signed distance of a point from a plane with a unit normal.
float planeDistance(glm::vec4 plane, glm::vec3 point);

// Projects every point onto `plane` along the line from the homogeneous `light`: a point
// light has w = 1, a directional light w = 0 (the direction it comes from). The matrix is
// (P.L) I - L P^T: points on the plane stay put (up to scale), the light maps to zero.
// Geometry on the far side of the light projects "backwards" (w < 0 after projection),
// which is why a lesson must not cast from casters beyond the light.
glm::mat4 planarShadowMatrix(glm::vec4 plane, glm::vec4 light);

// Mirrors through a plane with a unit normal: x' = x - 2 (n.x + d) n. Its determinant is
// -1, so front faces become back faces: flip the cull face when drawing through it.
glm::mat4 reflectionMatrix(glm::vec4 plane);

}  // namespace stencil
