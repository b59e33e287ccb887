#version 330 core
// Shadow-volume triangles in the caster's own space, homogeneous (w = 0 at infinity), moved
// exactly as common/light.vert moves the caster: the light cap lies on the caster's lit faces,
// and z-fail counts it right only if it gets the very same depths there.
layout(location = 0) in vec4 position;

uniform mat4 model;
uniform mat4 viewProjection;  // (world - origin) to clip
uniform vec3 origin;  // world, as common/light.vert's
invariant gl_Position;

void main() {
  vec4 world = model * position;
  gl_Position = viewProjection * vec4(world.xyz - origin * world.w, world.w);
}
