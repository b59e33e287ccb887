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
// When ties is given, it receives per pixel whether a side of a caster's shadow volume (one of its
// possible silhouette edges, as facesLight and possibleSilhouetteEdges find them on the welded
// mesh, extruded away from the light) passes the surface the ray meets closer in depth than a
// rasterizer's vertex snapping can move them: GL asks for 4 sub-pixel bits, so each vertex may
// land up to 1/16 pixel from where it lies, and a plane's window depth at a pixel may move by
// 1/16 of its change over a pixel in x plus that in y. Where the side's depth and the surface's
// are closer than the two planes' moves together, a conforming rasterizer may count the side on
// either side of the surface: the count there is not the algorithm's to decide. (The depth
// buffer's own rounding is not forgiven: its format is the lesson's choice.) Such pixels lie where a side grazes a surface, next to a terminator
// seen at a grazing angle, in a band that may be wider than the 3x3 pixels compareWithOracle's
// edge rule gives the terminator.
std::vector<PixelClass> classifyPixels(const std::vector<OracleObject>&, const glm::vec4& light,
                                       const glm::mat4& viewProjection, glm::ivec2 size,
                                       float lightRadius = std::numeric_limits<float>::infinity(),
                                       std::vector<int>* surfaces = nullptr, std::vector<bool>* ties = nullptr);

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
// rounding of it over the pixels beside the line. Given the ties classifyPixels found, a pixel
// where a side and the surface tie within a rasterizer's snapping is on an edge too.
OracleReport compareWithOracle(const std::vector<PixelClass>& oracle, const std::vector<bool>& litInImage,
                               glm::ivec2 size, const std::vector<int>* surfaces = nullptr,
                               const std::vector<bool>* ties = nullptr);

// compareWithOracle's edges: per pixel, top row first, whether a disagreement there is forgiven.
std::vector<bool> oracleEdges(const std::vector<PixelClass>& oracle, glm::ivec2 size,
                              const std::vector<int>* surfaces = nullptr, const std::vector<bool>* ties = nullptr);

// A picture of the comparison, RGBA top row first: the oracle's classes in greys and blue,
// forgiven disagreements yellow, the others red.
std::vector<std::uint8_t> oraclePicture(const std::vector<PixelClass>& oracle,
                                        const std::vector<bool>& litInImage, glm::ivec2 size,
                                        const std::vector<int>* surfaces = nullptr,
                                        const std::vector<bool>* ties = nullptr);

}  // namespace stencil
