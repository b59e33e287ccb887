// Shadow volumes built on the CPU (Kilgard, "Improving Shadows and Reflections via the
// Stencil Buffer", section 6 and appendix C): which faces a light sees, the silhouette between
// them, and the quads that extrude edges away from the light. The result is a soup of
// homogeneous triangles in the mesh's own space: draw it with the mesh's model matrix.
//
// A light is homogeneous, as in planar.h: w = 1 a point light, w = 0 the direction towards a
// directional light. Give it in the mesh's space (inverse model matrix times the world light).
//
// Depends on: GLM, mesh, adjacency, weld (C++17).
#pragma once
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <string>
#include <vector>

#include "geometry/adjacency.h"
#include "geometry/mesh.h"

namespace stencil {

// How far the edges are pushed away from the light. A finite distance is Kilgard's
// extendVolume: the volume ends there, and a receiver beyond it is not shadowed. Infinity puts
// the far vertices at w = 0, the point at infinity away from the light: the volume never
// ends, and a far clipping plane cuts only the part that lies beyond everything drawn. The same
// value is the lessons' infinite far plane and a light without bounds.
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Where `point` goes when pushed `distance` away from the light (kInfinity: w = 0).
glm::vec4 extrudeAway(const glm::vec3& point, const glm::vec4& light, float distance);

// One flag per triangle: does it face the light? Strictly: a face edge-on to the light (or a
// degenerate one) does not, so it casts no volume of its own.
std::vector<bool> facesLight(const Mesh& mesh, const glm::vec4& light);

// The faces whose side the eye sees is turned from the light: the eye and the light on opposite
// sides of the face's plane, decided with the float operations facesLight decides facing with (a
// face edge-on to the light is turned from it seen from the front, as facesLight calls it unlit).
// Such a side of a caster lies in the caster's own shadow: the segment from the light reaches it
// through the caster's inside, or, for an open caster, through the face itself. Faces edge-on to
// the eye (never seen) are left out. Returns their indices, three per face, in face order. light
// and eye homogeneous in the mesh's space (w = 0: the direction towards the light, or towards
// the eye of a parallel view).
std::vector<std::uint32_t> facesTurnedFromLight(const Mesh& mesh, const glm::vec4& light, const glm::vec4& eye);

// A directed edge (v0 -> v1) that extrudes into a quad facing out of the volume: the way the
// lit face walks it.
struct SilhouetteEdge {
  std::uint32_t v0, v1;
};

// The edges between a face that faces the light and one that does not, and the border edges of
// an open mesh (an outline and the holes of a planar cut-out), whichever way their one face
// faces. Needs adjacency of welded vertices (adjacency.h); non-manifold edges give no
// meaningful silhouette, check the adjacency report first.
std::vector<SilhouetteEdge> possibleSilhouetteEdges(const EdgeAdjacency& adjacency,
                                                    const std::vector<bool>& lit);

// ---- silhouettes at memory speed --------------------------------------------------------------
//
// facesLight gathers three indices and three positions per triangle and recomputes its normal on
// every call; possibleSilhouetteEdges reads 16-byte edges and two bit flags through bounds checks. A caster
// that is drawn from many lights or frames does the arithmetic that depends only on the mesh once:
// SilhouetteCaster keeps each face's normal and first corner (the facing test's inputs) in
// structure-of-arrays order, and each edge's two faces apart from its two vertices. The facing pass
// then streams 24 bytes per face, the edge pass 8 bytes per edge plus a one-byte flag per face it
// names, and an edge's vertices are read only when it is a possible silhouette edge.

// A caster's facing test and edges, prepared once. Built from a mesh and its adjacency (welded
// vertices, as possibleSilhouetteEdges needs). The normal is cross(b - a, c - a) and the test
// dot(normal, L.xyz - L.w * a) > 0, the same float operations in the same order as facesLight,
// so the flags, and the edges, are bit for bit the ones the Mesh overloads give.
struct SilhouetteCaster {
  std::vector<float> nx, ny, nz;  // per face: its normal, not normalised (mesh units squared)
  std::vector<float> ax, ay, az;  // per face: its first corner (mesh units)
  struct EdgeFaces {
    std::int32_t face0, face1;  // face1 = faceCount() for a border edge (see litFlags)
  };
  std::vector<EdgeFaces> edgeFaces;      // per adjacency edge, in the adjacency's order
  std::vector<SilhouetteEdge> edgeEnds;  // per adjacency edge: v0 -> v1 as face0 walks it
  std::size_t faceCount() const { return nx.size(); }
};
// Throws std::invalid_argument for an invalid mesh (validateMesh) or an adjacency that names a
// face the mesh does not have.
SilhouetteCaster prepareSilhouettes(const Mesh& mesh, const EdgeAdjacency& adjacency);

// The facing pass: lit[t] = 1 when face t faces the light (strictly, as facesLight), else 0;
// lit gets faceCount() + 1 entries, the last one 2, which a border edge's face1 names, so that it
// differs from its one face whichever way that faces. `lit` is reused storage: no allocation
// once it is large enough.
void facesLight(const SilhouetteCaster& caster, const glm::vec4& light, std::vector<std::uint8_t>& lit);

// The edge pass: the possible silhouette edges for flags from the facing pass above, appended to
// `out` after clearing it, in the order and direction possibleSilhouetteEdges(adjacency, lit) gives.
// Throws std::invalid_argument when lit does not have faceCount() + 1 entries.
void possibleSilhouetteEdges(const SilhouetteCaster& caster, const std::vector<std::uint8_t>& lit,
                             std::vector<SilhouetteEdge>& out);

// Both passes, for one light: the same edges as possibleSilhouetteEdges(adjacency, facesLight(mesh, light)).
std::vector<SilhouetteEdge> possibleSilhouetteEdges(const SilhouetteCaster& caster, const glm::vec4& light);

// Homogeneous triangles, three vertices each, counter-clockwise seen from outside the volume.
struct ShadowVolume {
  std::vector<glm::vec4> vertices;
  std::size_t triangleCount() const { return vertices.size() / 3; }
};

// The quad of edge a -> b (walked by the lit face) as two triangles facing out of the volume,
// by corner: 0 = a, 1 = b, 2 = a pushed away, 3 = b pushed away. It is split on the diagonal
// from the smaller endpoint (in x, then y, then z), so the edge walked the other way gives the
// same two triangles turned round, and the two quads cancel pixel for pixel.
std::array<int, 6> extrudedQuadCorners(const glm::vec3& a, const glm::vec3& b);

// The quad that extrudes edge a -> b away from the light, as two triangles facing out.
void addExtrudedEdge(ShadowVolume& volume, const glm::vec3& a, const glm::vec3& b, const glm::vec4& light,
                     float distance);

// ---- a caster, prepared once -------------------------------------------------------------------

// What preparing a caster found and did. Open meshes are kept: their border edges extrude as
// possible silhouette edges, and their faces cap the volume from both sides.
struct CasterReport {
  std::size_t inputVertices = 0, weldedVertices = 0;
  std::size_t droppedDegenerate = 0;  // triangles with a repeated vertex or zero area, removed
  std::size_t borderEdges = 0;        // open mesh
  std::size_t nonManifoldEdges = 0;   // three or more faces: refused
  std::size_t inconsistentEdges = 0;  // two faces walking the edge the same way: refused
  // Closed, two-manifold and consistently wound: what z-fail's closed volumes need (as
  // AdjacencyReport::closedManifold).
  bool closedManifold() const { return borderEdges == 0 && usable(); }
  bool usable() const { return nonManifoldEdges == 0 && inconsistentEdges == 0; }
  std::vector<std::string> messages;  // one line each, for the user
};

// A caster made fit for shadow volumes, built once and used for every light: welded positions (no
// normals: shapes split vertices at creases to carry normals, the silhouette needs them joined),
// degenerate triangles dropped, and its edges' faces.
struct PreparedCaster {
  Mesh mesh;
  EdgeAdjacency adjacency;
  CasterReport report;
};
// Prepares a mesh (its normals are ignored) as a caster: welds it by position (weld.h), drops its
// degenerate triangles and builds its edges' faces; the report says what was done and found.
// Throws std::invalid_argument for an invalid mesh or a position that is not finite.
PreparedCaster prepareCaster(const Mesh& mesh);

// The sides of the volume of a whole caster: every silhouette edge extruded. Its boundary is
// the union's, which is what the invert-bit method needs; the caster's own lit faces close it
// at the light's end. Throws std::invalid_argument for a mesh with non-manifold or
// inconsistently wound edges.
ShadowVolume silhouetteVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                              float distance);
ShadowVolume silhouetteVolume(const PreparedCaster& caster, const glm::vec4& light, float distance);

