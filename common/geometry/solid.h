// Which side of a closed caster the eye and the lights are on: rooms and buried lights
// (lessons 15 and 16, docs/15-robust-zfail.md "Rooms"). A closed mesh bounds a solid. With its
// faces pointing out, the solid is what it winds around; with them pointing in (a room written
// from inside) it is everything else, and reaches to infinity. The eye is never inside matter:
// a closed caster whose solid holds the eye is a room, a shell seen from inside, whose solid is
// its outside. Everitt and Kilgard's z-fail assumes the solid of every caster is bounded and
// holds neither the eye's far plane nor the light; these functions say where that fails.
#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geometry/mesh.h"

namespace stencil {

// The winding number of a closed mesh around a point (object space): the solid angles its
// triangles subtend from the point, summed, over 4 pi, rounded. 1 inside a mesh whose faces point
// out, -1 inside one whose faces point in, 0 outside either. Meaningless for a point on the
// surface or an open mesh. O(triangles), in double precision.
int windingNumber(const Mesh& mesh, const glm::dvec3& point);

// Whether a point lies on a mesh's surface, within 1e-6 of the mesh's extent seen from it: there
// a closed mesh's winding number is no whole number (a half on a face, a quarter on a box's
// edge), and which side of the solid the point is on has no answer. O(triangles).
bool onSurface(const Mesh& mesh, const glm::dvec3& point);

// How one closed caster stands towards an eye (object space, a point).
struct SolidSide {
  bool facesIn = false;  // its faces point inwards (negative signed volume)
  bool room = false;     // its solid reaches to infinity, and the eye is in its empty inside
};
// facesIn is the mesh's (signedVolume < 0, computed once by the caller); room when the eye is
// inside what the mesh encloses, whichever way its faces point: a box around the eye, or a room
// written from inside. A caster that faces in with the eye outside it would be a solid written
// inside out; the lessons refuse it.
SolidSide solidSide(const Mesh& mesh, bool facesIn, const glm::vec3& eye);

// Whether a homogeneous light (object space: w = 1 a point, w = 0 a direction) lies in the
// caster's solid, where no light it sends reaches anything the eye sees (the eye is in empty
// space, and light cannot leave a closed solid). A directional light lies at infinity: buried
// in a room's solid, never in a bounded one's.
bool lightBuried(const Mesh& mesh, const SolidSide& side, const glm::vec4& light);

}  // namespace stencil
