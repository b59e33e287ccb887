#include "geometry/shadow_volume.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "geometry/weld.h"

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

std::vector<SilhouetteEdge> silhouetteEdges(const EdgeAdjacency& adjacency, const std::vector<bool>& lit) {
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
  for (const SilhouetteEdge& e : silhouetteEdges(adjacency, facesLight(mesh, light)))
    addExtrudedEdge(volume, mesh.positions[e.v0], mesh.positions[e.v1], light, distance);
  return volume;
}

CasterEdges::CasterEdges(const Mesh& mesh)
    : welded(weldByPosition(mesh).mesh),
      adjacency(buildEdgeAdjacency(welded.indices, welded.positions.size())) {}

ShadowVolume silhouetteVolume(const CasterEdges& caster, const glm::vec4& light, float distance) {
  return silhouetteVolume(caster.welded, caster.adjacency, light, distance);
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

ClosedVolume closedVolume(const Mesh& mesh, const EdgeAdjacency& adjacency, const glm::vec4& light,
                          float distance) {
  const AdjacencyReport& r = adjacency.report;
  if (r.borderEdges != 0 || r.nonManifoldEdges != 0 || r.inconsistentEdges != 0) {
    throw std::invalid_argument("closedVolume: the caster has " + std::to_string(r.borderEdges) +
                                " border, " + std::to_string(r.nonManifoldEdges) + " non-manifold and " +
                                std::to_string(r.inconsistentEdges) +
                                " inconsistently wound edges; only a closed mesh bounds a closed volume");
  }
  const std::vector<bool> lit = facesLight(mesh, light);
  ClosedVolume closed;
  ShadowVolume& v = closed.triangles;
  const std::vector<SilhouetteEdge> silhouette = silhouetteEdges(adjacency, lit);
  closed.silhouetteEdges = silhouette.size();
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
    if (!lit[t])
      for (int k = 0; k < 3; ++k)
        v.vertices.push_back(extrudeAway(mesh.positions[mesh.indices[3 * t + k]], light, distance));
  closed.darkCapTriangles = v.triangleCount() - closed.sideTriangles - closed.lightCapTriangles;
  return closed;
}

}  // namespace stencil
