#include "geometry/shadow_volume.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/weld.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace stencil {

glm::vec4 extrudeAway(const glm::vec3& point, const glm::vec4& light, float distance) {
  // Away from a point light: p - L; from a directional light: -L (the same for every point).
  const glm::vec3 away = light.w == 0.0f ? -glm::vec3(light) : point - glm::vec3(light) / light.w;
  if (std::isinf(distance)) return glm::vec4(away, 0.0f);
  const float length = glm::length(away);
  if (length == 0.0f) return glm::vec4(point, 1.0f);  // the light sits on the point: no direction
  return glm::vec4(point + away * (distance / length), 1.0f);
}

namespace {

glm::vec3 faceNormal(const Mesh& mesh, std::size_t triangle) {
  const glm::vec3& a = mesh.positions[mesh.indices[3 * triangle]];
  const glm::vec3& b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const glm::vec3& c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return glm::cross(b - a, c - a);
}

// The index of the lowest set bit of a non-zero mask: C++20's std::countr_zero, one instruction
// on GCC and Clang.
int lowestSetBit(std::uint32_t mask) {
#if defined(__GNUC__)
  return __builtin_ctz(mask);
#else
  int bit = 0;
  for (; (mask & 1u) == 0; mask >>= 1) ++bit;
  return bit;
#endif
}

// Zero area, exactly: a repeated vertex, or three vertices on one line. A sliver keeps its
// place, however thin: dropping it would open the mesh.
bool degenerate(const std::vector<glm::vec3>& positions, const std::uint32_t* triangle) {
  const std::uint32_t a = triangle[0], b = triangle[1], c = triangle[2];
  if (a == b || b == c || c == a) return true;
  const glm::dvec3 pa(positions[a]), pb(positions[b]), pc(positions[c]);
  return glm::cross(pb - pa, pc - pa) == glm::dvec3(0.0);
}

std::string plural(std::size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// > 0: the triangle faces the light; 0: edge-on or degenerate.
float facing(const Mesh& mesh, std::size_t triangle, const glm::vec4& light) {
  const glm::vec3& a = mesh.positions[mesh.indices[3 * triangle]];
  return glm::dot(faceNormal(mesh, triangle), glm::vec3(light) - light.w * a);
}

}  // namespace

std::vector<bool> facesLight(const Mesh& mesh, const glm::vec4& light) {
  validateMesh(mesh);
  std::vector<bool> lit(mesh.triangleCount());
  for (std::size_t t = 0; t < lit.size(); ++t) lit[t] = facing(mesh, t, light) > 0.0f;
  return lit;
}

std::vector<std::uint32_t> facesTurnedFromLight(const Mesh& mesh, const glm::vec4& light, const glm::vec4& eye) {
  validateMesh(mesh);
  std::vector<std::uint32_t> faces;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const float seen = facing(mesh, t, eye);
    if (seen == 0.0f) continue;
    const bool lit = facing(mesh, t, light) > 0.0f;  // as facesLight
    // The side the eye sees faces the light when the eye sees the front of a lit face (or the
    // back of an unlit one).
    if (lit == (seen > 0.0f)) continue;
    faces.insert(faces.end(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
                 mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  return faces;
}

std::vector<SilhouetteEdge> possibleSilhouetteEdges(const EdgeAdjacency& adjacency,
                                                    const std::vector<bool>& lit) {
  std::vector<SilhouetteEdge> silhouette;
  for (const Edge& e : adjacency.edges) {
    const bool lit0 = lit.at(static_cast<std::size_t>(e.face0));
    if (e.face1 < 0) {  // a border: face0 walks v0 -> v1, out of the volume when it is lit
      silhouette.push_back(lit0 ? SilhouetteEdge{e.v0, e.v1} : SilhouetteEdge{e.v1, e.v0});
      continue;
    }
    const bool lit1 = lit.at(static_cast<std::size_t>(e.face1));
    if (lit0 && !lit1) silhouette.push_back({e.v0, e.v1});
    if (lit1 && !lit0) silhouette.push_back({e.v1, e.v0});  // face1 walks v1 -> v0
  }
  return silhouette;
}

SilhouetteCaster prepareSilhouettes(const Mesh& mesh, const EdgeAdjacency& adjacency) {
  validateMesh(mesh);
  SilhouetteCaster c;
  const std::size_t faces = mesh.triangleCount();
  for (auto* v : {&c.nx, &c.ny, &c.nz, &c.ax, &c.ay, &c.az}) v->resize(faces);
  for (std::size_t t = 0; t < faces; ++t) {
    const glm::vec3 n = faceNormal(mesh, t);  // as facing() computes it
    const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
    c.nx[t] = n.x, c.ny[t] = n.y, c.nz[t] = n.z;
    c.ax[t] = a.x, c.ay[t] = a.y, c.az[t] = a.z;
  }
  const auto border = static_cast<std::int32_t>(faces);
  c.edgeFaces.reserve(adjacency.edges.size());
  c.edgeEnds.reserve(adjacency.edges.size());
  for (const Edge& e : adjacency.edges) {
    if (e.face0 < 0 || static_cast<std::size_t>(e.face0) >= faces || e.face1 < -1 ||
        (e.face1 >= 0 && static_cast<std::size_t>(e.face1) >= faces))
      throw std::invalid_argument("prepareSilhouettes: an edge names a face past the mesh's " +
                                  std::to_string(faces) + " triangles");
    c.edgeFaces.push_back({e.face0, e.face1 < 0 ? border : e.face1});
    c.edgeEnds.push_back({e.v0, e.v1});
  }
  return c;
}

void facesLight(const SilhouetteCaster& c, const glm::vec4& light, std::vector<std::uint8_t>& lit) {
  const std::size_t faces = c.faceCount();
  lit.resize(faces + 1);
  const float lx = light.x, ly = light.y, lz = light.z, lw = light.w;
  const float *nx = c.nx.data(), *ny = c.ny.data(), *nz = c.nz.data();
  const float *ax = c.ax.data(), *ay = c.ay.data(), *az = c.az.data();
  std::uint8_t* out = lit.data();
  // dot(n, L.xyz - L.w * a) evaluated as glm does it, (x + y) + z with no reassociation: the same
  // rounding in every SSE lane as in the scalar loop and in facing().
  std::size_t t = 0;
#ifdef __SSE2__
  const __m128 Lx = _mm_set1_ps(lx), Ly = _mm_set1_ps(ly), Lz = _mm_set1_ps(lz), Lw = _mm_set1_ps(lw);
  const __m128 zero = _mm_setzero_ps();
  const auto facing4 = [&](std::size_t i) {  // 0xffffffff where the face faces the light, else 0
    const __m128 x = _mm_mul_ps(_mm_loadu_ps(nx + i), _mm_sub_ps(Lx, _mm_mul_ps(Lw, _mm_loadu_ps(ax + i))));
    const __m128 y = _mm_mul_ps(_mm_loadu_ps(ny + i), _mm_sub_ps(Ly, _mm_mul_ps(Lw, _mm_loadu_ps(ay + i))));
    const __m128 z = _mm_mul_ps(_mm_loadu_ps(nz + i), _mm_sub_ps(Lz, _mm_mul_ps(Lw, _mm_loadu_ps(az + i))));
    return _mm_castps_si128(_mm_cmpgt_ps(_mm_add_ps(_mm_add_ps(x, y), z), zero));
  };
  for (; t + 16 <= faces; t += 16) {  // sixteen faces' masks packed into sixteen 0/1 bytes
    const __m128i low = _mm_packs_epi32(facing4(t), facing4(t + 4));
    const __m128i high = _mm_packs_epi32(facing4(t + 8), facing4(t + 12));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + t),
                     _mm_and_si128(_mm_packs_epi16(low, high), _mm_set1_epi8(1)));
  }
#endif
  for (; t < faces; ++t) {
    const float f = nx[t] * (lx - lw * ax[t]) + ny[t] * (ly - lw * ay[t]) + nz[t] * (lz - lw * az[t]);
    out[t] = f > 0.0f ? 1 : 0;
  }
  out[faces] = 2;
}

namespace {

// Bit k set when edge k of the 32 at `faces` has one face lit and one not (or is a border). Unrolled
// in full, each test's shift is a constant: at 1k triangles, where the arrays sit in L1, a loop
// over k with a variable shift cost a fifth more than the two flag loads per edge that bound the
// edge pass.
inline std::uint32_t differingEdges32(const std::uint8_t* flag, const SilhouetteCaster::EdgeFaces* faces) {
  std::uint32_t mask = 0;
#pragma GCC unroll 32
  for (std::uint32_t k = 0; k < 32; ++k)
    mask |= static_cast<std::uint32_t>(flag[static_cast<std::uint32_t>(faces[k].face0)] !=
                                       flag[static_cast<std::uint32_t>(faces[k].face1)])
            << k;
  return mask;
}

}  // namespace

void possibleSilhouetteEdges(const SilhouetteCaster& c, const std::vector<std::uint8_t>& lit,
                             std::vector<SilhouetteEdge>& out) {
  if (lit.size() != c.faceCount() + 1)
    throw std::invalid_argument("possibleSilhouetteEdges: " + std::to_string(lit.size()) + " flags for " +
                                std::to_string(c.faceCount()) + " faces and the border's");
  out.clear();
  const std::uint8_t* flag = lit.data();
  const SilhouetteCaster::EdgeFaces* faces = c.edgeFaces.data();
  const std::size_t edges = c.edgeFaces.size();
  // Both faces lit or both not: inside the light cap or on the dark side. One lit face (or a
  // border's one face, against its flag 2): a possible silhouette edge, walked the lit face's way.
  const auto emit = [&](std::size_t k) {
    const SilhouetteEdge& ends = c.edgeEnds[k];
    out.push_back(flag[static_cast<std::uint32_t>(faces[k].face0)] == 1 ? ends
                                                                        : SilhouetteEdge{ends.v1, ends.v0});
  };
  // Most edges are not on the silhouette: thirty-two edges' tests go into the bits of a mask
  // without a branch, and only the set bits are visited, in order.
  std::size_t e = 0;
  for (; e + 32 <= edges; e += 32)
    for (std::uint32_t mask = differingEdges32(flag, faces + e); mask != 0; mask &= mask - 1)
      emit(e + static_cast<std::size_t>(lowestSetBit(mask)));
  for (; e < edges; ++e)
    if (flag[static_cast<std::uint32_t>(faces[e].face0)] != flag[static_cast<std::uint32_t>(faces[e].face1)])
      emit(e);
}

std::vector<SilhouetteEdge> possibleSilhouetteEdges(const SilhouetteCaster& caster, const glm::vec4& light) {
  std::vector<std::uint8_t> lit;
  std::vector<SilhouetteEdge> out;
  facesLight(caster, light, lit);
  possibleSilhouetteEdges(caster, lit, out);
  return out;
}

std::array<int, 6> extrudedQuadCorners(const glm::vec3& a, const glm::vec3& b) {
  // The volume lies to the left of a -> b seen from the light, so b, a, a', b' faces out.
  const bool aFirst = a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  if (aFirst) return {0, 2, 3, 0, 3, 1};  // a, a', b' and a, b', b
  return {1, 0, 2, 1, 2, 3};              // b, a, a' and b, a', b'
}

void addExtrudedEdge(ShadowVolume& volume, const glm::vec3& a, const glm::vec3& b, const glm::vec4& light,
                     float distance) {
  const glm::vec4 corners[4] = {glm::vec4(a, 1.0f), glm::vec4(b, 1.0f), extrudeAway(a, light, distance),
                                extrudeAway(b, light, distance)};
  for (int c : extrudedQuadCorners(a, b)) volume.vertices.push_back(corners[c]);
}

ShadowVolume silhouetteVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                              float distance) {
  if (adjacency.report.nonManifoldEdges != 0 || adjacency.report.inconsistentEdges != 0) {
    throw std::invalid_argument("silhouetteVolume: the mesh has " +
                                std::to_string(adjacency.report.nonManifoldEdges) + " non-manifold and " +
                                std::to_string(adjacency.report.inconsistentEdges) +
                                " inconsistently wound edges; its silhouette is not a volume's boundary");
  }
  ShadowVolume volume;
  for (const SilhouetteEdge& e : possibleSilhouetteEdges(adjacency, facesLight(mesh, light)))
    addExtrudedEdge(volume, mesh.positions[e.v0], mesh.positions[e.v1], light, distance);
  return volume;
}

