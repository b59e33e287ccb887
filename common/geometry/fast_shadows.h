// The data structures and procedures of McGuire, Hughes, Egan, Kilgard and Everitt, "Fast,
// Practical and Robust Shadows" (2003), GL-free:
//   - the doubled vertex array: each caster vertex once with w = 1 and once with w = 0, so a
//     vertex shader extrudes the w = 0 copy and every volume triangle costs indices only;
//   - the possible silhouette as side quads (or, for a directional light, triangles converging
//     on the one point at infinity) indexing that array, directed so they face out;
//   - the occlusion pyramid (the light and the camera's near rectangle) that decides per caster
//     whether z-pass suffices (case 1), or z-fail is needed without (case 2) or with (case 3)
//     the light cap;
//   - the dark cap as a fan over the silhouette edges at infinity, with its triangles that span
//     180 degrees or more split;
//   - the light's bounds: casters culled against them, and a scissor rectangle;
//   - one caster's volume for one light: its case (shadowCases), what the case asks for
//     (recipeFor: z-pass or z-fail, which dark cap, whether a light cap), and the volume as
//     indices into the doubled vertex array (volumeOf).
// Counting a volume (lesson 16's countVolume): two-sided stencil, no culling, depth and colour
// writes off, depth test LESS (GREATER with reversed depth). Z-pass draws the sides, front faces
// INCR_WRAP where the depth test passes, back faces DECR_WRAP. Z-fail draws the sides, the dark
// cap and its split triangles with back faces INCR_WRAP where the depth test fails, front faces
// DECR_WRAP, then the light cap with depth func NEVER: it lies on the caster's own surface, so it
// must always take the fail path. A pixel whose count ends 0 is lit.
// Lights are homogeneous as everywhere: w = 1 a point, w = 0 the direction towards the light.
//
// Depends on: GLM, mesh, adjacency, weld, shadow_volume, bounds, frustum (C++17).
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/frustum.h"
#include "geometry/mesh.h"
#include "geometry/shadow_volume.h"