// Kilgard's extendVolume for every triangle that faces the light: its three edges extruded, one
// volume per triangle. No adjacency needed and any triangle soup works, but the volumes
// overlap, so only a counting stencil gets their union right (shared edges cancel: one quad
// enters where the next exits). Three quads per lit triangle instead of one per silhouette edge.
// twoSided: a triangle facing away casts too, walked backwards (a planar cut-out lit from
// behind); a closed mesh does not need it, its front faces already cover the back's volumes.
ShadowVolume polygonVolumes(const Mesh& mesh, const glm::vec4& light, float distance, bool twoSided = false);

// Everitt and Kilgard's closed volume of a closed caster, what z-fail counts: the silhouette
// edges extruded (the sides), the faces that face the light as they are (the light cap, on the
// caster's own surface), and the faces that do not, pushed away from the light (the dark cap;
// to infinity it lies at w = 0). Every triangle faces out. For a directional light pushed to
// infinity the dark cap shrinks to the single point -L, so it is left out: the sides already
// meet there. Throws std::invalid_argument unless the mesh is closed, two-manifold and
// consistently wound (adjacency.h's report): an open volume would leave the count off.
struct ClosedVolume {
  ShadowVolume triangles;  // the sides, then the light cap, then the dark cap
  std::size_t possibleSilhouetteEdges = 0;
  std::size_t sideTriangles = 0, lightCapTriangles = 0, darkCapTriangles = 0;
};
ClosedVolume closedVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                          float distance);