PreparedCaster prepareCaster(const Mesh& mesh) {
  validateMesh(mesh);
  PreparedCaster result;
  CasterReport& report = result.report;
  report.inputVertices = mesh.positions.size();

  Mesh positionsOnly;
  positionsOnly.positions = mesh.positions;
  positionsOnly.indices = mesh.indices;
  Mesh welded = weldByPosition(positionsOnly).mesh;
  report.weldedVertices = welded.positions.size();

  result.mesh.positions = std::move(welded.positions);
  for (std::size_t t = 0; t < welded.triangleCount(); ++t) {
    if (degenerate(result.mesh.positions, &welded.indices[3 * t])) {
      ++report.droppedDegenerate;
      continue;
    }
    result.mesh.indices.insert(result.mesh.indices.end(), welded.indices.begin() + 3 * t,
                               welded.indices.begin() + 3 * t + 3);
  }
  result.adjacency = buildEdgeAdjacency(result.mesh.indices, result.mesh.positions.size());
  report.borderEdges = result.adjacency.report.borderEdges;
  report.nonManifoldEdges = result.adjacency.report.nonManifoldEdges;
  report.inconsistentEdges = result.adjacency.report.inconsistentEdges;

  if (report.weldedVertices < report.inputVertices)
    report.messages.push_back("welded " + std::to_string(report.inputVertices) + " vertices into " +
                              std::to_string(report.weldedVertices) + " (vertices split at seams)");
  if (report.droppedDegenerate > 0)
    report.messages.push_back("dropped " + plural(report.droppedDegenerate, "degenerate triangle"));
  if (report.borderEdges > 0)
    report.messages.push_back("open: " + plural(report.borderEdges, "border edge") +
                              " extrude as silhouette edges, and its faces cap the volume from both sides");
  if (report.nonManifoldEdges > 0)
    report.messages.push_back("not two-manifold: " + plural(report.nonManifoldEdges, "edge") +
                              " shared by three or more faces");
  if (report.inconsistentEdges > 0)
    report.messages.push_back("inconsistently wound: " + plural(report.inconsistentEdges, "edge") +
                              " walked the same way by both faces");
  return result;
}

