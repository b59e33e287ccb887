#include "geometry/cutout.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <stdexcept>

#include "geometry/planar.h"

namespace stencil {

Mesh makeCutout(const std::vector<std::string>& rows, float cellSize) {
  if (!(cellSize > 0.0f) || !std::isfinite(cellSize))
    throw std::invalid_argument("makeCutout: cellSize must be positive and finite");
  if (rows.empty() || rows.front().empty()) throw std::invalid_argument("makeCutout: empty grid");
  const std::size_t r = rows.size(), c = rows.front().size();
  for (const std::string& row : rows)
    if (row.size() != c) throw std::invalid_argument("makeCutout: rows of different lengths");

  Mesh mesh;
  std::vector<std::int64_t> vertexAt((r + 1) * (c + 1), -1);  // grid corner -> vertex, made on first use
  const auto vertex = [&](std::size_t i, std::size_t j) {
    std::int64_t& v = vertexAt[i * (c + 1) + j];
    if (v < 0) {
      v = static_cast<std::int64_t>(mesh.positions.size());
      mesh.positions.push_back({(static_cast<float>(j) - 0.5f * static_cast<float>(c)) * cellSize, 0.0f,
                                (static_cast<float>(i) - 0.5f * static_cast<float>(r)) * cellSize});
      mesh.normals.push_back({0.0f, 1.0f, 0.0f});
    }
    return static_cast<std::uint32_t>(v);
  };
  for (std::size_t i = 0; i < r; ++i)
    for (std::size_t j = 0; j < c; ++j) {
      if (rows[i][j] != '#') continue;
      // Corners (i, j), (i+1, j), (i+1, j+1): counter-clockwise seen from +y (z grows with i).
      const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), d = vertex(i + 1, j + 1),
                          e = vertex(i, j + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, e});
    }
  if (mesh.indices.empty()) throw std::invalid_argument("makeCutout: no filled cell");
  return mesh;
}

std::vector<std::string> latticeRows(int n) {
  if (n < 1) throw std::invalid_argument("latticeRows: n must be at least 1");
  const int m = 2 * n + 3;
  std::vector<std::string> rows(static_cast<std::size_t>(m), std::string(static_cast<std::size_t>(m), '#'));
  for (int i = 2; i <= 2 * n; i += 2)
    for (int j = 2; j <= 2 * n; j += 2) rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = '.';
  for (int i : {0, m - 1})
    for (int j : {0, m - 1}) rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = '.';
  return rows;
}

namespace {

double det4(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, const glm::dvec4& d) {
  return glm::determinant(glm::dmat4(a, b, c, d));
}

// The matrix whose columns are p[0..3] scaled so that they sum to p[4]: it sends e1..e4 to the
// first four points and (1,1,1,1) to the fifth. Throws when four of the five are coplanar.
glm::dmat4 basisTo(const std::array<glm::vec4, 5>& points, const char* which) {
  std::array<glm::dvec4, 5> p;
  for (std::size_t i = 0; i < 5; ++i) {
    p[i] = glm::dvec4(points[i]);
    const double length = glm::length(p[i]);
    if (!(length > 0.0) || !std::isfinite(length))
      throw std::invalid_argument(std::string("projectiveFromFivePoints: a ") + which +
                                  " point is zero or not finite");
    p[i] /= length;  // scale does not change a projective point; unit length makes the test below fair
  }
  // Any four coplanar (linearly dependent as 4-vectors): no projective basis. With unit vectors
  // the determinant is at most 1 in size.
  constexpr double kFlat = 1e-7;
  for (std::size_t skip = 0; skip < 5; ++skip) {
    std::array<glm::dvec4, 4> q;
    for (std::size_t i = 0, k = 0; i < 5; ++i)
      if (i != skip) q[k++] = p[i];
    if (std::abs(det4(q[0], q[1], q[2], q[3])) < kFlat)
      throw std::invalid_argument(std::string("projectiveFromFivePoints: four of the ") + which +
                                  " points are coplanar");
  }
  const glm::dmat4 columns(p[0], p[1], p[2], p[3]);
  const glm::dvec4 lambda = glm::inverse(columns) * p[4];
  return glm::dmat4(lambda.x * p[0], lambda.y * p[1], lambda.z * p[2], lambda.w * p[3]);
}

}  // namespace

glm::mat4 projectiveFromFivePoints(const std::array<glm::vec4, 5>& from, const std::array<glm::vec4, 5>& to) {
  const glm::dmat4 a = basisTo(from, "from"), b = basisTo(to, "to");
  const glm::dmat4 m = b * glm::inverse(a);
  // The map is defined up to scale, and a negative scale would turn every w negative (GL clips
  // such points away): scale it so that from[0] lands exactly on to[0].
  const glm::dvec4 image = m * glm::dvec4(from[0]), target(to[0]);
  return glm::mat4(m * (glm::dot(target, target) / glm::dot(image, target)));
}

