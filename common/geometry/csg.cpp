#include "geometry/csg.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "geometry/raycast.h"

namespace stencil {

namespace {

// Children before parents: every operation's operands have smaller indices, so one pass in
// index order visits operands first (no recursion, however long a chain of operations is).
void checkTree(const CsgTree& tree) {
  if (tree.root < 0 || static_cast<std::size_t>(tree.root) >= tree.nodes.size())
    throw std::invalid_argument("CSG tree: no root");
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const CsgTree::Node& n = tree.nodes[i];
    if (n.kind == CsgTree::Kind::Primitive) {
      if (n.primitive < 0) throw std::invalid_argument("CSG tree: a primitive without an index");
    } else if (n.left < 0 || n.right < 0 || static_cast<std::size_t>(n.left) >= i ||
               static_cast<std::size_t>(n.right) >= i) {
      throw std::invalid_argument("CSG tree: an operand that does not come before its operation");
    }
  }
}

class Parser {
 public:
  Parser(std::string_view text, const std::vector<std::string>& names) : text_(text), names_(names) {}

  CsgTree parse() {
    tree_.root = expression(0);
    skipSpace();
    if (at_ < text_.size()) fail(at_, std::string("unexpected '") + text_[at_] + "'");
    return tree_;
  }

 private:
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    throw std::invalid_argument("column " + std::to_string(column + 1) + ": " + what);
  }
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  int add(CsgTree::Kind kind, int left, int right, int primitive = -1) {
    tree_.nodes.push_back({kind, primitive, left, right});
    return static_cast<int>(tree_.nodes.size()) - 1;
  }
  int expression(std::size_t depth) {
    int left = term(depth);
    for (;;) {
      skipSpace();
      if (at_ >= text_.size() || (text_[at_] != '+' && text_[at_] != '-')) return left;
      const auto kind = text_[at_++] == '+' ? CsgTree::Kind::Union : CsgTree::Kind::Difference;
      left = add(kind, left, term(depth));
    }
  }
  int term(std::size_t depth) {
    int left = factor(depth);
    for (;;) {
      skipSpace();
      if (at_ >= text_.size() || text_[at_] != '*') return left;
      ++at_;
      left = add(CsgTree::Kind::Intersection, left, factor(depth));
    }
  }
  int factor(std::size_t depth) {
    skipSpace();
    if (at_ >= text_.size()) fail(at_, "a primitive or '(' expected, the text ends");
    const char c = text_[at_];
    if (c == '(') {
      if (depth + 1 > kMaxCsgDepth)
        fail(at_, "parentheses nested deeper than " + std::to_string(kMaxCsgDepth));
      const std::size_t open = at_++;
      const int inner = expression(depth + 1);
      skipSpace();
      if (at_ >= text_.size() || text_[at_] != ')') fail(open, "'(' is never closed");
      ++at_;
      return inner;
    }
    if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_'))
      fail(at_, std::string("a primitive or '(' expected, got '") + c + "'");
    const std::size_t start = at_;
    while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_'))
      ++at_;
    const std::string name(text_.substr(start, at_ - start));
    const auto found = std::find(names_.begin(), names_.end(), name);
    if (found == names_.end()) fail(start, "no primitive named '" + name + "'");
    return add(CsgTree::Kind::Primitive, -1, -1, static_cast<int>(found - names_.begin()));
  }

  std::string_view text_;
  const std::vector<std::string>& names_;
  std::size_t at_ = 0;
  CsgTree tree_;
};

std::vector<int> merged(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

CsgProduct both(const CsgProduct& a, const CsgProduct& b) {
  return {merged(a.intersected, b.intersected), merged(a.subtracted, b.subtracted)};
}

bool empty(const CsgProduct& p) {
  std::vector<int> common;
  std::set_intersection(p.intersected.begin(), p.intersected.end(), p.subtracted.begin(), p.subtracted.end(),
                        std::back_inserter(common));
  return !common.empty();
}

[[noreturn]] void tooMany(std::size_t maxProducts) {
  throw std::length_error("the sum of products grows past " + std::to_string(maxProducts) + " products");
}

bool inside(const std::vector<bool>& in, int primitive) {
  if (static_cast<std::size_t>(primitive) >= in.size())
    throw std::invalid_argument("CSG membership: primitive " + std::to_string(primitive) + " not given");
  return in[static_cast<std::size_t>(primitive)];
}

}  // namespace

