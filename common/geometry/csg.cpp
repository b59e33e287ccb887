#include "geometry/csg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
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

bool isCsgName(std::string_view name) {
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  return !name.empty() && letter(name.front()) &&
         std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
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
  // A singular matrix (a near plane lost to rounding) would cast no ray at all, and an empty
  // picture would agree with it.
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(inverse[c][r])) throw std::invalid_argument("rayCastCsg: the view-projection matrix has no inverse");
  CsgImage image;
  image.size = size;
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  image.depth.assign(n, 1.0f);
  image.primitive.assign(n, kNoSurface);
  image.sharedWith.assign(n, {});
  struct Event {
    float t;
    int primitive;
    int step;  // +1 entering (a front face), -1 leaving
    glm::vec3 normal;
  };
  // Whether b's hit lies in a's face's plane and b's face is parallel to a's: coincident faces.
  // Within float rounding of the points' distances from the world's origin (the transformed
  // corners carry that much), 64 ulps of it.
  const auto coplanar = [](const Ray& ray, const Event& a, const Event& b) {
    const glm::vec3 pa = ray.origin + a.t * ray.direction, pb = ray.origin + b.t * ray.direction;
    const float scale = std::max({std::abs(pa.x), std::abs(pa.y), std::abs(pa.z), std::abs(pb.x), std::abs(pb.y),
                                  std::abs(pb.z), std::numeric_limits<float>::min()});
    const float ulps = 64.0f * std::numeric_limits<float>::epsilon();
    return glm::length(glm::cross(a.normal, b.normal)) <= 1e-4f &&
           std::abs(glm::dot(a.normal, pb - pa)) <= ulps * scale;
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
        events.push_back({hit.t, hit.object, glm::dot(hit.normal, ray.direction) < 0.0f ? 1 : -1, hit.normal});
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
        // Crossings at the same t (an edge shared by two triangles), or on coincident faces,
        // together.
        const std::size_t head = e;
        const float t = events[e].t;
        const int first = events[e].primitive;
        std::vector<int> sharers;
        for (; e < events.size() && (events[e].t == t || coplanar(ray, events[head], events[e])); ++e) {
          const auto p = static_cast<std::size_t>(events[e].primitive);
          winding[p] += events[e].step;
          in[p] = winding[p] > 0;
          if (events[e].primitive != first &&
              std::find(sharers.begin(), sharers.end(), events[e].primitive) == sharers.end())
            sharers.push_back(events[e].primitive);
        }
        const glm::vec4 clip = viewProjection * glm::vec4(ray.origin + t * ray.direction, 1.0f);
        if (!(clip.w > 0.0f && clip.z <= clip.w)) break;  // past the far plane
        if (contains(tree, in)) {
          image.depth[pixel] = 0.5f * clip.z / clip.w + 0.5f;
          image.primitive[pixel] = first;
          if (!sharers.empty()) image.sharedWith[pixel] = std::move(sharers);
          break;
        }
      }
    }
  return image;
}

namespace {

// Marks the pixels (top row first) whose square grown by m is crossed by the window-space segment
// a-b (x right, y up, pixel (c, r) covering [c, c + 1] x [r, r + 1] counted from the bottom).
void markSegment(std::vector<bool>& marks, glm::ivec2 size, glm::dvec2 a, glm::dvec2 b, double m) {
  if (a.x > b.x) std::swap(a, b);
  const int c0 = std::max(0, static_cast<int>(std::floor(a.x - m))),
            c1 = std::min(size.x - 1, static_cast<int>(std::floor(b.x + m)));
  for (int c = c0; c <= c1; ++c) {
    // The part of the segment over the column grown by m, and its y range grown by m.
    const double x0 = std::max(a.x, c - m), x1 = std::min(b.x, c + 1 + m);
    if (x0 > x1) continue;
    const auto yAt = [&](double x) { return b.x == a.x ? a.y : a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x); };
    double y0 = b.x == a.x ? std::min(a.y, b.y) : yAt(x0), y1 = b.x == a.x ? std::max(a.y, b.y) : yAt(x1);
    if (y0 > y1) std::swap(y0, y1);
    const int r0 = std::max(0, static_cast<int>(std::floor(y0 - m))),
              r1 = std::min(size.y - 1, static_cast<int>(std::floor(y1 + m)));
    for (int r = r0; r <= r1; ++r)
      marks[static_cast<std::size_t>(size.y - 1 - r) * static_cast<std::size_t>(size.x) +
            static_cast<std::size_t>(c)] = true;
  }
}

