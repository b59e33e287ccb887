// Lesson 14 around its algorithms: the lesson's own scenes (the demo's two solids, the rounded
// cube, grids and a rack after OpenCSG's...), a scene file's csg line, the cameras, options and variants.
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "csg_lesson.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "gl/errors.h"

namespace stencil::csg_lesson {
namespace {

CsgScene twoSolids(int op) {
  using glm::translate;
  const glm::mat4 id(1.0f);
  CsgScene s;
  s.primitives.push_back(
      {"A", makeCube(0.8f), glm::rotate(id, glm::radians(25.0f), {0, 1, 0}), {0.95f, 0.55f, 0.2f}});
  s.primitives.push_back(
      {"B", makeSphere(0.85f, 48, 24), translate(id, {0.95f, 0.45f, 0.25f}), {0.25f, 0.5f, 0.95f}});
  const char* ops[] = {"A + B", "A * B", "A - B", "B - A"};
  s.expression = ops[op];
  return s;
}

CsgScene goldfeatherScene(int scene, int op, int side) {
  using glm::rotate;
  using glm::translate;
  const glm::mat4 id(1.0f);
  CsgScene s;
  switch (scene) {
    case 0: return twoSolids(op);
    case 1: {  // the rounded cube with three holes through it
      s.primitives.push_back({"cube", makeCube(1.0f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back({"sphere", makeSphere(1.35f, 48, 24), id, {0.25f, 0.5f, 0.95f}});
      const Mesh cylinder = makeCylinder(0.55f, 3.0f, 32);
      s.primitives.push_back(
          {"x", cylinder, rotate(id, glm::radians(90.0f), {0, 0, 1}), {0.3f, 0.8f, 0.35f}});
      s.primitives.push_back({"y", cylinder, id, {0.85f, 0.3f, 0.6f}});
      s.primitives.push_back(
          {"z", cylinder, rotate(id, glm::radians(90.0f), {1, 0, 0}), {0.9f, 0.85f, 0.3f}});
      s.expression = "cube * sphere - (x + y + z)";
      return s;
    }
    case 2:  // a corner scooped out of a cube, a small cube left standing in the scoop
      s.primitives.push_back({"A", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back(
          {"B", makeSphere(0.95f, 48, 24), translate(id, {0.7f, 0.7f, 0.7f}), {0.25f, 0.5f, 0.95f}});
      s.primitives.push_back(
          {"C", makeCube(0.3f), translate(id, {0.55f, 0.55f, 0.55f}), {0.3f, 0.8f, 0.35f}});
      s.expression = "A - (B - C)";
      return s;
    case 4: {  // a box minus a grid of spheres (5x5: 25 trimmers per target), after OpenCSG's grids
      s.primitives.push_back(
          {"box", makeCube(1.0f), glm::scale(id, {1.3f, 0.4f, 1.3f}), {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh sphere = makeSphere(0.3f, 24, 12);
      const auto place = [side](int j) {  // -1..1 across the box, the middle for one
        return side == 1 ? 0.0f : -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(side - 1);
      };
      for (int i = 0; i < side * side; ++i) {
        const std::string name = "s" + std::to_string(i);
        const glm::vec3 at(place(i % side), 0.4f, place(i / side));
        s.primitives.push_back({name, sphere, translate(id, at), {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    case 5:
    case 6:
    case 9: {  // a pocket whose floor is B's and whose top lies in A's top face (5), 0.01 above it (6)
               // or 0.01 below it (9: the pocket closed, the tie's other outcome)
      const float grow = scene == 6 ? 0.01f : scene == 9 ? -0.01f : 0.0f;
      s.primitives.push_back({"A", makeCube(0.8f), id, {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back(
          {"B",
           makeCube(1.0f),
           glm::scale(translate(id, {0.3f, 0.5f + 0.5f * grow, 0.3f}), {0.35f, 0.3f + 0.5f * grow, 0.35f}),
           {0.25f, 0.5f, 0.95f}});
      s.expression = "A - B";
      return s;
    }
    case 7: {  // a box minus 7x7x7 small boxes (OpenCSG's cube rack subtracts spheres)
      s.primitives.push_back({"box", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh cube = makeCube(0.1f);
      const auto place = [](int j) { return -1.0f + (2.0f * static_cast<float>(j) + 1.0f) / 7.0f; };
      for (int i = 0; i < 343; ++i) {
        const std::string name = "c" + std::to_string(i);
        s.primitives.push_back({name,
                                cube,
                                translate(id, {place(i % 7), place(i / 7 % 7), place(i / 49)}),
                                {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    case 8: {  // a box minus 27 spheres, the outer ones cutting its faces (after OpenCSG's)
      s.primitives.push_back({"box", makeCube(0.9f), id, {0.95f, 0.55f, 0.2f}});
      s.expression = "box";
      const Mesh sphere = makeSphere(0.32f, 24, 12);
      for (int i = 0; i < 27; ++i) {
        const std::string name = "s" + std::to_string(i);
        const glm::vec3 at(0.9f * static_cast<float>(i % 3 - 1), 0.9f * static_cast<float>(i / 3 % 3 - 1),
                           0.9f * static_cast<float>(i / 9 - 1));
        s.primitives.push_back({name, sphere, translate(id, at), {0.25f, 0.5f, 0.95f}});
        s.expression += " - " + name;
      }
      return s;
    }
    default:  // a ring cut through on its near side: the far side shows through the cut
      s.primitives.push_back({"T",
                              makeTorus(1.1f, 0.4f, 48, 24),
                              rotate(id, glm::radians(-28.0f), {1, 0, 0}),
                              {0.95f, 0.55f, 0.2f}});
      s.primitives.push_back({"B",
                              makeCube(0.5f),
                              glm::scale(translate(id, {0.3f, 0.2f, 1.05f}), {0.8f, 1.6f, 1.2f}),
                              {0.25f, 0.5f, 0.95f}});
      s.expression = "T - B";
      s.spinDegPerSecond = 0.0f;  // the cut stays in front
      return s;
  }
}

// A scene file's csg line (docs/scenes.md) over its objects, at their models at `time`; the
// file's own motion (spin, bob) turns them, so the lesson adds none.
CsgScene fileScene(const Scene& file, double time) {
  CsgScene s;
  for (const SceneObject& o : file.objects)
    s.primitives.push_back({o.name, o.mesh, o.modelAt(time), o.colour});
  s.expression = file.csg;
  s.spinDegPerSecond = 0.0f;
  return s;
}

}  // namespace

void Csg::startCounts(Frame& f, const SumOfProducts& sop, std::initializer_list<const char*> zeros,
                      bool beforePruning) {
  f.count("products", sop.products.size());
  f.count("literals", sop.literals());
  if (beforePruning) f.count("products_before_pruning", sop.productsBeforePruning);
  for (const char* name : zeros) f.count(name, 0);
}

CsgScene sceneFor(const Frame& f, const Scene* fromFile) {
  const int method = f.option("method");
  if (fromFile && method == kTwoSolids)
    throw UsageError(
        "--scene: method 0 draws the demo's two solids; the scene's csg expression needs "
        "--set method=1, 2, 3 or 4");
  if (fromFile) return fileScene(*fromFile, f.time);
  if (method == kTwoSolids) return twoSolids(f.option("op"));
  return goldfeatherScene(f.option("scene"), f.option("op"), f.option("grid"));
}

namespace {

// Low over the ring's near side, looking through the cut at the far side: two front faces of
// the torus along those rays.
OrbitCamera throughTheCut() {
  OrbitCamera c;
  c.target = {0.0f, 0.0f, 0.0f};
  c.distance = 5.0f;
  c.azimuthDeg = 15.0f;
  c.elevationDeg = 16.0f;
  c.farPlane = 30.0f;
  return c;
}

// From A's side of B: the bite A takes out of B faces this way.
OrbitCamera fromTheLeft() {
  OrbitCamera c;
  c.target = {0.45f, 0.2f, 0.1f};
  c.distance = 5.5f;
  c.azimuthDeg = -55.0f;
  c.elevationDeg = 30.0f;
  c.farPlane = 30.0f;
  return c;
}

// The eye inside B, outside A, looking at A: B's front faces lie behind the eye, only its back
// faces are drawn in front of A.
OrbitCamera insideB() {
  OrbitCamera c;
  c.target = {0.0f, 0.0f, 0.0f};
  c.distance = 1.78f;  // the eye 0.7 from B's centre, on the far side from A; B's radius 0.85
  c.azimuthDeg = 75.4f;
  c.elevationDeg = 24.6f;
  c.fovyDeg = 70.0f;
  c.farPlane = 30.0f;
  return c;
}

}  // namespace

// SCS's intersection step takes the furthest front face for where a ray enters a primitive, and
// its subtraction moves past one back face: both hold for convex primitives only. Only the
// primitives the expression draws are judged: an object the csg line leaves out is never drawn.
static std::string scsRefusal(const OptionsChosen& o) {
  if (o.value("method") != kScs) return {};
  std::vector<std::string> names;
  std::vector<const Mesh*> meshes;
  CsgScene own;
  if (o.scene) {
    for (const SceneObject& object : o.scene->objects) names.push_back(object.name), meshes.push_back(&object.mesh);
  } else {
    own = goldfeatherScene(o.value("scene"), o.value("op"), o.value("grid"));
    for (const Primitive& p : own.primitives) names.push_back(p.name), meshes.push_back(&p.mesh);
  }
  const CsgTree tree = parseCsg(o.scene ? o.scene->csg : own.expression, names);
  const std::vector<bool> used = primitivesUsed(normalize(tree), names.size());
  for (std::size_t i = 0; i < names.size(); ++i)
    if (used[i] && !convexMesh(*meshes[i]))
      return "method 3 (SCS) takes convex primitives only; '" + names[i] + "' is concave: use method 1, 2 or 4";
  return {};
}

bool convexMesh(const Mesh& mesh) {
  const PreparedCaster welded = prepareCaster(mesh);
  return isConvex(welded.mesh, welded.adjacency);
}

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "14-csg";
  info.title = "Constructive solid geometry";
  info.summary =
      "Which faces of a solid lie inside another, counted in the stencil: union, intersection and\n"
      "differences of two convex solids; any expression as a sum of products by Goldfeather's parity bits,\n"
      "with a convexity bound or the layered count, or by SCS's subtraction sequences.";
  info.options = {
      {"method", 'M',
       "0 two convex solids (the demo), 1 Goldfeather, 2 layered Goldfeather,\n"
       "      3 SCS (convex primitives only), 4 automatic (per product: SCS until a cycle changes\n"
       "      nothing where every primitive is convex, else layered Goldfeather; scissored)",
       kTwoSolids, 4},
      {"op", 'O', "two solids: 0 A + B, 1 A * B, 2 A - B, 3 B - A", kAMinusB, 3},
      {"scene", 'N',
       "the scene of methods 1 to 4: 0 the two solids (by op), 1 cube * sphere - three cylinders,\n"
       "      2 A - (B - C), 3 a torus (convexity 2) minus a box, 4 a box minus a grid of spheres,\n"
       "      5 a pocket whose top lies in A's top face (coincident faces), 6 the same, B 0.01 taller,\n"
       "      7 the cube rack: a box minus 343 boxes, 8 a box minus a 3x3x3 grid of spheres,\n"
       "      9 scene 5 with B 0.01 shorter: the pocket closed (which rounding may give scene 5)",
       0, 9},
      {"grid", 'G', "scene 4: spheres along each side of the grid (the sweep's primitive count)", 5, 7, 1},
      {"convexity", 'C',
       "Goldfeather: the layers tried per target primitive; 0: 1 for a convex mesh, else the most\n"
       "      of its target faces a pixel's ray crosses (counted); 1-8 a bound given",
       0, 8, 0},
      {"queries", 'Q', "Goldfeather: stop at the first layer an occlusion query finds empty", 0},
      {"stencil", 'T', "methods 0 to 2: trim by the stencil (off: every candidate surface kept, the result wrong)", 1},
      {"oracle", 'K',
       "check the depth and the primitive each pixel shows against a CPU CSG ray cast\n"
       "      (--stats reports oracle_*; headless, exit 1 where a pixel off the edges differs)",
       0},
  };
  info.variants = {
      {"a-minus-b", "A - B: A's front faces outside B, B's back faces inside A", {}},
      {"union", "A + B: both drawn, the depth test alone", {{"op", kUnion}}},
      {"intersection", "A * B: A's front faces inside B, B's inside A", {{"op", kIntersection}}},
      {"b-minus-a",
       "B - A: B's front faces outside A, A's back faces inside B, seen from A's side",
       {{"op", kBMinusA}},
       {},
       fromTheLeft()},
      {"no-stencil", "A - B without the count: A's front and B's back faces all kept", {{"stencil", 0}}},
      {"goldfeather", "A - B by Goldfeather's parity bits: the same picture", {{"method", kGoldfeather}}},
      {"goldfeather-rounded-cube",
       "cube * sphere - three cylinders: one product of five",
       {{"method", kGoldfeather}, {"scene", 1}}},
      {"goldfeather-nested",
       "A - (B - C) = A - B + A * C: two products merged by depth",
       {{"method", kGoldfeather}, {"scene", 2}}},
      {"goldfeather-torus-convexity-1",
       "a torus minus a box with a convexity bound of 1: the torus' second layer never tried",
       {{"method", kGoldfeather}, {"scene", 3}, {"convexity", 1}},
       {},
       throughTheCut()},
      {"goldfeather-torus",
       "the torus with a convexity bound of 2",
       {{"method", kGoldfeather}, {"scene", 3}, {"convexity", 2}},
       {},
       throughTheCut()},
      {"layered-torus",
       "layered Goldfeather on the torus: k from the layers' depth complexity",
       {{"method", kLayered}, {"scene", 3}},
       {},
       throughTheCut()},
      {"layered-rounded-cube",
       "layered Goldfeather on the rounded cube",
       {{"method", kLayered}, {"scene", 1}}},
      {"eye-in-b", "A - B with the eye inside B: the count starts at 0 outside B", {}, {}, insideB()},
      {"goldfeather-eye-in-b",
       "Goldfeather's A - B with the eye inside B",
       {{"method", kGoldfeather}},
       {},
       insideB()},
      {"scs-rounded-cube",
       "SCS: the intersection by counting, the cylinders by a subtraction sequence",
       {{"method", kScs}, {"scene", 1}}},
      {"scs-grid",
       "SCS on the box minus 25 spheres: a sequence of 25 * 24 + 1 = 601 subtractions",
       {{"method", kScs}, {"scene", 4}}},
      {"coincident",
       "A - B where B's top face lies in A's: tied depths, and a face at the surface's depth is not behind it",
       {{"method", kGoldfeather}, {"scene", 5}}},
      {"coincident-grown",
       "the same with B 0.01 taller: a clean pocket",
       {{"method", kGoldfeather}, {"scene", 6}}},
      {"layered-rack",
       "layered Goldfeather on the cube rack: 344 primitives, ids past 255 recorded modulo 255",
       {{"method", kLayered}, {"scene", 7}}},
      {"goldfeather-grid",
       "a box minus 25 spheres: 25 trimming primitives, more than the 8 stencil bits, flushed every 8",
       {{"method", kGoldfeather}, {"scene", 4}}},
      {"layered-grid", "the box minus 25 spheres, layered", {{"method", kLayered}, {"scene", 4}}},
  };
  info.reversedDepth = true;  // a float depth buffer, reversed, where the driver has clip control
  info.passes = {"surface", "count",  "keep",      "far",      "layers",
                 "select",  "parity", "intersect", "subtract", "merge"};
  info.camera.target = {0.2f, 0.2f, 0.2f};
  info.camera.distance = 5.5f;
  info.camera.azimuthDeg = 30.0f;
  info.camera.elevationDeg = 25.0f;
  info.camera.farPlane = 30.0f;
  // A scene file is drawn by the automatic method unless a method is chosen; the options that pick
  // the lesson's own scenes, and the demo's two solids, have nothing to draw it with.
  info.sceneSettings = {{"method", kAutomatic}};
  info.refuseOptions = [defaults = info.options](const OptionsChosen& o) -> std::string {
    const auto byDefault = [&](const char* name) {
      return std::any_of(defaults.begin(), defaults.end(),
                         [&](const Option& d) { return d.name == name && d.value == o.value(name); });
    };
    // Only Goldfeather's passes (and the demo's) have a trim to leave out.
    if (!byDefault("stencil") && (o.value("method") == kScs || o.value("method") == kAutomatic))
      return std::string(o.set("stencil") ? "--set stencil=0" : "--variant: it sets stencil=0, and") +
             (o.set("stencil") ? ":" : "") + " methods 3 and 4 have no untrimmed picture to show; it needs --set method=0, 1 or 2";
    if (!o.scene) return scsRefusal(o);
    for (const char* own : {"scene", "op", "grid"})
      if (o.set(own) || !byDefault(own))
        return (o.set(own) ? std::string("--set ") + own + ": it picks" : std::string("--variant: it sets ") + own + ", which picks") +
               " among the lesson's own scenes; --scene " + o.scene->file.string() + " is the scene";
    if (o.value("method") == kTwoSolids)
      return "--scene: method 0 draws the demo's two solids; the scene's csg expression needs "
             "--set method=1, 2, 3 or 4";
    return scsRefusal(o);
  };
  return info;
}

}  // namespace stencil::csg_lesson
