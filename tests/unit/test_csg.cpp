// CSG without GL: the text form's precedence and its errors; the sum of products against the tree
// on every membership of its primitives, its exact products for A - (B - C), its growth and bound;
// the CSG ray cast on two cubes seen face on, with depths derived from the geometry, and the near
// plane inside the solid; compareCsg's edge rule.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "geometry/csg.h"
#include "geometry/shapes.h"

using namespace stencil;

namespace {

const std::vector<std::string> kNames = {"a", "b", "c", "d", "e", "f"};

std::string roundTrip(const std::string& text) {
  return csgText(parseCsg(text, kNames), kNames);
}

std::string parseError(const std::string& text) {
  try {
    parseCsg(text, kNames);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// Every membership of the first n primitives: the tree and its normal form agree.
void expectSameSolid(const std::string& text, std::size_t n = 6) {
  const CsgTree tree = parseCsg(text, kNames);
  const SumOfProducts sop = normalize(tree);
  for (unsigned bits = 0; bits < (1u << n); ++bits) {
    std::vector<bool> in(n);
    for (std::size_t i = 0; i < n; ++i) in[i] = (bits >> i) & 1u;
    EXPECT_EQ(contains(tree, in), contains(sop, in)) << text << " at membership " << bits;
  }
  for (const CsgProduct& p : sop.products) EXPECT_FALSE(p.intersected.empty()) << text;
}

// Looking down -z from z = 5 at the origin, 60 degrees, a 41x41 image.
glm::mat4 frontView() {
  return glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 20.0f) *
         glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
}

// The window depth where pixel (px, py) of the 41x41 front view meets the plane z = planeZ.
float depthOnPlane(int px, int py, float planeZ) {
  const glm::mat4 vp = frontView(), inverse = glm::inverse(vp);
  const glm::vec2 ndc(2.0f * (static_cast<float>(px) + 0.5f) / 41.0f - 1.0f,
                      1.0f - 2.0f * (static_cast<float>(py) + 0.5f) / 41.0f);
  const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  const glm::vec3 hit = p0 + (planeZ - p0.z) / (p1.z - p0.z) * (p1 - p0);
  const glm::vec4 clip = vp * glm::vec4(hit, 1.0f);
  return 0.5f * clip.z / clip.w + 0.5f;
}

}  // namespace

TEST(Csg, TextFormPrecedence) {
  EXPECT_EQ(roundTrip("a - b * c"), "(a - (b * c))");
  EXPECT_EQ(roundTrip("a - b + c"), "((a - b) + c)");
  EXPECT_EQ(roundTrip("a-b-c"), "((a - b) - c)");
  EXPECT_EQ(roundTrip(" ( a + b ) * c "), "((a + b) * c)");
  EXPECT_EQ(parseCsg("a - (b - c)", kNames).primitiveCount(), 3u);
}

TEST(Csg, TextFormErrorsNameTheColumn) {
  EXPECT_EQ(parseError("a - x"), "column 5: no primitive named 'x'");
  EXPECT_EQ(parseError("a - (b + c"), "column 5: '(' is never closed");
  EXPECT_EQ(parseError("a -"), "column 4: a primitive or '(' expected, the text ends");
  EXPECT_EQ(parseError("a ? b"), "column 3: unexpected '?'");
  EXPECT_EQ(parseError("a + * b"), "column 5: a primitive or '(' expected, got '*'");
  EXPECT_EQ(parseError(""), "column 1: a primitive or '(' expected, the text ends");
  const std::string deep = std::string(kMaxCsgDepth + 1, '(') + "a" + std::string(kMaxCsgDepth + 1, ')');
  EXPECT_EQ(parseError(deep), "column 257: parentheses nested deeper than 256");
  const std::string allowed = std::string(kMaxCsgDepth, '(') + "a" + std::string(kMaxCsgDepth, ')');
  EXPECT_EQ(roundTrip(allowed), "a");
}

TEST(Csg, NestedDifferenceIsTwoProducts) {
  // A - (B - C) = A ~B + A C: what is left of A where B is, except where C fills B's hole.
  const SumOfProducts sop = normalize(parseCsg("a - (b - c)", kNames));
  ASSERT_EQ(sop.products.size(), 2u);
  EXPECT_EQ(sop.products[0].intersected, std::vector<int>({0}));
  EXPECT_EQ(sop.products[0].subtracted, std::vector<int>({1}));
  EXPECT_EQ(sop.products[1].intersected, std::vector<int>({0, 2}));
  EXPECT_TRUE(sop.products[1].subtracted.empty());
}

TEST(Csg, NormalFormIsTheSameSolid) {
  for (const char* text :
       {"a", "a + b", "a * b", "a - b", "b - a", "a - (b - c)", "a - (b + c)", "a - b * c",
        "(a + b) * (c + d)", "(a - b) * (c - d)", "(a + b) - (c * d - e)", "a - (b - (c - (d - e)))",
        "(a * b - c) + (d - e * f)", "a - a", "a * b - b * a + c"})
    expectSameSolid(text);
}

TEST(Csg, NormalFormGrowth) {
  // (a + b)(c + d)(e + f): 2^3 products of three primitives each.
  SumOfProducts sop = normalize(parseCsg("(a + b) * (c + d) * (e + f)", kNames));
  EXPECT_EQ(sop.products.size(), 8u);
  EXPECT_EQ(sop.literals(), 24u);
  // A chain of differences stays one product however long it is.
  sop = normalize(parseCsg("a - b - c - d - e - f", kNames));
  EXPECT_EQ(sop.products.size(), 1u);
  EXPECT_EQ(sop.products[0].subtracted, std::vector<int>({1, 2, 3, 4, 5}));
  // a - (b c d e f) = a~b + a~c + ... : one product per primitive subtracted from.
  sop = normalize(parseCsg("a - b * c * d * e * f", kNames));
  EXPECT_EQ(sop.products.size(), 5u);
  // x - x is empty: the rules make the product, pruning drops it.
  sop = normalize(parseCsg("a - a", kNames));
  EXPECT_EQ(sop.productsBeforePruning, 1u);
  EXPECT_EQ(sop.literalsBeforePruning, 2u);
  EXPECT_TRUE(sop.products.empty());
  // Past the bound: one line saying so.
  try {
    normalize(parseCsg("(a + b) * (c + d) * (e + f)", kNames), 7);
    FAIL() << "no bound";
  } catch (const std::length_error& e) {
    EXPECT_STREQ(e.what(), "the sum of products grows past 7 products");
  }
}

TEST(Csg, MalformedTreesAreRefused) {
  CsgTree tree;
  EXPECT_THROW(normalize(tree), std::invalid_argument);  // no root
  tree.nodes = {{CsgTree::Kind::Union, -1, 0, 1}, {CsgTree::Kind::Primitive, 0}};
  tree.root = 0;
  EXPECT_THROW(normalize(tree), std::invalid_argument);  // an operand after its operation
  EXPECT_THROW(contains(parseCsg("a - c", kNames), {true, false}), std::invalid_argument);
}

TEST(Csg, RayCastTwoCubesFaceOn) {
  // A: the cube [-1, 1]^3. B: a cube of half-size 0.5 at z = 1, its front at 1.5 towards the eye and
  // its back at 0.5, inside A. Pixel (21, 18) looks through both; pixel (21, 13) passes above B (its
  // ray is at y ~ 0.69 at z = 1.5) and meets A's front at z = 1, y ~ 0.79.
  const Mesh a = makeCube(1.0f), b = makeCube(0.5f);
  const std::vector<CsgPrimitive> prims = {{&a, glm::mat4(1)},
                                           {&b, glm::translate(glm::mat4(1), glm::vec3(0, 0, 1))}};
  const auto at = [](const CsgImage&, int x, int y) { return static_cast<std::size_t>(y * 41 + x); };
  const std::vector<std::string> names = {"A", "B"};
  struct Case {
    const char* text;
    int through, beside;              // primitive seen through both, beside B
    float depthThrough, depthBeside;  // the plane z it is seen on
  };
  for (const Case& c : {Case{"A + B", 1, 0, 1.5f, 1.0f}, Case{"A * B", 0, kNoSurface, 1.0f, 0.0f},
                        Case{"A - B", 1, 0, 0.5f, 1.0f}, Case{"B - A", 1, kNoSurface, 1.5f, 0.0f}}) {
    const CsgImage im = rayCastCsg(prims, parseCsg(c.text, names), frontView(), {41, 41});
    EXPECT_EQ(im.primitive[at(im, 21, 18)], c.through) << c.text;
    EXPECT_NEAR(im.depth[at(im, 21, 18)], depthOnPlane(21, 18, c.depthThrough), 1e-6f) << c.text;
    EXPECT_EQ(im.primitive[at(im, 21, 13)], c.beside) << c.text;
    if (c.beside >= 0) {
      EXPECT_NEAR(im.depth[at(im, 21, 13)], depthOnPlane(21, 13, c.depthBeside), 1e-6f) << c.text;
    }
    EXPECT_EQ(im.primitive[at(im, 0, 0)], kNoSurface) << c.text;
    EXPECT_EQ(im.depth[at(im, 0, 0)], 1.0f) << c.text;
  }
  // The near plane (z = 4.5) inside A and inside B (z from 4.3 to 5.3): a union starts inside;
  // A - B, with the near plane in B's hole, starts outside and meets B's back face at z = 4.3.
  const std::vector<CsgPrimitive> around = {{&a, glm::scale(glm::mat4(1), glm::vec3(10.0f))},
                                            {&b, glm::translate(glm::mat4(1), glm::vec3(0, 0, 4.8f))}};
  const CsgImage inside = rayCastCsg(around, parseCsg("A + B", names), frontView(), {41, 41});
  EXPECT_EQ(inside.primitive[at(inside, 21, 18)], kNearPlane);
  EXPECT_EQ(inside.depth[at(inside, 21, 18)], 0.0f);
  const CsgImage hole = rayCastCsg(around, parseCsg("A - B", names), frontView(), {41, 41});
  EXPECT_EQ(hole.primitive[at(hole, 21, 20)], 1);
  EXPECT_NEAR(hole.depth[at(hole, 21, 20)], depthOnPlane(21, 20, 4.3f), 1e-6f);
  EXPECT_THROW(rayCastCsg({prims[0]}, parseCsg("A - B", names), frontView(), {41, 41}),
               std::invalid_argument);
  // A matrix without an inverse casts no ray: refused, not an empty picture.
  glm::mat4 singular = frontView();
  for (int c = 0; c < 4; ++c) singular[c][2] = singular[c][3];  // clip z is clip w
  EXPECT_THROW(rayCastCsg(prims, parseCsg("A - B", names), singular, {41, 41}), std::invalid_argument);
}

TEST(Csg, RayCastConcavePrimitiveHasTwoIntervals) {
  // A torus seen along its axis through the ring: the ray enters and leaves it twice. Its tube
  // (major 1, minor 0.3) lies between radii 0.7 and 1.3; at the centre the ray passes through the
  // hole, at radius 1 it meets the tube's top.
  const Mesh torus = makeTorus(1.0f, 0.3f, 48, 24);
  const glm::mat4 faceOn = glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(1, 0, 0));
  const std::vector<std::string> names = {"A"};
  const CsgImage im = rayCastCsg({{&torus, faceOn}}, parseCsg("A", names), frontView(), {41, 41});
  EXPECT_EQ(im.primitive[20 * 41 + 20], kNoSurface);  // the hole
  int seen = 0;
  for (int v : im.primitive) seen += v == 0;
  EXPECT_GT(seen, 100);
}

