#version 330 core
// World position and normal for per-pixel lighting. Light passes that add onto an ambient pass
// with depth test EQUAL need every pass to produce the same depths.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;
uniform mat4 viewProjection;  // (world - origin) to clip
uniform vec3 origin;  // world; near the eye far from the world's origin (gl/light_shading.h)

out vec3 worldPosition;
out vec3 worldNormal;
invariant gl_Position;

void main() {
  vec4 world = model * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(model) * normal;  // rigid model matrices only
  gl_Position = viewProjection * vec4(world.xyz - origin, 1.0);
}
