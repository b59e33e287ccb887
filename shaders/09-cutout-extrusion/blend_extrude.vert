#version 330 core
// GPU extrusion by vertex blending (Kilgard, "Accelerated Stencil Shadow Extrusion via Vertex
// Blending"): every silhouette vertex is stored twice, with w = 1 (the near end of the volume) and
// w = 0 (the far end). The weight w blends two matrices: the model matrix keeps the near copy
// where it is, the model matrix times the extrusion to infinity sends the far copy to the point
// at infinity away from the light. The geometry never changes; only the second matrix does.
layout(location = 0) in vec4 position;  // xyz, and the blend weight in w

uniform mat4 nearTransform;  // viewProjection * model
uniform mat4 farTransform;   // viewProjection * model * extrusionToInfinity(light in model space)

void main() {
  vec4 p = vec4(position.xyz, 1.0);
  gl_Position = position.w * (nearTransform * p) + (1.0 - position.w) * (farTransform * p);
}
