// Lesson 14's refusals: what no method can draw right is one line (UsageError: exit 2), never a
// wrong picture. Decided from the geometry where it can be (the near and far planes against the
// primitives the expression uses, the eye inside the result), else from what the stencil counted:
// a count of target faces that reached 255, where the 8-bit stencil stops.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "csg_lesson.h"
#include "geometry/depth_complexity.h"
#include "geometry/solid.h"
#include "gl/errors.h"

namespace stencil::csg_lesson {
namespace {

// Whether the window segment p-q (normalized device x, y) meets the square [-1, 1]^2 (Liang and
// Barsky's clip).
bool segmentMeetsSquare(glm::dvec2 p, glm::dvec2 q) {
  const glm::dvec2 d = q - p;
  double t0 = 0.0, t1 = 1.0;
  const double edges[4][2] = {{-d.x, p.x + 1.0}, {d.x, 1.0 - p.x}, {-d.y, p.y + 1.0}, {d.y, 1.0 - p.y}};
  for (const auto& [along, room] : edges) {
    if (along == 0.0) {
      if (room < 0.0) return false;
    } else if (along < 0.0) {
      t0 = std::max(t0, room / along);
    } else {
      t1 = std::min(t1, room / along);
    }
  }
  return t0 <= t1;
}

// Whether the near plane's rectangle (the part of the near plane the frame sees) meets the solid
// that the closed mesh at `toClip` (world to GL's clip space, the model included) bounds: one of
// its triangles crosses the rectangle, or, crossing none, the rectangle lies inside it (its centre
// does: a ray from there crosses the surface an odd number of times).
bool nearRectangleMeets(const Mesh& mesh, const glm::dmat4& model, const glm::dmat4& viewProjection) {
  const glm::dmat4 toClip = viewProjection * model;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::dvec4 c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = toClip * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + k]]), 1.0);
    std::vector<glm::dvec2> on;  // where the triangle's edges meet the near plane z = -w
    for (int k = 0; k < 3; ++k) {
      const glm::dvec4 &a = c[k], &b = c[(k + 1) % 3];
      const double da = a.z + a.w, db = b.z + b.w;
      glm::dvec4 p = a;
      if (da != 0.0 && (da < 0.0) == (db < 0.0)) continue;
      if (da != 0.0) p = a + (b - a) * (da / (da - db));
      if (p.w > 0.0) on.emplace_back(p.x / p.w, p.y / p.w);
    }
    for (std::size_t i = 0; i < on.size(); ++i)
      for (std::size_t j = i; j < on.size(); ++j)
        if (segmentMeetsSquare(on[i], on[j])) return true;
  }
  const glm::dmat4 fromClip = glm::inverse(viewProjection);
  const glm::dvec4 centre = fromClip * glm::dvec4(0.0, 0.0, -1.0, 1.0);
  const glm::dvec3 o = glm::dvec3(centre) / centre.w,
                   dir = glm::normalize(glm::dvec3(0.3123, 0.5377, 0.7836));
  int crossings = 0;  // Moller and Trumbore's ray-triangle test
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::dvec3 v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + k]]), 1.0));
    const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0], h = glm::cross(dir, e2);
    const double det = glm::dot(e1, h);
    if (det == 0.0) continue;
    const glm::dvec3 s = o - v[0], q = glm::cross(s, e1);
    const double u = glm::dot(s, h) / det, w = glm::dot(dir, q) / det;
    if (u >= 0.0 && w >= 0.0 && u + w <= 1.0 && glm::dot(e2, q) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

// The first product that holds the eye (inside each of its intersected primitives and outside each
// of its subtracted ones, by the winding numbers of their meshes around it), or none.
const CsgProduct* productHoldingEye(const CsgScene& scene, const std::vector<glm::mat4>& models,
                                    const SumOfProducts& sop, const glm::vec3& eye) {
  std::vector<int> inside(scene.primitives.size(), -1);  // per primitive: not yet decided, 0 or 1
  const auto holds = [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    if (inside[k] < 0) {
      const glm::dvec4 there = glm::inverse(glm::dmat4(models[k])) * glm::dvec4(glm::dvec3(eye), 1.0);
      inside[k] = windingNumber(scene.primitives[k].mesh, glm::dvec3(there)) != 0;
    }
    return inside[k] == 1;
  };
  for (const CsgProduct& p : sop.products)
    if (!p.intersected.empty() && std::all_of(p.intersected.begin(), p.intersected.end(), holds) &&
        std::none_of(p.subtracted.begin(), p.subtracted.end(), holds))
      return &p;
  return nullptr;
}

// The names, quoted and joined: 'a', 'b' and 'c'.
std::string quotedList(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + ("'" + names[i] + "'");
  return text;
}

}  // namespace