namespace stencil {

// Index i is (p_i, 1), the vertex itself; index n + i is (p_i, 0), its copy that the vertex
// shader pushes to infinity away from the light (n = mesh.positions.size()).
std::vector<glm::vec4> doubledVertexArray(const Mesh& welded);

// The sides: each silhouette edge v0 -> v1 (as possibleSilhouetteEdges directs it) extruded into two
// triangles facing out of the volume, split as extrudedQuadCorners splits them so shared edges
// cancel. For a directional light the two far copies are the same point at infinity, so each
// edge is one triangle (v1, v0, far v0). Indices into doubledVertexArray of the same mesh.
std::vector<std::uint32_t> sideIndices(const Mesh& welded, const std::vector<SilhouetteEdge>& edges,
                                       bool directional);

// An open mesh blocks the light with both sides of every face: the faces towards the light
// close one volume, the faces away from it, turned round, another. An edge between the two
// kinds is then a side of both volumes, walked the same way: its quad counts twice. These are
// possibleSilhouetteEdges with every such interior edge twice (border edges once).
std::vector<SilhouetteEdge> twoSidedSilhouetteEdges(const EdgeAdjacency& adjacency,
                                                    const std::vector<bool>& lit);

// A caster's possible silhouette edges for its lit faces (facesLight, or a piece of them): over
// its adjacency when it is a closed manifold, twoSidedSilhouetteEdges when it is open.
std::vector<SilhouetteEdge> possibleSilhouetteEdges(const PreparedCaster& caster,
                                                    const std::vector<bool>& lit);

// The light cap: the faces towards the light, as they are (w = 1 copies). twoSided (an open
// mesh): the faces away from the light too, turned round.
std::vector<std::uint32_t> lightCapIndices(const Mesh& welded, const std::vector<bool>& lit,
                                           bool twoSided = false);

// Everitt and Kilgard's dark cap: the faces away from the light, pushed to infinity (w = 0
// copies) with their winding, so the cap faces away from the light. O(f) triangles. twoSided:
// the faces towards the light too, pushed to infinity and turned round.
std::vector<std::uint32_t> backFaceDarkCapIndices(const Mesh& welded, const std::vector<bool>& lit,
                                                  bool twoSided = false);

// The dark cap of a piece of a light cap (litFacePieces): the piece's own faces pushed to
// infinity and turned round, which close the piece's sides whatever the rest of the caster does.
std::vector<std::uint32_t> pieceDarkCapIndices(const Mesh& welded, const std::vector<bool>& lit);

// The angle the three directions span: the diameter, in degrees, of the smallest spherical cap
// that holds them. 180 when no open hemisphere holds them (they are coplanar with the origin and
// surround it) or when one of them is zero.
float spanDegrees(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// McGuire's dark cap for a point light, O(s) triangles: the silhouette at infinity closed by a
// fan from the far copy of one silhouette vertex to the far copies of every edge not touching it,
// wound to face away from the light. The fan's triangles overlap with both windings, but for
// every eye ray their signed count is the silhouette's winding number, which is what a counting
// stencil sees. The rasterizer draws a triangle at infinity as the cone of its three directions,
// the short way round; a triangle whose directions span 180 degrees or more (the light near its
// plane, over its inside) has no short way, so it is split into three through the foot of the
// light on its plane, each drawn from the triangle's own directions.
struct DarkCap {
  std::vector<std::uint32_t> indices;  // into doubledVertexArray
  // The split triangles, three vertices each, in the doubled array's format: (point, 0) for a
  // far copy. Drawn with the same shader.
  std::vector<glm::vec4> split;
  std::size_t splitTriangles = 0;  // fan triangles that spanned 180 degrees or more
  std::size_t triangleCount() const { return indices.size() / 3 + split.size() / 3; }
};
DarkCap fanDarkCap(const Mesh& welded, const std::vector<SilhouetteEdge>& edges, const glm::vec3& light,
                   float splitDegrees = 179.0f);

// The signed solid angle of triangle a, b, c seen from `eye` (Van Oosterom and Strackee):
// positive when it winds counter-clockwise seen from there, up to 2 pi for a hemisphere.
double solidAngle(const glm::vec3& eye, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// A shadow volume never holds its light, so its faces' signed solid angles seen from the light
// sum to zero. The fan holds to that only while the fan and the caster's faces away from the
// light do not enclose the light together (a light inside an open container: the shadow takes
// more than half the sky, the fan covers the opening instead). Then the sum is a whole number of
// spheres, 4 pi each, and so many spheres at infinity (octahedra of directions around the light,
// facing away from it) are added to the cap's split triangles. lightCap: indices of the volume's
// light cap (lightCapIndices). Returns the spheres added (negative: facing the light), 0 for a
// light outside the caster's convex hull.
int closeAroundLight(DarkCap& cap, const Mesh& welded, const std::vector<std::uint32_t>& lightCap,
                     const glm::vec3& light);

// The camera's near rectangle in world space, corners counter-clockwise as seen by the camera,
// from the inverse of viewProjection (GL clip conventions).
std::array<glm::vec3, 4> nearRectangle(const glm::mat4& viewProjection);

// The occlusion pyramid: the region between the light and the near rectangle, as inward planes.
// Its apex is a point light; a directional light makes it a prism reaching from the near
// rectangle towards the light. A shadow volume that enters the camera's near rectangle comes
// from a caster inside it. Four sides, the near plane, and for a point light a plane through it.
Frustum occlusionPyramid(const std::array<glm::vec3, 4>& nearRect, const glm::vec4& light);

// The paper's three cases for one caster (its world bounding sphere):
//   1: it misses the occlusion pyramid, its volume cannot reach the near rectangle: z-pass,
//      sides only;
//   2: it meets the pyramid but lies outside the view frustum: z-fail, sides and dark cap (the
//      light cap would not land on the screen);
//   3: it meets the pyramid and may be seen: z-fail, sides, dark cap and light cap.
int shadowCase(const Frustum& pyramid, const Frustum& frustum, const glm::vec3& centre, float radius);

// A caster whose bounds miss the light's bounding sphere shadows nothing the light reaches: the
// way from any point inside the sphere to the light stays inside it.
bool culledByLight(const glm::vec3& lightCentre, float lightRadius, const glm::vec3& centre, float radius);

// The window rectangle (GL's origin bottom left) that holds the light's sphere on screen, for
// glScissor: the projected bounding cube of the sphere, the whole window when the sphere reaches
// the near plane. Empty (w or h zero) when the sphere is entirely off screen.
struct ScissorRect {
  int x = 0, y = 0, width = 0, height = 0;
};
ScissorRect lightScissor(const glm::vec3& centre, float radius, const glm::mat4& viewProjection,
                         glm::ivec2 size);

// The window depths (0..1, GL's default depth range) between which the light's sphere lies, for
// glDepthBoundsEXT: a visible surface whose depth is outside them lies outside the sphere, and
// no volume needs to touch its pixel. From 0 when the sphere reaches the near plane.
struct DepthBounds {
  float nearest = 0.0f, farthest = 1.0f;
};
DepthBounds lightDepthBounds(const glm::vec3& centre, float radius, const glm::mat4& view,
                             const glm::mat4& projection);

// The world bounding sphere of a mesh placed by a rigid model matrix.
BoundingSphere worldBounds(const BoundingSphere& local, const glm::mat4& model);

// ---- one caster's volume for one light, by method (lessons 13 and 16) --------------------------

// The ways to build a light's volumes (lesson 16's --set method, lesson 13's --set volumes):
//   McGuire       per caster by its case: 1 z-pass with the sides alone, 2 z-fail with the fan
//                 dark cap, 3 the same with the light cap;
//   EverittKilgard  always z-fail, both caps of every volume (the faces away from the light at
//                 infinity, the faces towards it as they are);
//   Lengyel       z-pass for every caster while none is in the occlusion pyramid, else
//                 Everitt-Kilgard's full z-fail for all of them;
//   ZPass         z-pass for every caster, which fails with the eye in a shadow.
enum class ShadowMethod { McGuire = 0, EverittKilgard = 1, Lengyel = 2, ZPass = 3 };

// The dark cap a z-fail volume is closed with at infinity.
enum class DarkCapKind {
  None,       // z-pass, or a directional light: the sides meet at one point at infinity
  Fan,        // McGuire et al.'s, O(s): a fan over the silhouette at infinity (fanDarkCap)
  BackFaces,  // Everitt and Kilgard's, O(f): the faces away from the light at infinity
  Piece,      // one piece of the light cap pushed to infinity and turned round (pieceDarkCapIndices)
};

// What one caster's volume is for one light: counted in front of the scene or behind it, and
// which caps close it.
struct Recipe {
  bool zfail = false;  // counted behind the scene; else in front of it (z-pass)
  DarkCapKind darkCap = DarkCapKind::None;
  bool lightCap = false;
};

// The one place a method and a caster's case become a recipe. shadowCase 1, 2 or 3; a culled
// caster (0) has no volume, and gets the empty recipe (z-pass, no caps).
//   McGuire          1 z-pass, the sides alone; 2 z-fail with the fan; 3 the same and the light
//                    cap (lightCapInCase3 false leaves it out, to show the count go wrong);
//   EverittKilgard   z-fail with both full caps, whatever the case;
//   Lengyel          z-pass while no caster of the light meets the occlusion pyramid
//                    (anyInPyramid: some case above 1), else as EverittKilgard;
//   ZPass            z-pass, which fails with the eye in a shadow.
// A directional light's z-fail volume needs no dark cap: its sides meet at one point. (Lesson 16
// closes a caster that would nest past an 8-bit count in pieces of its light cap, each a
// z-fail volume with DarkCapKind::Piece and its light cap: the one recipe made elsewhere.)
Recipe recipeFor(ShadowMethod method, int shadowCase, bool anyInPyramid, bool lightCapInCase3,
                 bool directional);

// What one caster draws for one light, as ranges of its index list (volumeOf).
struct CasterVolume {
  int shadowCase = 0;  // 1, 2 or 3 from the pyramid; 0 culled, or not set (volumeOf leaves it)
  bool zfail = false;
  std::size_t sides = 0, darkCap = 0, lightCap = 0, silhouette = 0;  // index counts, in this order
  std::size_t splitTriangles = 0, splitVertices = 0;  // split vertices include spheres' octahedra
  int spheres = 0;                                    // whole spheres added to the fan
};

// One caster's volume as indices into its doubledVertexArray, with the dark cap's split
// triangles (and any spheres closeAroundLight adds) as vertices of their own.
struct VolumeIndices {
  CasterVolume volume;  // shadowCase left 0 for the caller
  std::vector<std::uint32_t> indices;
  std::vector<glm::vec4> split;
};

// One caster's volume for a light in the caster's own space, built as the recipe says: the
// sides, the dark cap and the light cap one after the other, then the silhouette as lines (for
// an overlay). lit: the faces taken as facing the light (facesLight's, or one piece of them,
// shadow_volume.h's litFacePieces, with DarkCapKind::Piece); edges: the possible silhouette
// edges between them (an open caster's both ways, possibleSilhouetteEdges(PreparedCaster, lit)).
// splitFan: split fan triangles that span 180 degrees or more (McGuire et al. section 5).
// light: w = 1 a point, w = 0 a direction; DarkCapKind::Fan needs a point light (recipeFor never
// asks a directional light for one), as the fan's apex is the light itself.
VolumeIndices volumeOf(const PreparedCaster& caster, const glm::vec4& light, const Recipe& recipe,
                       const std::vector<bool>& lit, const std::vector<SilhouetteEdge>& edges,
                       bool splitFan = true);

// A light's bounds for one view: the sphere (radius infinite for a directional light or with
// bounds off), its scissor rectangle (the whole window when unbounded; empty when off screen)
// and the window depths it spans, for EXT_depth_bounds_test where `depthBounds` says it applies.
// view and projection in GL's convention (Frame::projection); with reversed depth (lesson 15)
// the same bounds are glDepthBoundsEXT(1 - depth.farthest, 1 - depth.nearest).
struct LightClip {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
  ScissorRect scissor;
  bool depthBounds = false;  // bounded, so the depth range below means something
  DepthBounds depth;
  bool offScreen() const { return scissor.width <= 0 || scissor.height <= 0; }
};
LightClip lightClip(const glm::vec4& light, float radius, bool bounds, const glm::mat4& view,
                    const glm::mat4& projection, glm::ivec2 size);

// Every caster's case for one light, from their world bounding spheres: shadowCase's 1, 2 or 3,
// or 0 where the light's bounds (clip.centre, clip.radius; an infinite radius culls nothing)
// miss the caster (culledByLight); one case per sphere, in their order. Everything in world
// space and GL's clip convention: pyramid = occlusionPyramid(nearRectangle(vp), light) and
// frustum = viewFrustum(vp, false) (no far plane) for vp = projection x view, never a
// reversed-depth projection.
std::vector<int> shadowCases(const std::vector<BoundingSphere>& casters, const LightClip& clip,
                             const Frustum& pyramid, const Frustum& frustum);

// Whether some caster meets the occlusion pyramid (a case above 1): Lengyel's switch to z-fail.
bool anyInPyramid(const std::vector<int>& cases);

}  // namespace stencil
