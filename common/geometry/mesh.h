#pragma once

// Indexed triangle mesh plus the checks every lesson wants before it trusts
// one. No OpenGL here: the arrays are laid out so they upload to GL buffers
// as-is, but this layer must stay testable without a context.
//
// Depends on: GLM (C++17).

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace stencil {

struct Mesh {
  std::vector<glm::vec3> positions;
  // Empty, or exactly one per position.
  std::vector<glm::vec3> normals;
  // Triangle list; counter-clockwise seen from outside is the front face.
  std::vector<std::uint32_t> indices;

  std::size_t triangleCount() const;
};

// Throws std::invalid_argument naming the first problem: index count not a
// multiple of 3, an index past the last vertex, or a normals array whose size
// is neither 0 nor positions.size(). The other functions call this first so a
// broken mesh fails loudly instead of reading out of bounds.
void validateMesh(const Mesh& mesh);

// Index of the first vertex whose position or normal has a NaN or infinity.
std::optional<std::size_t> firstNonFiniteVertex(const Mesh& mesh);
bool allFinite(const Mesh& mesh);

// Applies an affine matrix (last row 0,0,0,1). Normals go through the
// inverse-transpose so they stay perpendicular under non-uniform scale, and are
// renormalised. A mirroring matrix (negative determinant) would turn the mesh
// inside out, so the winding of every triangle is flipped to keep it
// outward-facing. Throws std::invalid_argument for a projective or singular
// matrix, where normals have no meaning.
Mesh transformed(const Mesh& mesh, const glm::mat4& matrix);

// Enclosed volume by the divergence theorem (sum of signed tetrahedra against
// the origin), accumulated in double. Positive for a closed, outward-facing
// mesh; for an open mesh the value depends on the origin and means little.
double signedVolume(const Mesh& mesh);

}  // namespace stencil
