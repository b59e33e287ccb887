// Rooms and buried lights (geometry/solid.h): winding numbers of closed meshes, which side of a
// caster the eye is on, and whether a light is shut inside a solid.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/mesh.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/solid.h"
#include "geometry/weld.h"

namespace {

using namespace stencil;

Mesh turnedRound(Mesh m) {
  for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) std::swap(m.indices[i + 1], m.indices[i + 2]);
  return m;
}

TEST(Solid, WindingNumbersOfClosedMeshes) {
  const Mesh cube = makeCube(1.0f);
  EXPECT_EQ(windingNumber(cube, {0, 0, 0}), 1);
  EXPECT_EQ(windingNumber(cube, {0.99, -0.99, 0.5}), 1);
  EXPECT_EQ(windingNumber(cube, {1.01, 0, 0}), 0);
  EXPECT_EQ(windingNumber(cube, {1e6, 3, -2}), 0);
  EXPECT_EQ(windingNumber(turnedRound(cube), {0, 0, 0}), -1);
  EXPECT_EQ(windingNumber(turnedRound(cube), {0, 5, 0}), 0);
  const Mesh torus = makeTorus(1.0f, 0.25f, 32, 16);
  EXPECT_EQ(windingNumber(torus, {0, 0, 0}), 0) << "the hole";
  EXPECT_EQ(windingNumber(torus, {1, 0, 0}), 1) << "inside the ring";
  EXPECT_TRUE(onSurface(cube, {0, 1, 0.3})) << "on a face: a half";
  EXPECT_TRUE(onSurface(cube, {1, 1, 0.3})) << "on an edge: a quarter";
  EXPECT_FALSE(onSurface(cube, {0, 1.0001, 0.3}));
  EXPECT_FALSE(onSurface(cube, {0, 0.9999, 0.3}));
}

TEST(Solid, ABoxAroundTheEyeIsARoomWhicheverWayItFaces) {
  const Mesh box = makeCube(4.0f);
  const Mesh inward = turnedRound(box);
  EXPECT_TRUE(solidSide(box, false, {1, 1, 1}).room);
  EXPECT_TRUE(solidSide(inward, true, {1, 1, 1}).room);
  EXPECT_FALSE(solidSide(box, false, {9, 1, 1}).room);
  EXPECT_FALSE(solidSide(inward, true, {9, 1, 1}).room) << "a solid written inside out, seen from outside";
}

TEST(Solid, ALightOutsideTheRoomOrInsideASolidIsBuried) {
  const Mesh box = makeCube(4.0f);
  const SolidSide room = solidSide(box, false, {1, 1, 1});
  EXPECT_FALSE(lightBuried(box, room, {0.8f, 2.5f, 0.8f, 1.0f})) << "hanging in the room";
  EXPECT_TRUE(lightBuried(box, room, {-4.05f, 2.0f, -4.05f, 1.0f})) << "just outside a corner";
  EXPECT_TRUE(lightBuried(box, room, {0.0f, 1.0f, 0.0f, 0.0f})) << "the sun, outside every room";
  const SolidSide solid = solidSide(box, false, {9, 1, 1});
  EXPECT_TRUE(lightBuried(box, solid, {0, 0, 0, 1})) << "a light inside a solid box";
  EXPECT_FALSE(lightBuried(box, solid, {0, 9, 0, 1}));
  EXPECT_FALSE(lightBuried(box, solid, {0, 1, 0, 0}));
}

TEST(Solid, ARoomIsConvexWhenWhatItEnclosesIs) {
  const Mesh box = weldByPosition(makeCube(4.0f)).mesh;
  const Mesh inward = turnedRound(box);
  const EdgeAdjacency a = buildEdgeAdjacency(inward.indices, inward.positions.size());
  EXPECT_TRUE(isConvex(inward, a, true));
  EXPECT_FALSE(isConvex(inward, a, false)) << "read as facing out, every edge bends the wrong way";
  const Mesh stairs = turnedRound(weldByPosition(makeStairs(3, 1.0f, 0.2f, 0.3f)).mesh);
  EXPECT_FALSE(isConvex(stairs, buildEdgeAdjacency(stairs.indices, stairs.positions.size()), true));
}

}  // namespace
