#version 330 core
// The doubled vertex array (McGuire et al. 2003): every caster vertex is stored twice, with w = 1
// and w = 0. The w = 1 copy stays where it is; the w = 0 copy becomes the point at infinity away
// from the light: p - L for a point light, -L for a directional one (light.w * p - light.xyz).
// The vertices never change; a shadow volume is a list of indices into them.
// The w = 1 copies go through the same steps as common/light.vert, so a volume's near edge lands
// exactly on its caster's edge: no pixel along a silhouette falls between the two.
layout(location = 0) in vec4 position;

uniform mat4 model;
uniform mat4 viewProjection;  // (world - origin) to clip
uniform vec3 origin;  // world, as common/light.vert's
uniform vec4 light;  // in the caster's own space; w = 1 a point, w = 0 a direction
invariant gl_Position;

void main() {
  vec4 p = position.w != 0.0 ? vec4(position.xyz, 1.0) : vec4(light.w * position.xyz - light.xyz, 0.0);
  vec4 world = model * p;
  gl_Position = viewProjection * vec4(world.xyz - origin * world.w, world.w);
}