ShadowVolume silhouetteVolume(const PreparedCaster& caster, const glm::vec4& light, float distance) {
  return silhouetteVolume(caster.mesh, caster.adjacency, light, distance);
}

ShadowVolume polygonVolumes(const Mesh& mesh, const glm::vec4& light, float distance, bool twoSided) {
  validateMesh(mesh);
  ShadowVolume volume;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const float f = facing(mesh, t, light);
    if (f == 0.0f || (f < 0.0f && !twoSided)) continue;
    glm::vec3 p[3] = {mesh.positions[mesh.indices[3 * t]], mesh.positions[mesh.indices[3 * t + 1]],
                      mesh.positions[mesh.indices[3 * t + 2]]};
    if (f < 0.0f) std::swap(p[1], p[2]);  // seen from the light it is now counter-clockwise
    for (int k = 0; k < 3; ++k) addExtrudedEdge(volume, p[k], p[(k + 1) % 3], light, distance);
  }
  return volume;
}

namespace {

// The closed volume of the lit faces; its dark cap the other faces pushed away (Everitt and
// Kilgard's, for the whole light cap) or the lit faces pushed away and turned round (a piece).
ClosedVolume closedVolumeOf(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                            float distance, const std::vector<bool>& lit, bool piece) {
  const AdjacencyReport& r = adjacency.report;
  if (r.borderEdges != 0 || r.nonManifoldEdges != 0 || r.inconsistentEdges != 0) {
    throw std::invalid_argument("closedVolume: the caster has " + std::to_string(r.borderEdges) +
                                " border, " + std::to_string(r.nonManifoldEdges) + " non-manifold and " +
                                std::to_string(r.inconsistentEdges) +
                                " inconsistently wound edges; only a closed mesh bounds a closed volume");
  }
  if (lit.size() != mesh.indices.size() / 3)
    throw std::invalid_argument("closedVolume: " + std::to_string(lit.size()) + " lit flags for " +
                                std::to_string(mesh.indices.size() / 3) + " triangles");
  ClosedVolume closed;
  ShadowVolume& v = closed.triangles;
  const std::vector<SilhouetteEdge> silhouette = possibleSilhouetteEdges(adjacency, lit);
  closed.possibleSilhouetteEdges = silhouette.size();
  for (const SilhouetteEdge& e : silhouette)
    addExtrudedEdge(v, mesh.positions[e.v0], mesh.positions[e.v1], light, distance);
  closed.sideTriangles = v.triangleCount();
  // Lit faces face the light, which is out of the volume at its near end.
  for (std::size_t t = 0; t < lit.size(); ++t)
    if (lit[t])
      for (int k = 0; k < 3; ++k)
        v.vertices.push_back(glm::vec4(mesh.positions[mesh.indices[3 * t + k]], 1.0f));
  closed.lightCapTriangles = v.triangleCount() - closed.sideTriangles;
  // Unlit faces face away from the light; pushed along the light's rays they still do, which is
  // out of the volume at its far end. Each vertex goes where the sides' far corners went.
  const bool collapses = light.w == 0.0f && std::isinf(distance);
  for (std::size_t t = 0; t < lit.size() && !collapses; ++t)
    if (lit[t] == piece)
      for (int k = 0; k < 3; ++k)  // a piece's own faces turned round: corners 0, 2, 1
        v.vertices.push_back(
            extrudeAway(mesh.positions[mesh.indices[3 * t + (piece ? (3 - k) % 3 : k)]], light, distance));
  closed.darkCapTriangles = v.triangleCount() - closed.sideTriangles - closed.lightCapTriangles;
  return closed;
}

}  // namespace