TEST(Csg, CompareForgivesOnlyEdges) {
  CsgImage expected;
  expected.size = {4, 1};
  expected.depth = {0.5f, 0.5f, 0.5f, 1.0f};
  expected.primitive = {0, 0, 0, kNoSurface};
  expected.sharedWith.assign(4, {});
  // Pixel 0 wrong in depth, off an edge; pixel 2 wrong in primitive, on an edge.
  const std::vector<bool> edges = {false, false, true, true};
  const CsgReport r = compareCsg(expected, {0.6f, 0.5f, 1.0f, 1.0f}, {0, 0, kNoSurface, kNoSurface}, edges, 1e-3f, 0.0f);
  EXPECT_EQ(r.depthDisagreements, 1u);
  EXPECT_EQ(r.primitiveDisagreements, 1u);
  EXPECT_EQ(r.onEdges, 1u);
  EXPECT_EQ(r.edgePixels, 2u);
  EXPECT_FALSE(r.passed());
  EXPECT_NEAR(r.largestDepthError, 0.1f, 1e-6f);
  EXPECT_TRUE(compareCsg(expected, expected.depth, expected.primitive, edges, 0.0f, 0.0f).passed());
  // A depth jump within one primitive is no edge by itself: only the geometry's edges forgive.
  expected.depth = {0.5f, 0.51f, 0.51f, 1.0f};
  EXPECT_FALSE(compareCsg(expected, {0.51f, 0.51f, 0.51f, 1.0f}, expected.primitive, edges, 1e-3f, 0.0f).passed());
  // The tolerance grows with the surface's slope over the snapping: 0.01 per pixel, half a pixel.
  EXPECT_TRUE(compareCsg(expected, {0.504f, 0.51f, 0.51f, 1.0f}, expected.primitive, edges, 0.0f, 0.5f).passed());
  // A shared surface may show any primitive lying in it.
  expected.sharedWith[1] = {3};
  EXPECT_TRUE(compareCsg(expected, expected.depth, {0, 3, 0, kNoSurface}, edges, 0.0f, 0.0f).passed());
  EXPECT_FALSE(compareCsg(expected, expected.depth, {0, 2, 0, kNoSurface}, edges, 0.0f, 0.0f).passed());
  EXPECT_THROW(compareCsg(expected, {0.5f}, {0}, {false}, 0.0f, 0.0f), std::invalid_argument);
}

