// Soft shadows from an area light (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 6.4 and figure 15; Brotman and Badler 1984): the light is sampled by a cluster
// of point lights, each casting a hard shadow, and the shadows averaged. Here: where to put the
// samples, and the exact answer they converge to.
//
// Units are world units; the area light lies in the horizontal plane y = centre.y and shines
// down onto receivers below it. A receiver point sees a fraction of the light's area (the visible
// fraction, 0 in the umbra, 1 fully lit, in between in the penumbra); the average of N point
// lights' hard shadows estimates it.
#pragma once
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace stencil {

enum class SamplePattern {
  Grid,      // cell centres of a rows x columns grid (rows the largest divisor of N <= sqrt N)
  Jittered,  // one uniformly random point in each cell of the same grid (stratified)
  Halton,    // the 2-3 Halton sequence, a low-discrepancy set
};

enum class LightShape { Rectangle, Disk };

struct AreaLight {
  glm::vec3 centre{0.0f};
  glm::vec2 size{1.0f};  // rectangle: extent along x and along z; disk: diameter in size.x
  LightShape shape = LightShape::Rectangle;
};

// The radical inverse of index in base (van der Corput): the digits mirrored about the point.
// radicalInverse(2, 1) = 0.5, (2, 2) = 0.25, (3, 1) = 1/3. Throws std::invalid_argument for a
// base below 2.
double radicalInverse(int base, std::uint64_t index);

// The grid a pattern of n samples uses: rows x columns = n, rows the largest divisor of n that is
// at most sqrt(n) (a prime n is a single row).
glm::ivec2 sampleGrid(int n);

// n sample points in the unit square [0, 1)^2. round numbers the progressive rounds: round r of
// Jittered draws fresh random points in the same cells (a fixed seed per round, so every run is
// the same), Halton continues its sequence at r * n + 1, and Grid repeats itself (it never
// converges past its own n). Throws std::invalid_argument for n < 1 or a negative round.
std::vector<glm::vec2> unitSquareSamples(SamplePattern, int n, int round = 0);

// Shirley and Chiu's concentric map of the unit square onto the unit disk (radius 1, centre 0):
// area-preserving up to a constant, so strata stay strata.
glm::vec2 concentricDisk(glm::vec2 unit);

// The world point of the light at unit-square coordinates (a rectangle stretched, a disk through
// concentricDisk).
glm::vec3 lightPoint(const AreaLight&, glm::vec2 unit);

// The light's outline as a convex polygon in the light's plane, (x, z) counter-clockwise seen
// from above: the rectangle's four corners, or the disk as a regular polygon of diskSides sides
// (area within 1e-4 of the disk's at 256 sides).
std::vector<glm::dvec2> lightOutline(const AreaLight&, int diskSides = 256);

// ---- the exact answer ---------------------------------------------------------------------------

// A straight occluder edge at height h, parallel to a side of a rectangular light of width W at
// height H, over the receiver plane y = 0: the penumbra on the plane is W * h / (H - h) wide (a
// light point at offset u across the light projects the edge to offset -u * h / (H - h)).
// Throws std::invalid_argument unless 0 < h < H and W >= 0.
double straightEdgePenumbraWidth(double W, double H, double h);

// The visible fraction across that penumbra: a linear ramp, 0 at the umbra's side and 1 at the
// lit side. s is the distance from the umbra's side of the penumbra towards the lit side.
double straightEdgeVisibleFraction(double s, double W, double H, double h);

// Area of a simple polygon (shoelace), positive when counter-clockwise.
double polygonArea(const std::vector<glm::dvec2>&);

// The part of `subject` (any convex polygon) inside `clip` (a convex, counter-clockwise polygon):
// Sutherland-Hodgman. Empty when they do not overlap.
std::vector<glm::dvec2> clipConvex(const std::vector<glm::dvec2>& subject,
                                   const std::vector<glm::dvec2>& clip);

// The convex hull of points, counter-clockwise (Andrew's monotone chain); collinear points dropped.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points);

// The visible fraction of the light from `receiver` past a convex occluder given by its corners
// (world space): one minus the area of the light covered by the occluder's projection from the
// receiver onto the light's plane, over the light's area. The projection of a convex solid from
// a point is the convex hull of its corners' projections. Every corner must lie strictly between
// the receiver's height and the light's (else std::invalid_argument): the projection is then
// finite and on the light's side. The disk is its 256-sided outline (lightOutline), both in the
// covered area and in the light's.
double visibleFraction(const AreaLight&, const std::vector<glm::vec3>& occluderCorners,
                       const glm::vec3& receiver);

}  // namespace stencil
