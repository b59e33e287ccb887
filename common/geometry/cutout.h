// Planar cut-outs and their shadow volumes (Kilgard, "Improving Shadows and Reflections via the
// Stencil Buffer", sections 6.2.1-6.2.2, and "Accelerated Stencil Shadow Extrusion via Vertex
// Blending"). A cut-out is a flat, open mesh: its silhouette, seen from any light off its plane,
// is its border (outline and holes), so its shadow volume has the same sides for every light and
// only the far ends move. That allows three ways to extrude it: on the CPU each frame
// (shadow_volume.h), by one projective matrix applied to a static prism, or on the GPU from
// doubled vertices. A complex closed object flattened onto a plane becomes a cut-out too.
//
// Lights are homogeneous, as in shadow_volume.h: w = 1 a point light, w = 0 the direction towards
// a directional light, given in the cut-out's own space.
#pragma once
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/mesh.h"
#include "geometry/shadow_volume.h"

namespace stencil {

// A cut-out drawn on a grid: '#' is a filled square cell, anything else a hole. Row 0 is at -z,
// column 0 at -x; the cut-out lies in the y = 0 plane centred on the origin, facing +y, one
// cell `cellSize` wide. Neighbouring cells share their vertices, so the mesh is welded and its
// border edges are exactly the outline and the holes. Throws std::invalid_argument for an empty
// or ragged grid, no filled cell, or a non-positive cell size.
Mesh makeCutout(const std::vector<std::string>& rows, float cellSize);

// A window lattice for makeCutout: (2n+3) x (2n+3) cells, n x n square holes one cell apart
// inside a frame two cells wide, and the four corner cells notched out (a concave outline).
// n >= 1; throws std::invalid_argument otherwise.
std::vector<std::string> latticeRows(int n);

// The projective map of 3D space (homogeneous 4x4 matrix) that sends from[i] to to[i], each up
// to scale, i = 0..4. Closed form: the matrix A that sends the basis e1..e4 to from[0..3] and
// (1,1,1,1) to from[4] (columns from[i] scaled so they sum to from[4]), the same B for `to`, then
// B * inverse(A), scaled so that from[0] maps exactly onto to[0]. Throws std::invalid_argument when four of
// the `from` points are coplanar (no unique map) or four of the `to` points are (the map would flatten space:
// no invertible one).
glm::mat4 projectiveFromFivePoints(const std::array<glm::vec4, 5>& from, const std::array<glm::vec4, 5>& to);

// The static prism of a cut-out in the y = 0 plane: each border edge extruded one unit along -y,
// as the +y face walks it (the volume of a light straight above at infinity). Its far vertices
// are the near ones minus (0, 1, 0). Build it once; cutoutExtrusionMatrix moves its far end.
ShadowVolume cutoutPrism(const Mesh& cutout, const EdgeAdjacency& adjacency);

// The constant projective matrix that turns cutoutPrism into the shadow volume of `light`: it
// keeps the plane y = 0 point for point and sends each far vertex p - (0, 1, 0) to the point
// away from the light through p. Found from five correspondences: (0,0,0), (1,0,0) and (0,0,1)
// stay; (0,-1,0) and (1,-1,1) go to (0,0,0) and (1,0,1) pushed away from the light. A point light
// pushes to infinity (w = 0). A directional light can only push a finite `reach`: sending every
// point to the one point at infinity would make the map singular. Throws std::invalid_argument
// for a light in the plane y = 0 (the cut-out is edge-on: no volume). The matrix comes out as the
// identity with its y column replaced by k * light (light scaled to w = 1, or k = reach).
glm::mat4 cutoutExtrusionMatrix(const glm::vec4& light, float reach);

// The sides of a shadow volume with every vertex doubled: (x, y, z, 1) at the near end and
// (x, y, z, 0) at the far end, both with the position of the silhouette vertex. A vertex shader
// blends two matrices with weights w and 1 - w: the model matrix keeps the near copy, and
// extrusionToInfinity moves the far copy away from the light. Static for a cut-out: build it once
// with the border edges (possibleSilhouetteEdges with any lit flags; a border is always silhouette).
std::vector<glm::vec4> doubledVertexVolume(const Mesh& mesh, const std::vector<SilhouetteEdge>& edges);

// The matrix that sends every point (w = 1) to the point at infinity away from the light:
// p - L for a point light, -L for a directional one. It is light.w * I - L * (0,0,0,1)^T.
glm::mat4 extrusionToInfinity(const glm::vec4& light);

// A closed object flattened onto a plane: the outline of its shadow there, as directed segments
// on the plane with the shadow on their left seen from the light (counter-clockwise around the
// shadow, clockwise around its holes).
struct Segment {
  glm::vec3 a, b;
};

// The object's silhouette edges (faces towards the light against faces away) projected onto
// `plane` from the light: closed loops whose winding number counts how many layers of the
// object cover a point. Needs every vertex strictly between the light and the plane. Throws
// std::invalid_argument otherwise, or for a mesh that is not a closed manifold.
std::vector<Segment> projectedSilhouette(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                         const glm::vec4& light, const glm::vec4& plane);

// The boundary of the region where those loops have a nonzero winding number (the GLU
// tessellator's GLU_TESS_WINDING_NONZERO with boundary only): every segment split where it
// crosses another, and a piece kept where the winding number is nonzero on one side only, turned
// so that side is on its left seen from the light. Overlaps of the object with itself leave no
// edge inside the shadow. The loops must come as projectedSilhouette gives them.
std::vector<Segment> nonzeroOutline(const std::vector<Segment>& loops, const glm::vec4& plane);

// The winding number of `point` (on the plane) around closed loops, seen from the side the
// plane's normal points to (counter-clockwise loops count +1).
int windingNumber(const std::vector<Segment>& loops, const glm::vec4& plane, const glm::vec3& point);

// The shadow volume of a flattened outline: each segment extruded away from the light, closed at
// the plane by a fan of triangles from the first vertex to each segment. The fan's triangles
// overlap, front and back facing, but their signed sum is the outline's winding number: 1 inside,
// 0 outside, which is all a counting stencil sees. The plane end must be drawn (nothing opaque
// stands there as a cut-out does), or an eye ray entering through it is not counted.
ShadowVolume flattenedVolume(const std::vector<Segment>& outline, const glm::vec4& light, float distance);

}  // namespace stencil
