// A scene's objects on the GPU, shaded by shaders/common/light.vert and light.frag one light at
// a time: what a lesson that adds lights pass by pass draws for each pass (lesson 16). Back-face
// culling is decided per object, the one GL state draw() sets: a closed object's back faces are
// hidden while the object is whole on screen; where the near plane cuts it, the eye looks through
// the cut at its back faces, and an open surface is seen from both sides, so those are drawn
// without culling.
#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "geometry/bounds.h"
#include "geometry/scene.h"
#include "gl/gpu_mesh.h"
#include "gl/shader.h"

namespace stencil {

class SceneMeshes {
 public:
  SceneMeshes();  // with a current context: builds the light program

  // Uploads every object of the scene. A casting object's prepared caster (SceneObject::caster)
  // says whether it is closed; others are prepared here to find out. Throws as prepareCaster does.
  void set(const Scene&);

  // The frame's placement, before draw(): each object's model matrix at `time` (seconds), and
  // which objects the near plane of viewProjection (world to clip, GL's convention) cuts.
  // Returns the number of closed objects it cuts, which draw() draws with their back faces.
  std::size_t place(const Scene&, double time, const glm::mat4& viewProjection);
  const std::vector<glm::mat4>& models() const { return models_; }  // per object, this frame

  // Every object of `scene` (the one given to set) lit by one light: world homogeneous `light`
  // (w = 1 a point, w = 0 the direction towards it), its colour, its radius (infinite: no
  // fall-off) and `ambient`, seen from `eye` (world) through viewProjection (the matrix the frame
  // draws with). Faces seen from behind are lit on the side the eye sees (rooms). Leaves
  // GL_CULL_FACE enabled and the light program bound.
  void draw(const Scene& scene, const glm::mat4& viewProjection, const glm::vec3& eye, const glm::vec4& light,
            const glm::vec3& colour, float radius, const glm::vec3& ambient);
  // The faces of every casting object whose side the eye sees is turned from `light` (world,
  // homogeneous): geometry/shadow_volume.h's facesTurnedFromLight, drawn with the light program
  // through viewProjection, so that their fragments have exactly the depths draw() gave them.
  // eye: world, homogeneous (w = 0: the direction towards a parallel view's eye). The caller
  // sets the stencil and depth state; no culling. Uploads the faces anew on each call. Returns
  // the triangles drawn.
  std::size_t drawTurnedFromLight(const Scene& scene, const glm::mat4& viewProjection, const glm::vec4& light,
                           const glm::vec4& eye);
  // Object i's triangles alone, with the program and state bound now.
  void drawObject(std::size_t i) const { meshes_[i]->draw(); }

 private:
  Program light_;
  std::vector<std::unique_ptr<GpuMesh>> meshes_;
  std::vector<bool> closed_;            // per object: a closed mesh
  std::vector<BoundingSphere> bounds_;  // per object, object space
  std::vector<glm::mat4> models_;       // per object, this frame
  glm::vec3 origin_{0.0f};              // draw()'s drawingOrigin, for drawTurnedFromLight
  std::vector<bool> cutByNearPlane_;    // per object, this frame
};

}  // namespace stencil