std::size_t CsgTree::primitiveCount() const {
  return static_cast<std::size_t>(
      std::count_if(nodes.begin(), nodes.end(), [](const Node& n) { return n.kind == Kind::Primitive; }));
}

CsgTree parseCsg(std::string_view text, const std::vector<std::string>& names) {
  return Parser(text, names).parse();
}

std::string csgText(const CsgTree& tree, const std::vector<std::string>& names) {
  checkTree(tree);
  std::vector<std::string> text(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const CsgTree::Node& n = tree.nodes[i];
    if (n.kind == CsgTree::Kind::Primitive) {
      text[i] = static_cast<std::size_t>(n.primitive) < names.size()
                    ? names[static_cast<std::size_t>(n.primitive)]
                    : "#" + std::to_string(n.primitive);
      continue;
    }
    const char* op = n.kind == CsgTree::Kind::Union          ? " + "
                     : n.kind == CsgTree::Kind::Intersection ? " * "
                                                             : " - ";
    text[i] =
        "(" + text[static_cast<std::size_t>(n.left)] + op + text[static_cast<std::size_t>(n.right)] + ")";
  }
  return text[static_cast<std::size_t>(tree.root)];
}

std::size_t SumOfProducts::literals() const {
  std::size_t n = 0;
  for (const CsgProduct& p : products) n += p.size();
  return n;
}

SumOfProducts normalize(const CsgTree& tree, std::size_t maxProducts) {
  checkTree(tree);
  std::vector<std::vector<CsgProduct>> sop(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const CsgTree::Node& n = tree.nodes[i];
    std::vector<CsgProduct>& out = sop[i];
    if (n.kind == CsgTree::Kind::Primitive) {
      out.push_back({{n.primitive}, {}});
      continue;
    }
    const std::vector<CsgProduct>&left = sop[static_cast<std::size_t>(n.left)],
          &right = sop[static_cast<std::size_t>(n.right)];
    switch (n.kind) {
      case CsgTree::Kind::Union:  // x + y: both lists
        if (left.size() + right.size() > maxProducts) tooMany(maxProducts);
        out = left;
        out.insert(out.end(), right.begin(), right.end());
        break;
      case CsgTree::Kind::Intersection:  // (a + b)(c + d) = ac + ad + bc + bd
        if (left.size() * right.size() > maxProducts) tooMany(maxProducts);
        for (const CsgProduct& a : left)
          for (const CsgProduct& b : right) out.push_back(both(a, b));
        break;
      case CsgTree::Kind::Difference: {
        // x - (q1 + q2 + ...) = x ~q1 ~q2 ..., and ~(a b ~c) = ~a + ~b + c (De Morgan): each
        // product of x meets one literal of each complemented product.
        out = left;
        for (const CsgProduct& q : right) {
          std::vector<CsgProduct> complement;
          for (int a : q.intersected) complement.push_back({{}, {a}});
          for (int c : q.subtracted) complement.push_back({{c}, {}});
          if (out.size() * complement.size() > maxProducts) tooMany(maxProducts);
          std::vector<CsgProduct> next;
          for (const CsgProduct& p : out)
            for (const CsgProduct& l : complement) next.push_back(both(p, l));
          out = std::move(next);
        }
        break;
      }
      case CsgTree::Kind::Primitive: break;
    }
    // Operands are no longer needed once their parent is built (each node has one parent).
    std::vector<CsgProduct>().swap(sop[static_cast<std::size_t>(n.left)]);
    std::vector<CsgProduct>().swap(sop[static_cast<std::size_t>(n.right)]);
  }
  SumOfProducts result;
  for (CsgProduct& p : sop[static_cast<std::size_t>(tree.root)]) {
    ++result.productsBeforePruning;
    result.literalsBeforePruning += p.size();
    if (!empty(p)) result.products.push_back(std::move(p));
  }
  return result;
}