// The volume of a piece of the light cap: `lit` (one flag per triangle) must be a subset of the
// faces that face the light, such as one piece of litFacePieces. The sides extrude the edges
// between a lit face and any other, the light cap is the lit faces, and the dark cap the lit
// faces pushed away and turned round. The count it adds at a point is the number of lit faces the
// segment from the light to the point crosses (the sum of the faces' own volumes, whose shared
// sides cancel): the pieces' counts add up to the whole caster's. Throws as closedVolume does,
// and std::invalid_argument when lit has the wrong size.
ClosedVolume closedVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                          float distance, const std::vector<bool>& lit);

// ---- more than 255 nested volumes ------------------------------------------------------------
//
// The z-fail count at a point is how many times the segment from the light to the point crosses a
// caster's faces that face the light, summed over the casters. An 8-bit stencil wraps at 256, and
// a point inside 256 volumes reads 0: lit. countPlan splits a light's volumes into groups whose
// counts cannot pass 127, to be counted in the low 7 bits and folded into the top bit after each
// group; a scene whose bounds add up to 255 or less keeps the plain 8-bit count.

// Whether a closed caster is convex: one connected piece, and at every edge each face's far
// corner lies on or behind the other face's plane (within a tolerance of 1e-5 of the mesh's
// size). A closed, connected surface convex at every edge bounds a convex solid, so a segment
// from a light outside it crosses at most one face that faces the light. Needs a closed mesh's
// adjacency (welded vertices); false for anything else. facesIn: the mesh's faces point inwards
// (a room): whether the region they enclose is convex.
bool isConvex(const Mesh& mesh, const EdgeAdjacency& adjacency, bool facesIn = false);

