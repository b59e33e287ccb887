// Reversed depth: the same projection with window depth 1 at the near plane and 0 at the far
// plane (or at infinity). Meant for a floating-point depth buffer and
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), where window depth is clip z / clip w with no
// remapping. A float holds nearly the same relative precision at every magnitude, and 1/d
// (what a perspective stores) is small far away, where that precision is wanted; GL's default
// mapping 0.5 + 0.5 z/w instead piles every distant depth up just below 1, where a float's
// steps are 2^-24 apart, as coarse as a 24-bit fixed-point buffer's.
#pragma once
#include <glm/glm.hpp>

namespace stencil {

// The projection `projection` (GL's convention: clip z from -w at the near plane to +w at the
// far plane) with its depth reversed for a zero-to-one clip range: clip x, y and w unchanged,
// clip z' = (w - z) / 2, so window depth z'/w = (1 - z/w) / 2 is 1 at the near plane and 0 at
// the far plane. The clip volume 0 <= z' <= w is the old -w <= z <= w, so exactly what was
// clipped is clipped. For glm::infinitePerspective(fovy, aspect, n) the depth row (0 0 -1 -2n)
// becomes (0 0 0 n), exactly: clip z' = n w_in, window depth n / d at eye distance d, and a
// point at infinity (w_in = 0) lands at depth 0, inside the clip volume. Any projection works,
// perspective (finite or infinite) or parallel.
glm::mat4 reversedDepth(const glm::mat4& projection);

// Far from the world's origin a float's step is coarse (1/128 at 1e5 units), and
// viewProjection * world, a sum of terms that large, loses a position to cancellation: a box 1e5
// units out seen from 5 units away moved by most of a pixel at 1024x768. Drawing (and ray casting)
// from an origin near the eye keeps every coordinate at the size of its distance from the eye,
// which is what a pixel's footprint scales with. drawingOrigin is the eye (world) rounded to a
// multiple of 1024 world units: exact in float, and 0 within 512 units of the world's origin, so
// every such scene is drawn and cast bit for bit as from the world's origin.
glm::vec3 drawingOrigin(const glm::vec3& eye);

// viewProjection * translate(origin), taken in double and rounded once: (world - origin) to clip.
// For origin 0 it is viewProjection itself.
glm::mat4 viewProjectionFrom(const glm::mat4& viewProjection, const glm::vec3& origin);

}  // namespace stencil