bool contains(const CsgTree& tree, const std::vector<bool>& in) {
  checkTree(tree);
  std::vector<char> value(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    const CsgTree::Node& n = tree.nodes[i];
    if (n.kind == CsgTree::Kind::Primitive) {
      value[i] = inside(in, n.primitive);
      continue;
    }
    const bool l = value[static_cast<std::size_t>(n.left)], r = value[static_cast<std::size_t>(n.right)];
    value[i] = n.kind == CsgTree::Kind::Union          ? (l || r)
               : n.kind == CsgTree::Kind::Intersection ? (l && r)
                                                       : (l && !r);
  }
  return value[static_cast<std::size_t>(tree.root)];
}

bool contains(const SumOfProducts& sop, const std::vector<bool>& in) {
  for (const CsgProduct& p : sop.products) {
    bool all = true;
    for (int a : p.intersected) all = all && inside(in, a);
    for (int s : p.subtracted) all = all && !inside(in, s);
    if (all) return true;
  }
  return false;
}

std::vector<int> subtractionSequence(int n) {
  if (n < 0 || n > 1000) throw std::invalid_argument("subtractionSequence: n must be within 0..1000");
  std::vector<int> sequence;
  for (int i = 0; i < n; ++i) sequence.push_back(i);  // the first run, up
  for (int run = 1; run < n; ++run) {
    // Each further run turns at the last entry and covers the other n - 1.
    const bool down = run % 2 == 1;
    const int from = sequence.back();
    for (int k = 1; k < n; ++k) sequence.push_back(down ? from - k : from + k);
  }
  return sequence;
}