std::vector<bool> primitivesUsed(const SumOfProducts& sop, std::size_t count) {
  std::vector<bool> used(count, false);
  for (const CsgProduct& p : sop.products) {
    for (int a : p.intersected) used[static_cast<std::size_t>(a)] = true;
    for (int s : p.subtracted) used[static_cast<std::size_t>(s)] = true;
  }
  return used;
}

std::string productText(const CsgProduct& p, const CsgScene& scene) {
  constexpr std::size_t kNamed = 6;  // a product of hundreds is named by its first few
  std::string text;
  std::size_t named = 0;
  for (int a : p.intersected)
    if (named++ < kNamed)
      text += (text.empty() ? "" : " * ") + scene.primitives[static_cast<std::size_t>(a)].name;
  for (int s : p.subtracted)
    if (named++ < kNamed) text += " - " + scene.primitives[static_cast<std::size_t>(s)].name;
  if (p.size() > kNamed) text += " ... (" + std::to_string(p.size()) + " primitives)";
  return text;
}

// What no method can draw, refused (UsageError) rather than drawn wrong, judged on the primitives
// the expression uses:
//   - the near plane cutting the result: where the near plane's point lies inside the result the
//     ray cast sees a cap there, and no method draws one. It can lie inside a product only where it
//     lies inside each of the product's intersected primitives: refused where the near plane's
//     rectangle meets all of them (one cut by it, or holding it all). Where the eye itself lies
//     inside the result a nearer near plane cuts it too: the line says so. A subtracted primitive
//     the near plane cuts is drawn right (its faces counted behind the surface: z-fail).
//   - the far plane cutting a primitive without depth clamping (frontFace), as in a browser
//     without EXT_depth_clamp: the faces past it would be lost to the counts.
//   - a near plane nearer than 2^-24 of the farthest the solid reaches along the view (refuseNear).
void Csg::refuseCuts(const Frame& f, const CsgScene& scene, const SumOfProducts& sop) const {
  refuseNear(f);
  const glm::dmat4 viewProjection = glm::dmat4(f.projection) * glm::dmat4(view_);
  std::vector<int> meets(scene.primitives.size(), -1);  // per primitive: not yet decided, 0 or 1
  for (const CsgProduct& p : sop.products) {
    bool all = !p.intersected.empty();
    for (int a : p.intersected) {
      const auto i = static_cast<std::size_t>(a);
      if (meets[i] < 0)
        meets[i] = nearRectangleMeets(scene.primitives[i].mesh, glm::dmat4(models_[i]), viewProjection);
      all = all && meets[i] == 1;
      if (!all) break;
    }
    if (!all) continue;
    if (const CsgProduct* holding = productHoldingEye(scene, models_, sop, f.eye))
      throw UsageError("the eye is inside '" + productText(*holding, scene) +
                       "', part of the result: the near plane cuts the result at any near distance, and no "
                       "method draws the cap the cut leaves there; move the eye out of it");
    throw UsageError("the near plane cuts '" +
                     scene.primitives[static_cast<std::size_t>(p.intersected.front())].name +
                     "', an intersected primitive: the result may begin at the near plane, and no method "
                     "draws the cap the cut leaves there; move the eye back or make near smaller");
  }
  const std::vector<bool> used = primitivesUsed(sop, scene.primitives.size());
  if (!hasFeature(f.features, Feature::DepthClamp))
    for (std::size_t i = 0; i < scene.primitives.size(); ++i)
      if (used[i] && reachesPastFar(f, static_cast<int>(i)))
        throw UsageError("the far plane may cut '" + scene.primitives[i].name +
                         "', and without depth clamping (EXT_depth_clamp) its faces past it are lost to the "
                         "counts; make far larger");
}