ClosedVolume closedVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                          float distance) {
  return closedVolumeOf(mesh, adjacency, light, distance, facesLight(mesh, light), false);
}

ClosedVolume closedVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                          float distance, const std::vector<bool>& lit) {
  return closedVolumeOf(mesh, adjacency, light, distance, lit, true);
}

bool isConvex(const Mesh& mesh, const EdgeAdjacency& adjacency, bool facesIn) {
  if (!adjacency.report.closedManifold() || adjacency.report.degenerateTriangles != 0 || mesh.indices.empty())
    return false;
  const std::size_t faces = mesh.indices.size() / 3;
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float tolerance = 1e-5f * glm::length(hi - lo);
  const auto corner = [&](std::int32_t f, int k) {
    return mesh.positions[mesh.indices[3 * std::size_t(f) + k]];
  };
  // The corner of face g that is not on the edge, against face f's plane (normal not normalised:
  // scale the distance).
  const auto behind = [&](std::int32_t f, std::int32_t g, const Edge& e) {
    const glm::vec3 a = corner(f, 0), n = glm::cross(corner(f, 1) - a, corner(f, 2) - a);
    const float length = glm::length(n);
    if (length == 0.0f) return false;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.indices[3 * std::size_t(g) + k];
      if (i == e.v0 || i == e.v1) continue;
      const float distance = glm::dot(n, mesh.positions[i] - a) / length;
      return (facesIn ? -distance : distance) <= tolerance;
    }
    return false;
  };
  // Union-find over faces: connected through shared edges.
  std::vector<std::size_t> parent(faces);
  for (std::size_t f = 0; f < faces; ++f) parent[f] = f;
  const auto root = [&](std::size_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  std::size_t pieces = faces;
  for (const Edge& e : adjacency.edges) {
    if (!behind(e.face0, e.face1, e) || !behind(e.face1, e.face0, e)) return false;
    const std::size_t a = root(std::size_t(e.face0)), b = root(std::size_t(e.face1));
    if (a != b) {
      parent[a] = b;
      --pieces;
    }
  }
  return pieces == 1;
}

