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
};

// Ray casting of the solid: along each pixel centre's ray from the near plane, the intervals
// inside each primitive (its surfaces crossed, entering where the ray meets a face's front and
// leaving at a back, a running count > 0 being inside, so a concave primitive gives several
// intervals) combined by the tree; the first surface is where the combination turns from
// outside to inside. Its window depth comes from viewProjection (GL's clip conventions, clip z
// from -w at the near plane to +w at the far; a far plane at infinity is fine), and its
// primitive is the one whose surface it is. Surfaces past the far plane are not seen. Throws
// std::invalid_argument for a primitive RayScene::add refuses or a tree naming a primitive
// that is not given.
CsgImage rayCastCsg(const std::vector<CsgPrimitive>& primitives, const CsgTree& tree,
                    const glm::mat4& viewProjection, glm::ivec2 size);

struct CsgReport {
  std::size_t pixels = 0;
  std::size_t primitiveDisagreements = 0;  // another primitive seen (or none)
  std::size_t depthDisagreements = 0;      // the same primitive, a depth further than the tolerance
  std::size_t onEdges = 0;                 // of the disagreeing pixels, those on an edge (forgiven)
  float largestDepthError = 0.0f;          // over the pixels that agree on the primitive, off edges
  bool passed() const { return primitiveDisagreements + depthDisagreements == onEdges; }
};

// A rendering's depth and primitive per pixel (same layout as CsgImage) against the ray cast. A
// pixel is on an edge when a pixel of its 3x3 neighbourhood shows another primitive in the ray
// cast, or the same one more than edgeDepthJump away in depth (a primitive's silhouette over
// itself, a torus' near side over its far side). depthTolerance and edgeDepthJump are in window
// depth units. Throws std::invalid_argument when the sizes do not match.
CsgReport compareCsg(const CsgImage& expected, const std::vector<float>& depth,
                     const std::vector<int>& primitive, float depthTolerance, float edgeDepthJump = 1e-3f);

}  // namespace stencil