// The segment between world points p and q clipped to the view volume's near and far planes
// (GL's clip conventions), marked in window space.
void markWorldSegment(std::vector<bool>& marks, glm::ivec2 size, const glm::dmat4& vp, const glm::dvec3& p,
                      const glm::dvec3& q, double m) {
  glm::dvec4 a = vp * glm::dvec4(p, 1.0), b = vp * glm::dvec4(q, 1.0);
  // Near: z + w >= 0; far: w - z >= 0 (a far plane at infinity leaves every point in front of it).
  for (int plane = 0; plane < 2; ++plane) {
    const double da = plane == 0 ? a.z + a.w : a.w - a.z, db = plane == 0 ? b.z + b.w : b.w - b.z;
    if (da < 0 && db < 0) return;
    if (da < 0) a = a + (b - a) * (da / (da - db));
    else if (db < 0) b = b + (a - b) * (db / (db - da));
  }
  if (a.w <= 0 || b.w <= 0) return;
  const auto window = [&](const glm::dvec4& c) {
    return glm::dvec2((c.x / c.w * 0.5 + 0.5) * size.x, (c.y / c.w * 0.5 + 0.5) * size.y);
  };
  markSegment(marks, size, window(a), window(b), m);
}

// The segment where two triangles cross (each one's corners on both sides of the other's plane),
// if any; coplanar ones are left to the caller.
bool triangleCrossing(const std::array<glm::dvec3, 3>& t, const std::array<glm::dvec3, 3>& u, glm::dvec3& from,
                      glm::dvec3& to) {
  // Where t's edges cross u's plane, and u's edges t's: two intervals along the common line.
  const auto cuts = [](const std::array<glm::dvec3, 3>& x, const std::array<glm::dvec3, 3>& plane,
                       std::vector<glm::dvec3>& out) {
    const glm::dvec3 n = glm::cross(plane[1] - plane[0], plane[2] - plane[0]);
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = glm::dot(n, x[static_cast<std::size_t>(i)] - plane[0]);
    if ((d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0)) return false;
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) return false;  // coplanar
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const glm::dvec3 &a = x[static_cast<std::size_t>(i)], &b = x[static_cast<std::size_t>(j)];
      if (d[i] == 0) out.push_back(a);
      if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) out.push_back(a + (b - a) * (d[i] / (d[i] - d[j])));
    }
    return out.size() >= 1;
  };
  std::vector<glm::dvec3> a, b;
  if (!cuts(t, u, a) || !cuts(u, t, b)) return false;
  const glm::dvec3 dir = glm::cross(t[1] - t[0], t[2] - t[0]), dir2 = glm::cross(u[1] - u[0], u[2] - u[0]);
  const glm::dvec3 line = glm::cross(dir, dir2);
  if (glm::dot(line, line) == 0.0) return false;
  const auto range = [&](const std::vector<glm::dvec3>& pts) {
    double lo = INFINITY, hi = -INFINITY;
    for (const glm::dvec3& p : pts) {
      lo = std::min(lo, glm::dot(line, p));
      hi = std::max(hi, glm::dot(line, p));
    }
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = range(a);
  const auto [blo, bhi] = range(b);
  const double lo = std::max(alo, blo), hi = std::min(ahi, bhi);
  if (lo > hi) return false;
  // The points of t's cut at lo and hi (its cut is a segment along the line).
  const auto at = [&](double s) {
    glm::dvec3 p0 = a.front(), p1 = a.front();
    for (const glm::dvec3& p : a) {
      if (glm::dot(line, p) < glm::dot(line, p0)) p0 = p;
      if (glm::dot(line, p) > glm::dot(line, p1)) p1 = p;
    }
    const double s0 = glm::dot(line, p0), s1 = glm::dot(line, p1);
    return s1 == s0 ? p0 : p0 + (p1 - p0) * ((s - s0) / (s1 - s0));
  };
  from = at(lo);
  to = at(hi);
  return true;
}

}  // namespace