std::size_t nestingBound(std::size_t litFaces, std::size_t possibleSilhouetteEdges, bool convex,
                         bool lightOutside) {
  if (litFaces == 0) return 0;
  if (convex) return 1;
  return lightOutside ? std::min(litFaces, possibleSilhouetteEdges / 2) : litFaces;
}

std::vector<std::vector<bool>> litFacePieces(const std::vector<bool>& lit, std::size_t maxFaces) {
  if (maxFaces == 0) throw std::invalid_argument("litFacePieces: pieces of 0 faces");
  std::vector<std::vector<bool>> pieces;
  std::size_t inPiece = maxFaces;
  for (std::size_t t = 0; t < lit.size(); ++t) {
    if (!lit[t]) continue;
    if (inPiece == maxFaces) {
      pieces.emplace_back(lit.size(), false);
      inPiece = 0;
    }
    pieces.back()[t] = true;
    ++inPiece;
  }
  return pieces;
}

namespace {

// The most closed ranges [lo, hi] that hold one x, each widened by pad.
std::size_t deepestOverlap(std::vector<std::pair<double, double>>& ranges, double pad) {
  std::vector<std::pair<double, int>> events;  // (x, -1 opens, +1 closes): opens first at a tie
  events.reserve(2 * ranges.size());
  for (const auto& [lo, hi] : ranges) {
    events.push_back({lo - pad, -1});
    events.push_back({hi + pad, +1});
  }
  std::sort(events.begin(), events.end());
  std::size_t open = 0, deepest = 0;
  for (const auto& [x, kind] : events) {
    if (kind < 0) deepest = std::max(deepest, ++open);
    else --open;
  }
  return deepest;
}

}  // namespace

