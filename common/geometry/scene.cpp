#include "geometry/scene.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/weld.h"

namespace stencil {

namespace {

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

}  // namespace

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
    report.messages.push_back("welded " + plural(report.inputVertices - report.weldedVertices, "split vertex") +
                              " at seams");
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

glm::mat4 SceneObject::modelAt(double time) const {
  const float t = static_cast<float>(time);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, bob * std::sin(t), 0.0f)) * model;
  if (spinDegPerSecond != 0.0f) m = glm::rotate(m, glm::radians(spinDegPerSecond * t), spinAxis);
  return m;
}

}  // namespace stencil