// An upper bound on the count one closed volume adds at any point, from what building it saw:
// 1 for a convex caster; otherwise the number of lit faces, and no more than half the silhouette
// edges when the light lies outside the caster's bounding sphere (or is directional). Why the
// half: seen from the light, a great circle of directions (a line, for a directional light)
// through any direction leaves the caster's outline, crosses each silhouette edge's image at most
// once, and the number of lit faces behind it changes by one at each crossing, from 0 back to 0.
std::size_t nestingBound(std::size_t litFaces, std::size_t possibleSilhouetteEdges, bool convex,
                         bool lightOutside);

// A bound on the same count from the silhouette seen from the light: the count at a point is the
// number of lit faces whose images, seen from the light, cover the point's direction, and since
// the lit faces all wind one way in that image, that is the winding number of the image of their
// boundary, the possible silhouette edges. Projected onto a plane (centrally, onto a plane across
// the axis from the light to the lit faces' centroid, for a point light; along the light's
// direction for a directional one) every edge is a segment, and a line x = const leaves the
// outline on both sides, the winding changing by at most one at each segment it crosses: the
// winding anywhere on it is at most half the segments whose x-range holds it. The bound is the
// smaller of the largest such half across x and across y (each range widened by 1e-9 of the
// image's extent, so rounding can only raise it). A torus crossed at most four times gets 2 or
// so whatever its tessellation, where half its silhouette edges is hundreds. mesh: object space;
// lit: one flag per triangle (facesLight, or a part of it); edges: the possible silhouette edges
// of exactly those faces; light: homogeneous, in the mesh's space. 0 when no face is lit;
// std::numeric_limits<std::size_t>::max() (no bound) when a lit face's corner does not lie in
// front of the light along the axis (the light inside or among the faces), where no plane shows
// them all. Throws std::invalid_argument when lit has the wrong size.
std::size_t projectedNestingBound(const Mesh& mesh, const std::vector<bool>& lit,
                                  const std::vector<SilhouetteEdge>& edges, const glm::vec4& light);

// The faces that face the light in pieces of at most maxFaces each, in index order (one flag
// per triangle per piece). No pieces when no face faces the light. Throws
// std::invalid_argument for maxFaces 0.
std::vector<std::vector<bool>> litFacePieces(const std::vector<bool>& lit, std::size_t maxFaces);

// A piece of a caster's light cap and the most its volume adds to a pixel's count.
struct LitPiece {
  std::vector<bool> lit;  // one flag per triangle: closedVolume's `lit`
  std::size_t nesting = 0;
};
// The faces that face the light in pieces whose volumes each count at most maxNesting: a caster
// whose count could pass a count group's range is counted piece by piece (closedVolume with
// each piece as `lit`). The pieces are whole connected regions of lit faces (joined through
// shared edges), as many together as their bounds (the smaller of their face count and
// projectedNestingBound) allow; only a region that by itself may count past maxNesting is cut
// into runs of maxNesting faces in index order. Why whole regions: where two pieces share an
// edge, each piece's volume has a side hanging from it, inside the caster, and at a pixel whose
// centre lies on that edge (within the rasterizer's sub-pixel precision) the side's depth and
// the surface's are equal but for rounding. Counted in one group, the two sides cancel; in two
// groups, each group's count is off by one there and the pixel is shadowed (issue 29: 321
// pieces of a torus of 86,400 triangles left 3 to 11 such pixels). Regions share no edge.
// Needs a closed caster's adjacency (welded vertices); light homogeneous in the mesh's space.
// Throws std::invalid_argument for maxNesting 0 or lit of the wrong size.
std::vector<LitPiece> litFacePieces(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                    const std::vector<bool>& lit, const glm::vec4& light,
                                    std::size_t maxNesting);

// Which group each volume is counted in, from their nesting bounds in drawing order.
struct CountPlan {
  std::vector<int> group;  // per volume; groups are consecutive, from 0
  int groups = 0;
  bool fold = false;  // count in bits 0-6 and fold each group into bit 7; else all 8 bits, one group
};
// The plain count (one group, no fold) when the bounds add up to 255 or less; otherwise greedy
// groups of at most 127 each. A bound above 127 (split such a caster with litFacePieces first)
// gets a group of its own and can still wrap: the caller should not let that happen.
CountPlan countPlan(const std::vector<std::size_t>& bounds);

}  // namespace stencil
