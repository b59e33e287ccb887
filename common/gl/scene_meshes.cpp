#include "gl/scene_meshes.h"

#include "geometry/fast_shadows.h"
#include "geometry/shadow_volume.h"
#include "gl/light_shading.h"

namespace stencil {

SceneMeshes::SceneMeshes() : light_("common/light.vert", "common/light.frag") {}

void SceneMeshes::set(const Scene& scene) {
  meshes_.clear();
  closed_.clear();
  bounds_.clear();
  for (const SceneObject& o : scene.objects) {
    meshes_.push_back(std::make_unique<GpuMesh>(o.mesh));
    bounds_.push_back(boundingSphereOf(o.mesh.positions));
    const bool prepared = o.casts && !o.caster.mesh.positions.empty();
    closed_.push_back(prepared ? o.caster.report.closedManifold()
                               : prepareCaster(o.mesh).report.closedManifold());
  }
}

std::size_t SceneMeshes::place(const Scene& scene, double time, const glm::mat4& viewProjection) {
  const Plane nearPlane = viewFrustum(viewProjection, false).planes[4];
  const float length = glm::length(glm::vec3(nearPlane));
  models_.clear();
  cutByNearPlane_.assign(scene.objects.size(), false);
  std::size_t closedCut = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    models_.push_back(scene.objects[i].modelAt(time));
    const BoundingSphere world = worldBounds(bounds_[i], models_[i]);
    cutByNearPlane_[i] = (glm::dot(glm::vec3(nearPlane), world.centre) + nearPlane.w) / length < world.radius;
    closedCut += cutByNearPlane_[i] && closed_[i] ? 1 : 0;
  }
  return closedCut;
}

void SceneMeshes::draw(const Scene& scene, const glm::mat4& viewProjection, const glm::vec3& eye,
                       const glm::vec4& light, const glm::vec3& colour, float radius,
                       const glm::vec3& ambient) {
  // The light's bounds (docs/scenes.md); a wall seen from inside a room is lit on the side the eye sees.
  origin_ = drawingOrigin(eye);
  setLightShading(light_, {.viewProjection = viewProjection,
                           .origin = origin_,
                           .eye = eye,
                           .light = light,
                           .lightColour = colour,
                           .ambient = ambient,
                           .radius = radius,
                           .twoSided = true});
  // A mirroring model matrix (a negative scale) turns the object's winding round on screen, on top
  // of whatever the caller's front face says for the view.
  GLint viewFront = GL_CCW;
  glGetIntegerv(GL_FRONT_FACE, &viewFront);
  const GLenum otherFront = viewFront == GL_CCW ? GL_CW : GL_CCW;
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    light_.set("model", models_[i]);
    light_.set("colour", scene.objects[i].colour);
    if (closed_[i] && !cutByNearPlane_[i])
      glEnable(GL_CULL_FACE);  // a closed object's back faces are hidden anyway
    else                       // an open surface is seen from both sides; a cut one through the cut
      glDisable(GL_CULL_FACE);
    glFrontFace(glm::determinant(glm::mat3(models_[i])) < 0.0f ? otherFront : static_cast<GLenum>(viewFront));
    meshes_[i]->draw();
  }
  glFrontFace(static_cast<GLenum>(viewFront));
  glEnable(GL_CULL_FACE);
}

std::size_t SceneMeshes::drawTurnedFromLight(const Scene& scene, const glm::mat4& viewProjection, const glm::vec4& light,
                                      const glm::vec4& eye) {
  setLightShading(light_, {.viewProjection = viewProjection, .origin = origin_});  // the positions draw() gave
  glDisable(GL_CULL_FACE);
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.casts) continue;
    const glm::mat4 toObject = glm::inverse(models_[i]);
    Mesh turned{o.mesh.positions, o.mesh.normals, facesTurnedFromLight(o.mesh, toObject * light, toObject * eye)};
    if (turned.indices.empty()) continue;
    light_.set("model", models_[i]);
    GpuMesh(turned).draw();
    triangles += turned.triangleCount();
  }
  return triangles;
}

}  // namespace stencil
