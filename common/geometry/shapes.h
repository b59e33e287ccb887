#pragma once

// Procedural meshes for the lessons. All are centred at the origin, have unit
// outward normals and counter-clockwise front faces seen from outside.
//
// Closed shapes are watertight once welded (weldByPosition): vertices are only
// duplicated where a crease needs two normals, and the duplicates have
// bit-identical positions, so an exact weld recovers the closed manifold that
// stencil shadow volumes and capping need. Bad parameters (non-positive or
// non-finite sizes, too few segments) throw std::invalid_argument.

#include "geometry/mesh.h"

namespace stencil {

// Square in the y = 0 plane, normal +y, one-sided and open.
// (divisions+1)^2 vertices, 2*divisions^2 triangles. divisions >= 1.
Mesh makePlane(float halfSize, int divisions = 1);

// Square with a square hole, both centred, in the y = 0 plane, normal +y: a ground with a
// hole in it. 0 < innerHalfSize < outerHalfSize. 8 vertices, 8 triangles.
Mesh makeSquareRing(float outerHalfSize, float innerHalfSize);

// The square [-1,1]^2 in the z=0 plane, facing +z: drawn with an identity transform it
// covers the whole viewport (full-screen passes that read the stencil).
Mesh makeScreenQuad();

// Axis-aligned cube. 24 vertices (4 per face so each face keeps its own
// normal), 12 triangles; 8 vertices after welding.
Mesh makeCube(float halfExtent);

// UV sphere around the y axis with one vertex per pole (no degenerate
// triangles, nothing to weld). slices >= 3 around, stacks >= 2 from pole to
// pole. slices*(stacks-1)+2 vertices, 2*slices*(stacks-1) triangles.
Mesh makeSphere(float radius, int slices, int stacks);

// Ring torus around the y axis; 0 < minorRadius < majorRadius so it does not
// intersect itself. Both segment counts >= 3.
// majorSegments*minorSegments vertices, twice as many triangles.
Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments);

// Capped cylinder along y from -height/2 to +height/2, slices >= 3. Side and
// caps have separate rim vertices so caps get flat normals:
// 4*slices+2 vertices (2*slices+2 welded), 4*slices triangles.
Mesh makeCylinder(float radius, float height, int slices);

// Capped cone along y, base at -height/2, apex at +height/2, slices >= 3.
// The apex is split per slice so each side triangle gets its own apex normal:
// 3*slices+1 vertices (slices+2 welded), 2*slices triangles.
Mesh makeCone(float radius, float height, int slices);

// A solid flight of stairs: `steps` steps, each `rise` high and `run` deep, climbing along +x,
// `width` wide along z; closed down to the floor under the lowest step and at the back of the
// highest. Centred like the others: x and y from -half to +half of the whole flight.
// Every face has its own vertices (flat normals): 16*steps+8 vertices, 12*steps triangles;
// 6*steps+2 after welding.
Mesh makeStairs(int steps, float width, float rise, float run);

}  // namespace stencil