bool containsEveryOrdering(const std::vector<int>& sequence, int n) {
  if (n < 0 || n > 8) throw std::invalid_argument("containsEveryOrdering: n must be within 0..8");
  std::vector<int> ordering(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ordering[static_cast<std::size_t>(i)] = i;
  do {
    std::size_t at = 0;
    for (int v : sequence)
      if (at < ordering.size() && v == ordering[at]) ++at;
    if (at < ordering.size()) return false;
  } while (std::next_permutation(ordering.begin(), ordering.end()));
  return true;
}

std::size_t shortestOrderingSequence(int n) {
  if (n < 0 || n > 4) throw std::invalid_argument("shortestOrderingSequence: n must be within 0..4");
  if (n <= 1) return static_cast<std::size_t>(n);
  for (std::size_t length = static_cast<std::size_t>(n);; ++length) {
    // Every sequence of this length over 0..n-1, as the digits of a counter in base n.
    std::vector<int> sequence(length, 0);
    for (;;) {
      if (containsEveryOrdering(sequence, n)) return length;
      std::size_t digit = 0;
      while (digit < length && ++sequence[digit] == n) sequence[digit++] = 0;
      if (digit == length) break;
    }
  }
}

CsgImage rayCastCsg(const std::vector<CsgPrimitive>& primitives, const CsgTree& tree,
                    const glm::mat4& viewProjection, glm::ivec2 size) {
  checkTree(tree);
  for (const CsgTree::Node& n : tree.nodes)
    if (n.kind == CsgTree::Kind::Primitive && static_cast<std::size_t>(n.primitive) >= primitives.size())
      throw std::invalid_argument("rayCastCsg: the tree names primitive " + std::to_string(n.primitive) +
                                  " of " + std::to_string(primitives.size()));
  RayScene scene;
  for (const CsgPrimitive& p : primitives) {
    if (!p.mesh) throw std::invalid_argument("rayCastCsg: a primitive without a mesh");
    scene.add(*p.mesh, p.model);
  }
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProjection));
  CsgImage image;
  image.size = size;
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  image.depth.assign(n, 1.0f);
  image.primitive.assign(n, kNoSurface);
  struct Event {
    float t;
    int primitive;
    int step;  // +1 entering (a front face), -1 leaving
  };
  std::vector<Event> events;
  std::vector<int> winding(primitives.size());
  std::vector<bool> in(primitives.size());
  for (int py = 0; py < size.y; ++py)
    for (int px = 0; px < size.x; ++px) {
      // From the near plane (t = 0) on; t grows with depth.
      const Ray ray = cameraRay(inverse, size, px, py).ray;
      // The whole line: what it crosses before the near plane says which primitives hold the
      // near plane's point (a closed surface is crossed as often in as out along a line).
      events.clear();
      for (const RayHit& hit : scene.allHits(ray, -INFINITY, INFINITY))
        events.push_back({hit.t, hit.object, glm::dot(hit.normal, ray.direction) < 0.0f ? 1 : -1});
      std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
      std::fill(winding.begin(), winding.end(), 0);
      std::size_t e = 0;
      for (; e < events.size() && events[e].t <= 0.0f; ++e)
        winding[static_cast<std::size_t>(events[e].primitive)] += events[e].step;
      for (std::size_t i = 0; i < in.size(); ++i) in[i] = winding[i] > 0;
      const std::size_t pixel =
          static_cast<std::size_t>(py) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(px);
      if (contains(tree, in)) {
        image.depth[pixel] = 0.0f;
        image.primitive[pixel] = kNearPlane;
        continue;
      }
      while (e < events.size()) {
        // Crossings at the same t (an edge shared by two triangles, coincident faces) together.
        const float t = events[e].t;
        const int first = events[e].primitive;
        for (; e < events.size() && events[e].t == t; ++e) {
          const auto p = static_cast<std::size_t>(events[e].primitive);
          winding[p] += events[e].step;
          in[p] = winding[p] > 0;
        }
        const glm::vec4 clip = viewProjection * glm::vec4(ray.origin + t * ray.direction, 1.0f);
        if (!(clip.w > 0.0f && clip.z <= clip.w)) break;  // past the far plane
        if (contains(tree, in)) {
          image.depth[pixel] = 0.5f * clip.z / clip.w + 0.5f;
          image.primitive[pixel] = first;
          break;
        }
      }
    }
  return image;
}

CsgReport compareCsg(const CsgImage& expected, const std::vector<float>& depth,
                     const std::vector<int>& primitive, float depthTolerance, float edgeDepthJump) {
  const glm::ivec2 size = expected.size;
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  if (expected.depth.size() != n || expected.primitive.size() != n || depth.size() != n ||
      primitive.size() != n)
    throw std::invalid_argument("compareCsg: the images do not match the size");
  CsgReport report;
  report.pixels = n;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
      bool edge = false;
      for (int dy = -1; dy <= 1 && !edge; ++dy)
        for (int dx = -1; dx <= 1 && !edge; ++dx) {
          const int nx = std::clamp(x + dx, 0, size.x - 1), ny = std::clamp(y + dy, 0, size.y - 1);
          const std::size_t j =
              static_cast<std::size_t>(ny) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(nx);
          edge = expected.primitive[j] != expected.primitive[i] ||
                 std::abs(expected.depth[j] - expected.depth[i]) > edgeDepthJump;
        }
      const bool samePrimitive = primitive[i] == expected.primitive[i];
      const float error = std::abs(depth[i] - expected.depth[i]);
      if (samePrimitive && !edge && expected.primitive[i] >= 0)
        report.largestDepthError = std::max(report.largestDepthError, error);
      if (!samePrimitive) {
        ++report.primitiveDisagreements;
      } else if (!(error <= depthTolerance)) {
        ++report.depthDisagreements;
      } else {
        continue;
      }
      report.onEdges += edge;
    }
  return report;
}

}  // namespace stencil
