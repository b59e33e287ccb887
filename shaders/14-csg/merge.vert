#version 330 core
// common/light.vert (the same position, bit for bit: gl_Position is invariant), with the
// primitive's index passed on as a flat varying: a uniform that only the vertex stage reads, so
// draws of different primitives share one fragment-stage state (llvmpipe copies that state,
// 33 KB, at each change).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;
uniform mat4 viewProjection;  // (world - origin) to clip
uniform vec3 origin;          // world; near the eye far from the world's origin (gl/light_shading.h)
uniform int primitive;        // this primitive's index + 1

out vec3 worldPosition;
out vec3 worldNormal;
flat out int fragmentPrimitive;
invariant gl_Position;

void main() {
  vec4 world = model * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(model) * normal;  // rigid model matrices only
  fragmentPrimitive = primitive;
  gl_Position = viewProjection * vec4(world.xyz - origin, 1.0);
}