std::vector<bool> csgEdgePixels(const std::vector<CsgPrimitive>& primitives, const glm::mat4& viewProjection,
                                glm::ivec2 size, float margin) {
  if (!(margin >= 0.0f)) throw std::invalid_argument("csgEdgePixels: the margin must be 0 or more");
  std::vector<bool> marks(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y), false);
  const glm::dmat4 vp(viewProjection);
  // The eye: the point clip space sends to (0, 0, z, 0), where the view's lines meet; for an
  // orthographic view that is a direction (w = 0), along which the faces' turn is judged.
  const glm::dmat4 inverse = glm::inverse(vp);
  const glm::dvec4 eye = [&] {
    const glm::dvec4 p = inverse * glm::dvec4(0, 0, 1, 0);
    if (std::abs(p.w) <= 1e-12 * glm::length(glm::dvec3(p))) return glm::dvec4(-glm::normalize(glm::dvec3(p)), 0.0);
    return glm::dvec4(glm::dvec3(p) / p.w, 1.0);
  }();
  struct Placed {
    std::vector<std::array<glm::dvec3, 3>> triangles;
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
  };
  std::vector<Placed> placed(primitives.size());
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const CsgPrimitive& p = primitives[i];
    if (!p.mesh) throw std::invalid_argument("csgEdgePixels: a primitive without a mesh");
    std::vector<glm::vec3> world(p.mesh->positions.size());
    for (std::size_t v = 0; v < world.size(); ++v) world[v] = glm::vec3(p.model * glm::vec4(p.mesh->positions[v], 1.0f));
    // Facing of each triangle: +1 turned to the eye, -1 away, 0 edge-on within rounding.
    std::map<std::pair<std::array<float, 3>, std::array<float, 3>>, int> edgeFacing;  // bit 1 front, 2 back, 4 edge-on
    const bool mirrored = glm::determinant(glm::mat3(p.model)) < 0.0f;
    const auto key = [](const glm::vec3& v) { return std::array<float, 3>{v.x, v.y, v.z}; };
    Placed& out = placed[i];
    for (std::size_t k = 0; k + 2 < p.mesh->indices.size(); k += 3) {
      std::array<glm::vec3, 3> c;
      for (int j = 0; j < 3; ++j) c[static_cast<std::size_t>(j)] = world[p.mesh->indices[k + static_cast<std::size_t>(j)]];
      std::array<glm::dvec3, 3> d{glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2])};
      out.triangles.push_back(d);
      for (const glm::dvec3& v : d) {
        out.lo = glm::min(out.lo, v);
        out.hi = glm::max(out.hi, v);
      }
      glm::dvec3 n = glm::cross(d[1] - d[0], d[2] - d[0]);
      if (mirrored) n = -n;
      const glm::dvec3 toEye = eye.w == 0 ? glm::dvec3(eye) : glm::dvec3(eye) - d[0];
      const double f = glm::dot(n, toEye);
      const double scale = glm::length(n) * glm::length(toEye);
      const int facing = std::abs(f) <= 1e-6 * scale ? 4 : f > 0 ? 1 : 2;
      for (int j = 0; j < 3; ++j) {
        std::array<float, 3> a = key(c[static_cast<std::size_t>(j)]), b = key(c[static_cast<std::size_t>((j + 1) % 3)]);
        if (b < a) std::swap(a, b);
        edgeFacing[{a, b}] |= facing | (edgeFacing.count({a, b}) ? 8 : 0);
      }
      // Where the face crosses the near and the far plane.
      for (int plane = 0; plane < 2; ++plane) {
        std::vector<glm::dvec3> cut;
        double dist[3];
        for (int j = 0; j < 3; ++j) {
          const glm::dvec4 clip = vp * glm::dvec4(d[static_cast<std::size_t>(j)], 1.0);
          dist[j] = plane == 0 ? clip.z + clip.w : clip.w - clip.z;
        }
        for (int j = 0; j < 3; ++j) {
          const int l = (j + 1) % 3;
          if ((dist[j] < 0) != (dist[l] < 0))
            cut.push_back(d[static_cast<std::size_t>(j)] +
                          (d[static_cast<std::size_t>(l)] - d[static_cast<std::size_t>(j)]) * (dist[j] / (dist[j] - dist[l])));
        }
        if (cut.size() == 2) {
          const glm::dvec4 a = vp * glm::dvec4(cut[0], 1.0), b = vp * glm::dvec4(cut[1], 1.0);
          const auto window = [&](const glm::dvec4& q) {
            return glm::dvec2((q.x / q.w * 0.5 + 0.5) * size.x, (q.y / q.w * 0.5 + 0.5) * size.y);
          };
          if (a.w > 0 && b.w > 0) markSegment(marks, size, window(a), window(b), margin);
        }
      }
    }
    // Possible silhouette edges: a face on each side turned differently, an edge-on face, or a
    // border (an edge of one face only).
    for (const auto& [edge, bits] : edgeFacing) {
      const bool shared = bits & 8;
      const bool silhouette = (bits & 4) || ((bits & 1) && (bits & 2)) || !shared;
      if (!silhouette) continue;
      markWorldSegment(marks, size, vp,
                       glm::dvec3(edge.first[0], edge.first[1], edge.first[2]),
                       glm::dvec3(edge.second[0], edge.second[1], edge.second[2]), margin);
    }
  }
  // Where two primitives' faces cross; coincident faces' edges both.
  for (std::size_t i = 0; i < placed.size(); ++i)
    for (std::size_t j = i + 1; j < placed.size(); ++j) {
      const Placed &a = placed[i], &b = placed[j];
      if (glm::any(glm::lessThan(a.hi, b.lo)) || glm::any(glm::lessThan(b.hi, a.lo))) continue;
      for (const auto& t : a.triangles) {
        glm::dvec3 tlo = glm::min(t[0], glm::min(t[1], t[2])), thi = glm::max(t[0], glm::max(t[1], t[2]));
        if (glm::any(glm::lessThan(thi, b.lo)) || glm::any(glm::lessThan(b.hi, tlo))) continue;
        for (const auto& u : b.triangles) {
          const glm::dvec3 ulo = glm::min(u[0], glm::min(u[1], u[2])), uhi = glm::max(u[0], glm::max(u[1], u[2]));
          if (glm::any(glm::lessThan(thi, ulo)) || glm::any(glm::lessThan(uhi, tlo))) continue;
          // Coplanar within float rounding of the corners' distance from the origin: the
          // coincident faces' borders are where the shared surface begins.
          const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
          const double scale =
              std::max({glm::length(thi), glm::length(tlo), glm::length(uhi), glm::length(ulo), 1e-30}) * glm::length(n);
          const double ulps = 64.0 * std::numeric_limits<float>::epsilon();
          bool coplanar = true;
          for (const glm::dvec3& v : u) coplanar = coplanar && std::abs(glm::dot(n, v - t[0])) <= ulps * scale;
          if (coplanar) {
            for (int k = 0; k < 3; ++k) {
              markWorldSegment(marks, size, vp, t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)], margin);
              markWorldSegment(marks, size, vp, u[static_cast<std::size_t>(k)], u[static_cast<std::size_t>((k + 1) % 3)], margin);
            }
            continue;
          }
          glm::dvec3 from, to;
          if (triangleCrossing(t, u, from, to)) markWorldSegment(marks, size, vp, from, to, margin);
        }
      }
    }
  return marks;
}