ShadowVolume cutoutPrism(const Mesh& cutout, const EdgeAdjacency& adjacency) {
  validateMesh(cutout);
  const glm::vec4 fromAbove(0.0f, 1.0f, 0.0f, 0.0f);
  ShadowVolume prism;
  for (const SilhouetteEdge& e : possibleSilhouetteEdges(adjacency, facesLight(cutout, fromAbove)))
    addExtrudedEdge(prism, cutout.positions[e.v0], cutout.positions[e.v1], fromAbove, 1.0f);
  return prism;
}

glm::mat4 cutoutExtrusionMatrix(const glm::vec4& light, float reach) {
  if (light.y == 0.0f)
    throw std::invalid_argument("cutoutExtrusionMatrix: the light is in the cut-out's plane (edge-on)");
  // Pushed away from the light: a point light to infinity (X - L at w = 0); a directional
  // light by `reach` (X - reach * L, still at w = 1).
  const glm::vec4 push = light.w != 0.0f ? light / light.w : reach * light;
  const glm::vec4 o(0, 0, 0, 1), x(1, 0, 0, 1), z(0, 0, 1, 1), q(1, 0, 1, 1);
  return projectiveFromFivePoints({o, x, z, o - glm::vec4(0, 1, 0, 0), q - glm::vec4(0, 1, 0, 0)},
                                  {o, x, z, o - push, q - push});
}

std::vector<glm::vec4> doubledVertexVolume(const Mesh& mesh, const std::vector<SilhouetteEdge>& edges) {
  validateMesh(mesh);
  std::vector<glm::vec4> vertices;
  vertices.reserve(edges.size() * 6);
  for (const SilhouetteEdge& e : edges) {
    const glm::vec3& a = mesh.positions.at(e.v0);
    const glm::vec3& b = mesh.positions.at(e.v1);
    // The same quad as addExtrudedEdge, with the far copies flagged by w = 0.
    const glm::vec4 corners[4] = {glm::vec4(a, 1), glm::vec4(b, 1), glm::vec4(a, 0), glm::vec4(b, 0)};
    for (int c : extrudedQuadCorners(a, b)) vertices.push_back(corners[c]);
  }
  return vertices;
}

glm::mat4 extrusionToInfinity(const glm::vec4& light) {
  glm::mat4 m = light.w * glm::mat4(1.0f);
  m[3] -= light;  // column 3 multiplies the point's w
  return m;
}

namespace {

// Orthonormal u, v on the plane with u x v = n, the plane's unit normal.
struct PlaneFrame {
  glm::dvec3 origin, u, v;
  glm::dvec2 to2d(const glm::vec3& p) const {
    const glm::dvec3 d = glm::dvec3(p) - origin;
    return {glm::dot(d, u), glm::dot(d, v)};
  }
};

PlaneFrame frameOf(const glm::vec4& plane) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(plane));
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  return {-n * (double(plane.w) / glm::length(glm::dvec3(plane))), u, glm::cross(n, u)};
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x * b.y - a.y * b.x;
}

int winding2d(const std::vector<std::pair<glm::dvec2, glm::dvec2>>& loops, const glm::dvec2& p) {
  int w = 0;
  for (const auto& [a, b] : loops) {
    const double side = cross2(b - a, p - a);  // > 0: p left of a -> b
    if (a.y <= p.y && b.y > p.y && side > 0) ++w;
    if (b.y <= p.y && a.y > p.y && side < 0) --w;
  }
  return w;
}

std::vector<std::pair<glm::dvec2, glm::dvec2>> flatten(const std::vector<Segment>& loops,
                                                       const PlaneFrame& f) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> flat;
  flat.reserve(loops.size());
  for (const Segment& s : loops) flat.push_back({f.to2d(s.a), f.to2d(s.b)});
  return flat;
}

}  // namespace

int windingNumber(const std::vector<Segment>& loops, const glm::vec4& plane, const glm::vec3& point) {
  const PlaneFrame f = frameOf(plane);
  return winding2d(flatten(loops, f), f.to2d(point));
}