TEST(Csg, EdgesAreTheGeometrys) {
  // A cube face on, 41x41: its silhouette is the square's outline, and no pixel inside the face
  // is an edge (the face's diagonal is no edge: both its triangles turn to the eye).
  const Mesh cube = makeCube(1.0f);
  const std::vector<CsgPrimitive> one = {{&cube, glm::mat4(1.0f)}};
  const std::vector<bool> edges = csgEdgePixels(one, frontView(), {41, 41}, 1.0f / 256.0f);
  const CsgImage im = rayCastCsg(one, parseCsg("A", {"A"}), frontView(), {41, 41});
  std::size_t marked = 0;
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * 41 + x);
      marked += edges[i];
      // A pixel whose 3x3 neighbourhood all sees the cube, or all misses it, is no edge.
      bool same = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, 40), ny = std::clamp(y + dy, 0, 40);
          same = same && im.primitive[static_cast<std::size_t>(ny * 41 + nx)] == im.primitive[i];
        }
      if (same) {
        EXPECT_FALSE(edges[i]) << x << ", " << y;
      }
    }
  EXPECT_GT(marked, 4u * 10u);
  // Two cubes crossing: the curve where their faces cross is an edge, inside both outlines.
  const Mesh other = makeCube(1.0f);
  const std::vector<CsgPrimitive> two = {{&cube, glm::mat4(1.0f)},
                                         {&other, glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 1, 0))}};
  const std::vector<bool> crossing = csgEdgePixels(two, frontView(), {41, 41}, 1.0f / 256.0f);
  std::size_t more = 0;
  for (std::size_t i = 0; i < crossing.size(); ++i) more += crossing[i] && !edges[i];
  EXPECT_GT(more, 0u);
  EXPECT_THROW(csgEdgePixels(one, frontView(), {41, 41}, -1.0f), std::invalid_argument);
}

