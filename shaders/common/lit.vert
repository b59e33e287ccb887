#version 330 core
// Position and normal to world space for simple diffuse lighting.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;
uniform mat4 viewProjection;

out vec3 worldNormal;

void main() {
  // Models here use uniform scale only, so the model matrix transforms normals too.
  worldNormal = mat3(model) * normal;
  gl_Position = viewProjection * model * vec4(position, 1.0);
}