std::vector<Segment> projectedSilhouette(const Mesh& mesh, const EdgeAdjacency& adjacency,
                                         const glm::vec4& light, const glm::vec4& plane) {
  validateMesh(mesh);
  if (!adjacency.report.closedManifold())
    throw std::invalid_argument("projectedSilhouette: the mesh is not a closed manifold");
  const float lightSide = glm::dot(plane, light);
  if (lightSide == 0.0f) throw std::invalid_argument("projectedSilhouette: the light is in the plane");
  for (const glm::vec3& p : mesh.positions) {
    const float height = glm::dot(plane, glm::vec4(p, 1.0f));  // on the light's side, nearer than the light
    const bool between = lightSide > 0 ? height > 0 && (light.w == 0 || height < lightSide / light.w)
                                       : height < 0 && (light.w == 0 || height > lightSide / light.w);
    if (!between)
      throw std::invalid_argument("projectedSilhouette: the object is not between the light and the plane");
  }
  const glm::mat4 flatten = planarShadowMatrix(plane, light);
  const auto project = [&](const glm::vec3& p) {
    const glm::vec4 q = flatten * glm::vec4(p, 1.0f);
    return glm::vec3(q) / q.w;
  };
  std::vector<Segment> loops;
  for (const SilhouetteEdge& e : possibleSilhouetteEdges(adjacency, facesLight(mesh, light)))
    loops.push_back({project(mesh.positions[e.v0]), project(mesh.positions[e.v1])});
  return loops;
}

std::vector<Segment> nonzeroOutline(const std::vector<Segment>& loops, const glm::vec4& plane) {
  const PlaneFrame f = frameOf(plane);
  const auto flat = flatten(loops, f);
  double extent = 0.0;
  for (const auto& [a, b] : flat)
    extent = std::max({extent, std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});

  // Where each segment crosses the others: its parameter and the 3D point, computed once per
  // pair so both pieces that meet there share the exact same vertex.
  struct Cut {
    double t;
    glm::vec3 point;
  };
  std::vector<std::vector<Cut>> cuts(loops.size());
  constexpr double kEnd = 1e-9;  // crossings at a segment's ends are its loop's own joints
  for (std::size_t i = 0; i < flat.size(); ++i)
    for (std::size_t j = i + 1; j < flat.size(); ++j) {
      const glm::dvec2 p = flat[i].first, r = flat[i].second - p;
      const glm::dvec2 q = flat[j].first, s = flat[j].second - q;
      const double denominator = cross2(r, s);
      if (denominator == 0.0) continue;  // parallel: no single crossing
      const double t = cross2(q - p, s) / denominator, u = cross2(q - p, r) / denominator;
      if (t <= kEnd || t >= 1 - kEnd || u <= kEnd || u >= 1 - kEnd) continue;
      const glm::vec3 point = loops[i].a + static_cast<float>(t) * (loops[i].b - loops[i].a);
      cuts[i].push_back({t, point});
      cuts[j].push_back({u, point});
    }

  std::vector<Segment> outline;
  const double offset = 1e-6 * std::max(extent, 1e-3);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::vector<Cut>& c = cuts[i];
    std::sort(c.begin(), c.end(), [](const Cut& x, const Cut& y) { return x.t < y.t; });
    std::vector<glm::vec3> points{loops[i].a};
    for (const Cut& cut : c) points.push_back(cut.point);
    points.push_back(loops[i].b);
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const glm::dvec2 a = f.to2d(points[k]), b = f.to2d(points[k + 1]);
      const double length = glm::length(b - a);
      if (length == 0.0) continue;
      const glm::dvec2 middle = 0.5 * (a + b), left = glm::dvec2(-(b - a).y, (b - a).x) / length;
      const int wLeft = winding2d(flat, middle + offset * left),
                wRight = winding2d(flat, middle - offset * left);
      if ((wLeft != 0) == (wRight != 0)) continue;  // inside or outside on both sides: not on the outline
      // Seen from the plane's normal side the loops wind positively around the shadow when the
      // light is on that side, negatively when it is behind; either way keep the shadow on the
      // left seen from the light.
      if (wLeft > 0 || wRight < 0)
        outline.push_back({points[k], points[k + 1]});
      else
        outline.push_back({points[k + 1], points[k]});
    }
  }
  return outline;
}

ShadowVolume flattenedVolume(const std::vector<Segment>& outline, const glm::vec4& light, float distance) {
  ShadowVolume volume;
  if (outline.empty()) return volume;
  for (const Segment& s : outline) addExtrudedEdge(volume, s.a, s.b, light, distance);
  const glm::vec4 centre(outline.front().a, 1.0f);  // the fan's apex: any point on the plane works
  for (const Segment& s : outline)
    volume.vertices.insert(volume.vertices.end(), {centre, glm::vec4(s.a, 1), glm::vec4(s.b, 1)});
  return volume;
}

}  // namespace stencil