TEST(Csg, SubtractionSequencesHoldEveryOrdering) {
  for (int n = 0; n <= 7; ++n) {
    const std::vector<int> sequence = subtractionSequence(n);
    EXPECT_EQ(sequence.size(), static_cast<std::size_t>(n == 0 ? 0 : n * (n - 1) + 1)) << n;
    EXPECT_TRUE(containsEveryOrdering(sequence, n)) << n;
    if (n >= 2) {  // one entry fewer and some ordering is missing
      std::vector<int> shorter(sequence.begin(), sequence.end() - 1);
      EXPECT_FALSE(containsEveryOrdering(shorter, n)) << n;
    }
  }
  EXPECT_EQ(subtractionSequence(3), std::vector<int>({0, 1, 2, 1, 0, 1, 2}));
  EXPECT_THROW(subtractionSequence(-1), std::invalid_argument);
  EXPECT_THROW(containsEveryOrdering({}, 9), std::invalid_argument);
}

TEST(Csg, ShortestOrderingSequencesAreTheKnownMinimum) {
  // By exhaustive search: 1, 3, 7, 12 for n = 1..4. From n = 3 on that is (n - 1)^2 + 3, which the
  // simple sequence's n(n - 1) + 1 meets at n = 3 and exceeds from n = 4 on (13 against 12).
  const std::size_t found[] = {0, shortestOrderingSequence(1), shortestOrderingSequence(2),
                               shortestOrderingSequence(3), shortestOrderingSequence(4)};
  EXPECT_EQ(found[1], 1u);
  EXPECT_EQ(found[2], 3u);
  for (int n = 3; n <= 4; ++n) EXPECT_EQ(found[n], static_cast<std::size_t>((n - 1) * (n - 1) + 3)) << n;
  EXPECT_EQ(subtractionSequence(3).size(), found[3]);
  EXPECT_EQ(subtractionSequence(4).size(), found[4] + 1);
  EXPECT_THROW(shortestOrderingSequence(5), std::invalid_argument);
}