CsgReport compareCsg(const CsgImage& expected, const std::vector<float>& depth, const std::vector<int>& primitive,
                     const std::vector<bool>& edges, float depthStep, float snap) {
  const glm::ivec2 size = expected.size;
  const std::size_t n = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  if (expected.depth.size() != n || expected.primitive.size() != n || depth.size() != n ||
      primitive.size() != n || edges.size() != n || (!expected.sharedWith.empty() && expected.sharedWith.size() != n))
    throw std::invalid_argument("compareCsg: the images do not match the size");
  CsgReport report;
  report.pixels = n;
  const auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x);
  };
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const std::size_t i = at(x, y);
      report.edgePixels += edges[i];
      const int e = expected.primitive[i];
      bool samePrimitive = primitive[i] == e;
      if (!samePrimitive && !expected.sharedWith.empty())
        for (int s : expected.sharedWith[i]) samePrimitive = samePrimitive || primitive[i] == s;
      // The surface's depth change per pixel, from the neighbours on the same surface.
      float slope = 0.0f;
      for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
        float s = 0.0f;
        for (int sign : {-1, 1}) {
          const int nx = x + sign * d.x, ny = y + sign * d.y;
          if (nx < 0 || ny < 0 || nx >= size.x || ny >= size.y) continue;
          const std::size_t j = at(nx, ny);
          if (expected.primitive[j] == e) s = std::max(s, std::abs(expected.depth[j] - expected.depth[i]));
        }
        slope += s;
      }
      const float tolerance = depthStep + snap * slope;
      const float error = std::abs(depth[i] - expected.depth[i]);
      if (samePrimitive && !edges[i] && e >= 0) report.largestDepthError = std::max(report.largestDepthError, error);
      if (!samePrimitive) {
        ++report.primitiveDisagreements;
      } else if (e >= 0 && !(error <= tolerance)) {
        ++report.depthDisagreements;
      } else {
        continue;
      }
      report.onEdges += edges[i];
    }
  return report;
}

}  // namespace stencil
