// An independent answer to "is this pixel in shadow?": one camera ray per pixel centre and,
// where it meets a receiver, one ray towards the light (geometry/raycast.h). Lessons'
// stencil results are checked against it pixel by pixel; only pixels on an edge of the
// oracle's own picture (a silhouette, a shadow boundary, a surface's border) may differ.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/mesh.h"

namespace stencil {

enum class PixelClass : std::uint8_t {
  Empty,     // the camera ray meets nothing
  Other,     // it meets an object that receives no shadow (a planar caster, say)
  Lit,       // it meets a receiver, and the way to the light is free
  Shadowed,  // it meets a receiver, and a caster blocks the way to the light
  // It meets a receiver the light does not reach: beyond a bounded point light's radius (a
  // method may skip shadows there), or on a surface edge-on to the light (the light arrives at
  // zero incidence). Neither lit nor shadowed is claimed.
  OutOfReach,
};

struct OracleObject {
  const Mesh* mesh;  // not owned
  glm::mat4 model;
  bool casts;     // may block the light
  bool receives;  // its visible pixels are classified lit or shadowed
  // When set, the true sphere (world centre xyz, radius w) stands in for the mesh, which may then
  // be null: the reference for a tessellated sphere.
  std::optional<glm::vec4> sphere = std::nullopt;
};

// The class of every pixel centre of a size.x by size.y image seen through viewProjection
// (GL's conventions: clip space -1..1), top row first like Image. Shadowed where a caster
// blocks the way to the light, and on a caster's own side turned from the light (the side the
// camera sees), which lies in the caster's shadow volume; a receiver that casts nothing and
// faces away from the light is still Lit unless a caster is in the way.
// lightRadius bounds a point light (geometry/scene.h, SceneLight::radius). The rays are cast in
// a frame moved to drawingOrigin (geometry/projection.h) near the eye, all of it moved alike, so
// rounding grows with distance from the eye rather than from the world's origin.
// When surfaces is given, it receives per pixel the index into the objects of what the camera
// ray meets, -1 for nothing, and, where the side of a caster the ray meets is turned from the
// light, that index plus the number of objects: where it changes, the pixel lies on a
// silhouette or on a caster's terminator, where its own volume leaves its surface.
std::vector<PixelClass> classifyPixels(const std::vector<OracleObject>&, const glm::vec4& light,
                                       const glm::mat4& viewProjection, glm::ivec2 size,
                                       float lightRadius = std::numeric_limits<float>::infinity(),
                                       std::vector<int>* surfaces = nullptr);

struct OracleReport {
  std::size_t receiverPixels = 0;  // Lit or Shadowed by the oracle
  std::size_t shadowedPixels = 0;  // Shadowed by the oracle
  std::size_t disagreements = 0;   // the image's "lit receiver" differs from the oracle's
  std::size_t onEdges = 0;         // of which on an edge of the oracle's picture (forgiven)
  bool passed() const { return disagreements == onEdges; }
};

// Compares the image's verdict (true: a lit receiver) with the oracle's Lit, pixel by pixel.
// A pixel is on an edge when a pixel of its 3x3 neighbourhood has another class or, given the
// surfaces classifyPixels found, another surface: a silhouette, where the rasterizer's coverage
// and the ray through the pixel centre may see different things, or a caster's terminator, where
// the sides of its own volume leave its surface at the faces' grazing angle and lie within
// rounding of it over the pixels beside the line.
OracleReport compareWithOracle(const std::vector<PixelClass>& oracle, const std::vector<bool>& litInImage,
                               glm::ivec2 size, const std::vector<int>* surfaces = nullptr);

// A picture of the comparison, RGBA top row first: the oracle's classes in greys and blue,
// forgiven disagreements yellow, the others red.
std::vector<std::uint8_t> oraclePicture(const std::vector<PixelClass>& oracle,
                                        const std::vector<bool>& litInImage, glm::ivec2 size,
                                        const std::vector<int>* surfaces = nullptr);

}  // namespace stencil