// A perspective frame's near plane n against the farthest point D of the primitives' bounding
// spheres along the view. GL's depth mapping puts distance d at 1 - n/d (times f / (f - n) for a
// far plane at f), held in steps of 2^-24 (a float just below 1, a 24-bit buffer): Frame::projection
// is that mapping in float, so is the depth without clip control, and the oracle's depths are its
// window depths. Past n 2^24 a distance is the far plane's depth, and -(f + n)/(f - n) rounds to
// within a step of -1, which moves a far plane there (far 30 with near 1e-6 lay at 16.8). Refused
// below D 2^-24: every point of the solid then lies a step or more in front of the far plane.
void Csg::refuseNear(const Frame& f) const {
  const glm::dmat4 p(f.projection);
  if (p[2][3] != -1.0 || p[3][3] != 0.0) return;  // parallel: depth linear in the distance
  const double near = p[3][2] / (p[2][2] - 1.0);
  double farthest = 0.0;
  for (std::size_t i = 0; i < models_.size(); ++i) {
    const BoundingSphere s = worldSphereOf(static_cast<int>(i));
    farthest = std::max(farthest, -(glm::dmat4(view_) * glm::dvec4(glm::dvec3(s.centre), 1.0)).z + s.radius);
  }
  const double bound = std::ldexp(farthest, -24);
  if (near >= bound) return;
  std::ostringstream out;
  out.precision(3);
  out << "the near plane (" << near << ") is nearer than 2^-24 times the distance of the solid's farthest point "
      << "along the view (" << farthest << "): GL's depth mapping puts distance d at 1 - near/d, held in steps of "
      << "2^-24 (a float just below 1, or 24 bits), so that point would lie at the far plane's depth; make near at "
      << "least " << bound;
  throw UsageError(out.str());
}

// A count of target faces that reached 255 (the k-th layer's selection, or lesson 13's count
// before the layers): INCR stops there, so 255 reads as 255 or more, and a layer past the 255th
// could never be selected (EQUAL 255 passes every fragment from the 256th on). Refused, naming
// the product (method 1: the target it counts alone), the most of those faces a pixel's ray
// crosses (counted again on the CPU, geometry/depth_complexity.h) and what to split; the GL
// state is put back first (abandonFrame): in the window the next frame is drawn with the
// settings before.
void Csg::refuseDeepCount(Frame& f, const CsgProduct& p, const std::vector<int>& targets) {
  abandonFrame(f);
  const CsgScene scene = sceneFor(f, fromFile_);
  std::vector<OracleObject> fronts, backs;
  for (int x : targets)
    (subtracted(p, x) ? backs : fronts)
        .push_back({&scene.primitives[static_cast<std::size_t>(x)].mesh, models_[static_cast<std::size_t>(x)],
                    true, true});
  const std::size_t pixels = static_cast<std::size_t>(f.size.x) * static_cast<std::size_t>(f.size.y);
  std::vector<std::uint32_t> crossed(pixels, 0);
  for (const auto& [objects, faces] :
       {std::pair{&fronts, FacesCounted::Front}, std::pair{&backs, FacesCounted::Back}}) {
    if (objects->empty()) continue;
    const std::vector<std::uint32_t> n = depthComplexity(*objects, f.projection * f.view, f.size, faces);
    for (std::size_t i = 0; i < n.size(); ++i) crossed[i] += n[i];
  }
  const std::uint32_t most = *std::max_element(crossed.begin(), crossed.end());
  const std::string count = most >= 255 ? std::to_string(most) : "255 or more";
  const int method = f.option("method");
  const auto name = [&](int i) { return scene.primitives[static_cast<std::size_t>(i)].name; };
  if (method == kGoldfeather) {
    const int x = targets.front();
    throw UsageError("method 1 (Goldfeather) counts the layers of '" + name(x) + "' (its " +
                     (subtracted(p, x) ? "back" : "front") +
                     " faces along each pixel's ray) in the 8-bit stencil, 254 at most; a ray crosses " +
                     count + " of them: split '" + name(x) +
                     "' into objects joined by '+', each of fewer layers");
  }
  // A concave intersected primitive split in a union makes products of its own, each counted
  // apart; a subtracted one split stays in this product, and method 1 counts each target alone.
  std::vector<std::string> concaveIntersected, concaveSubtracted;
  for (int x : targets)
    if (!convex_[static_cast<std::size_t>(x)])
      (subtracted(p, x) ? concaveSubtracted : concaveIntersected).push_back(name(x));
  std::string remedy = "methods 1, 3 and 4 draw a product of convex primitives without this count";
  if (!concaveIntersected.empty())
    remedy = "split " + quotedList(concaveIntersected) +
             " into objects joined by '+', each then a product of its own";
  if (!concaveSubtracted.empty())
    remedy = (concaveIntersected.empty() ? "" : remedy + ", and ") +
             "use method 1, which counts the layers of " + quotedList(concaveSubtracted) + " apart";
  throw UsageError(
      "method " + std::to_string(method) + " draws the product '" + productText(p, scene) +
      "' by layered Goldfeather, which counts its target faces (its intersected primitives' front "
      "faces, its subtracted ones' back faces) along each pixel's ray in the 8-bit stencil, 254 at "
      "most; a ray crosses " +
      count + " of them: " + remedy);
}

}  // namespace stencil::csg_lesson
