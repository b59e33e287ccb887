// Constructive solid geometry with no OpenGL: a CSG tree's text form, its normal form as a sum of
// products (Goldfeather, Monar, Turk and Fuchs, "Near Real-Time CSG Rendering Using Tree
// Normalization and Geometric Pruning", 1989), and a CSG ray cast, the oracle that says which
// surface each pixel of a stencil CSG rendering must show (lesson 14).
#pragma once
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/mesh.h"

namespace stencil {

// A CSG tree over numbered primitives. nodes[root] is the root; an operation's children are
// nodes of the same vector.
struct CsgTree {
  enum class Kind { Primitive, Union, Intersection, Difference };
  struct Node {
    Kind kind = Kind::Primitive;
    int primitive = -1;         // Primitive: its index in the name list given to parseCsg
    int left = -1, right = -1;  // operations: the operands' node indices
  };
  std::vector<Node> nodes;
  int root = -1;

  std::size_t primitiveCount() const;  // leaves, a primitive named twice counted twice
};

inline constexpr std::size_t kMaxCsgDepth = 256;        // parentheses and operators nested
inline constexpr std::size_t kMaxCsgProducts = 100000;  // normalize's default bound

// Reads the text form: primitive names, `+` union, `*` intersection, `-` difference,
// parentheses; `*` binds tighter than `+` and `-`, which bind left to right, so
// "a - b + c" is (a - b) + c and "a - b * c" is a - (b * c). A name is [A-Za-z_][A-Za-z0-9_]*
// and must be in `names` (its index there is the primitive). Throws std::invalid_argument "column N: what is
// wrong" (1-based) for an unknown name, a missing operand or parenthesis, a stray character, or nesting past
// kMaxCsgDepth.
CsgTree parseCsg(std::string_view text, const std::vector<std::string>& names);

// Whether parseCsg can name a primitive called `name`: [A-Za-z_][A-Za-z0-9_]*. Any other name would
// be read as several ("drill-x" as drill - x) or not at all.
bool isCsgName(std::string_view name);

// The tree written back in the text form, fully parenthesised, with the given names.
std::string csgText(const CsgTree&, const std::vector<std::string>& names);

// One product of the normal form: the intersection of the `intersected` primitives minus each of
// the `subtracted` ones. Both sorted, without repeats, never sharing a primitive; intersected is
// never empty (a product of complements alone would be unbounded, and the rules never make one).
struct CsgProduct {
  std::vector<int> intersected, subtracted;
  std::size_t size() const { return intersected.size() + subtracted.size(); }
};

struct SumOfProducts {
  std::vector<CsgProduct> products;  // the union of these
  // The growth: products the rules produced before empty ones (a primitive both intersected
  // and subtracted, x - x) were dropped, and the primitives they named together.
  std::size_t productsBeforePruning = 0, literalsBeforePruning = 0;
  std::size_t literals() const;  // primitives named by the kept products together
};

// The tree as a union of products, by Goldfeather et al.'s rewriting rules applied all the way
// down: x - (y + z) = (x - y) - z, x * (y + z) = x*y + x*z, x - (y * z) = (x - y) + (x - z),
// x - (y - z) = (x - y) + (x * z), and their mirror images. A difference distributes over the
// products of what it subtracts, so the normal form can grow exponentially with the tree: past
// maxProducts products it throws std::length_error "the sum of products grows past N products"
// (OpenSCAD's "normalized tree is growing past N elements"). Throws std::invalid_argument for a
// malformed tree.
SumOfProducts normalize(const CsgTree&, std::size_t maxProducts = kMaxCsgProducts);

// Membership: whether a point inside exactly the primitives i with inside[i] lies in the solid.
// Both throw std::invalid_argument when inside is shorter than a primitive index.
bool contains(const CsgTree&, const std::vector<bool>& inside);
bool contains(const SumOfProducts&, const std::vector<bool>& inside);

// ---- SCS: sequenced convex subtraction (Stewart, Leach and John 1998) ---------------------------

// The order SCS subtracts n convex primitives in: every ordering of 0..n-1 must be a subsequence
// (the primitives may lie along a ray in any order). This one runs up 0..n-1, then down n-2..0,
// up 1..n-1, and so on, n runs in all, each after the first one shorter: n(n - 1) + 1 entries.
// The shortest such sequences are known to have (n - 1)^2 + 3 entries for n >= 3 (1 and 3 for
// n = 1 and 2), fewer from n = 4 on; this is not one of those. Throws std::invalid_argument for
// n < 0 or n > 1000.
std::vector<int> subtractionSequence(int n);

// Whether every ordering of 0..n-1 is a subsequence of `sequence` (n! orderings: n <= 8, else
// std::invalid_argument).
bool containsEveryOrdering(const std::vector<int>& sequence, int n);

// The length of the shortest sequence over 0..n-1 that contains every ordering, by exhaustive
// search (n <= 4, else std::invalid_argument): the known minimum, derived.
std::size_t shortestOrderingSequence(int n);

// ---- the CSG ray cast ---------------------------------------------------------------------------

// A closed, outward-wound primitive mesh placed in the world.
struct CsgPrimitive {
  const Mesh* mesh;  // not owned
  glm::mat4 model;
};

inline constexpr int kNoSurface = -1;  // the pixel's ray never enters the solid
inline constexpr int kNearPlane = -2;  // the ray starts inside the solid: the near plane cuts it

// What each pixel of a size.x by size.y image shows, top row first like Image.
struct CsgImage {
  glm::ivec2 size{0};
  std::vector<float> depth;    // window depth in [0, 1] (GL's default depth range); 1 where empty
  std::vector<int> primitive;  // the primitive whose surface is seen, or kNoSurface, kNearPlane
  // Coincident faces: per pixel, the other primitives whose faces lie in the plane of the face
  // seen there (empty almost everywhere). The rule: a shared surface belongs to every primitive
  // lying in it, and a picture may show any of them.
  std::vector<std::vector<int>> sharedWith;
};

// Ray casting of the solid: along each pixel centre's ray from the near plane, the intervals
// inside each primitive (its surfaces crossed, entering where the ray meets a face's front and
// leaving at a back, a running count > 0 being inside, so a concave primitive gives several
// intervals) combined by the tree; the first surface is where the combination turns from
// outside to inside. Its window depth comes from viewProjection (GL's clip conventions, clip z
// from -w at the near plane to +w at the far; a far plane at infinity is fine), and its
// primitive is the one whose surface it is. Crossings of coplanar faces of different primitives
// (coincident faces: the hit points lie in both planes within float rounding of their distance
// from the world's origin) count as one crossing, so a shared surface is decided by the tree, not
// by rounding: A - B with B's top face in A's top face opens the pocket. Surfaces past the far
// plane are not seen. Throws
// std::invalid_argument for a primitive RayScene::add refuses, a tree naming a primitive
// that is not given, or a viewProjection without an inverse (no rays to cast).
CsgImage rayCastCsg(const std::vector<CsgPrimitive>& primitives, const CsgTree& tree,
                    const glm::mat4& viewProjection, glm::ivec2 size);

struct CsgReport {
  std::size_t pixels = 0;
  std::size_t primitiveDisagreements = 0;  // another primitive seen (or none)
  std::size_t depthDisagreements = 0;      // the same primitive, a depth further than the tolerance
  std::size_t onEdges = 0;                 // of the disagreeing pixels, those on an edge (forgiven)
  std::size_t edgePixels = 0;              // pixels the edges cross, disagreeing or not
  float largestDepthError = 0.0f;          // over the pixels that agree on the primitive, off edges
  bool passed() const { return primitiveDisagreements + depthDisagreements == onEdges; }
};

// The pixels (top row first, size.x by size.y) where a rasterized picture of the primitives may
// differ from a ray through the pixel's centre, decided in the geometry: those whose square,
// grown by `margin` pixels on every side, is crossed by an edge of what can be seen. The edges:
// each primitive's possible silhouette edges (an edge between a face turned to the eye and one
// turned away, or next to a face edge-on to the eye: where one primitive's surface passes behind
// itself or another's), the curves where faces of two primitives cross (triangle against
// triangle, where the CSG result turns from one primitive's surface to another's), and where
// faces cross the near and the far plane. Faces' shared edges within one side of a surface are
// not edges: both triangles give the same depth there, and the rasterizer covers each pixel
// centre once. margin allows for the rasterizer's snapping of vertices to its sub-pixel grid:
// 2^-GL_SUBPIXEL_BITS is enough. The primitives' triangles are placed by their models (an edge of
// one mesh is two triangles with the same two corner positions). Throws std::invalid_argument
// for a primitive without a mesh or a negative margin.
std::vector<bool> csgEdgePixels(const std::vector<CsgPrimitive>& primitives, const glm::mat4& viewProjection,
                                glm::ivec2 size, float margin);

// A rendering's depth and primitive per pixel (same layout as CsgImage) against the ray cast.
// A pixel agrees when it shows the ray cast's primitive, or one that shares the surface seen there
// (CsgImage::sharedWith), at a depth within the tolerance: depthStep (the depth buffer's
// resolution, window units) plus the depth the ray cast's surface changes by over `snap` pixels
// in x and y (the rasterizer's vertex snapping, from the neighbouring pixels' depths on the same
// surface). Disagreeing pixels on `edges` (csgEdgePixels) are counted as on edges, and forgiven.
// Throws std::invalid_argument when the sizes do not match.
CsgReport compareCsg(const CsgImage& expected, const std::vector<float>& depth, const std::vector<int>& primitive,
                     const std::vector<bool>& edges, float depthStep, float snap);

}  // namespace stencil