std::size_t projectedNestingBound(const Mesh& mesh, const std::vector<bool>& lit,
                                  const std::vector<SilhouetteEdge>& edges, const glm::vec4& light) {
  if (lit.size() != mesh.indices.size() / 3)
    throw std::invalid_argument("projectedNestingBound: " + std::to_string(lit.size()) + " lit flags for " +
                                std::to_string(mesh.indices.size() / 3) + " triangles");
  constexpr std::size_t kNoBound = std::numeric_limits<std::size_t>::max();
  const bool directional = light.w == 0.0f;
  const glm::dvec3 from = directional ? glm::dvec3(0.0) : glm::dvec3(glm::vec3(light) / light.w);
  // The axis: where the light shines (directional), or from the light to the lit corners' centroid.
  glm::dvec3 axis(0.0);
  std::size_t corners = 0;
  if (directional) {
    axis = -glm::dvec3(glm::vec3(light));
  } else {
    for (std::size_t t = 0; t < lit.size(); ++t)
      if (lit[t])
        for (int k = 0; k < 3; ++k, ++corners) axis += glm::dvec3(mesh.positions[mesh.indices[3 * t + k]]) - from;
    if (corners == 0) return 0;
  }
  if (glm::length(axis) == 0.0) return kNoBound;
  axis = glm::normalize(axis);
  // Every lit corner strictly in front of the light: then the plane at distance 1 shows them all.
  if (!directional)
    for (std::size_t t = 0; t < lit.size(); ++t)
      if (lit[t])
        for (int k = 0; k < 3; ++k)
          if (glm::dot(glm::dvec3(mesh.positions[mesh.indices[3 * t + k]]) - from, axis) <= 0.0) return kNoBound;
  const glm::dvec3 u = glm::normalize(
      glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 v = glm::cross(axis, u);
  const auto image = [&](std::uint32_t i) {
    const glm::dvec3 d = glm::dvec3(mesh.positions[i]) - from;
    const double depth = directional ? 1.0 : glm::dot(d, axis);
    return glm::dvec2(glm::dot(d, u), glm::dot(d, v)) / depth;
  };
  std::vector<std::pair<double, double>> xs, ys;
  xs.reserve(edges.size());
  ys.reserve(edges.size());
  double extent = 0.0;
  for (const SilhouetteEdge& e : edges) {
    const glm::dvec2 a = image(e.v0), b = image(e.v1);
    xs.push_back({std::min(a.x, b.x), std::max(a.x, b.x)});
    ys.push_back({std::min(a.y, b.y), std::max(a.y, b.y)});
    extent = std::max({extent, std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
  }
  const double pad = 1e-9 * extent;
  return std::min(deepestOverlap(xs, pad), deepestOverlap(ys, pad)) / 2;
}

std::vector<LitPiece> litFacePieces(const Mesh& mesh, const EdgeAdjacency& adjacency, const std::vector<bool>& lit,
                                    const glm::vec4& light, std::size_t maxNesting) {
  if (maxNesting == 0) throw std::invalid_argument("litFacePieces: pieces that count at most 0");
  if (lit.size() != mesh.indices.size() / 3)
    throw std::invalid_argument("litFacePieces: " + std::to_string(lit.size()) + " lit flags for " +
                                std::to_string(mesh.indices.size() / 3) + " triangles");
  // Regions: lit faces joined through the edges they share (union-find).
  std::vector<std::size_t> parent(lit.size());
  for (std::size_t f = 0; f < parent.size(); ++f) parent[f] = f;
  const auto root = [&](std::size_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  for (const Edge& e : adjacency.edges)
    if (e.face1 >= 0 && lit[std::size_t(e.face0)] && lit[std::size_t(e.face1)])
      parent[root(std::size_t(e.face0))] = root(std::size_t(e.face1));
  // Each region numbered in the order of its first face, with its faces and its silhouette edges
  // (an edge with one lit face belongs to that face's region).
  std::vector<std::size_t> regionOf(lit.size(), 0), regionOfRoot(lit.size(), SIZE_MAX);
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t f = 0; f < lit.size(); ++f) {
    if (!lit[f]) continue;
    std::size_t& r = regionOfRoot[root(f)];
    if (r == SIZE_MAX) {
      r = faces.size();
      faces.emplace_back();
    }
    regionOf[f] = r;
    faces[r].push_back(static_cast<std::uint32_t>(f));
  }
  std::vector<std::vector<SilhouetteEdge>> edges(faces.size());
  for (const Edge& e : adjacency.edges) {
    const bool lit0 = lit[std::size_t(e.face0)], lit1 = e.face1 >= 0 && lit[std::size_t(e.face1)];
    if (lit0 && !lit1) edges[regionOf[std::size_t(e.face0)]].push_back({e.v0, e.v1});
    if (lit1 && !lit0) edges[regionOf[std::size_t(e.face1)]].push_back({e.v1, e.v0});
  }
  std::vector<LitPiece> pieces;
  LitPiece gathering{std::vector<bool>(lit.size(), false), 0};
  const auto flush = [&] {
    if (gathering.nesting == 0) return;
    pieces.push_back(std::move(gathering));
    gathering = {std::vector<bool>(lit.size(), false), 0};
  };
  std::vector<bool> region(lit.size(), false);
  for (std::size_t r = 0; r < faces.size(); ++r) {
    for (std::uint32_t f : faces[r]) region[f] = true;
    const std::size_t bound = std::min(faces[r].size(), projectedNestingBound(mesh, region, edges[r], light));
    if (bound <= maxNesting) {  // whole, beside the regions before it while their bounds allow
      if (gathering.nesting + bound > maxNesting) flush();
      for (std::uint32_t f : faces[r]) gathering.lit[f] = true;
      gathering.nesting += std::max<std::size_t>(bound, 1);
    } else {  // too deep by itself: runs of maxNesting faces
      flush();
      for (std::vector<bool>& run : litFacePieces(region, maxNesting)) {
        const auto n = static_cast<std::size_t>(std::count(run.begin(), run.end(), true));
        pieces.push_back({std::move(run), n});
      }
    }
    for (std::uint32_t f : faces[r]) region[f] = false;
  }
  flush();
  return pieces;
}

CountPlan countPlan(const std::vector<std::size_t>& bounds) {
  CountPlan plan;
  plan.group.assign(bounds.size(), 0);
  std::size_t total = 0;
  for (std::size_t b : bounds) total += b;
  if (total <= 255) {
    plan.groups = bounds.empty() ? 0 : 1;
    return plan;
  }
  plan.fold = true;
  std::size_t inGroup = 0;
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    if (plan.groups == 0 || inGroup + bounds[i] > 127) {
      ++plan.groups;
      inGroup = 0;
    }
    plan.group[i] = plan.groups - 1;
    inGroup += bounds[i];
  }
  return plan;
}

}  // namespace stencil
