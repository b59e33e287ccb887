#version 330 core
// The doubled vertex array (McGuire et al. 2003): every caster vertex is stored twice, with w = 1
// and w = 0. The w = 1 copy stays where it is; the w = 0 copy becomes the point at infinity away
// from the light: p - L for a point light, -L for a directional one (light.w * p - light.xyz).
// The vertices never change; a shadow volume is a list of indices into them.
layout(location = 0) in vec4 position;

uniform mat4 transform;  // viewProjection * model
uniform vec4 light;      // in the caster's own space; w = 1 a point, w = 0 a direction

void main() {
  vec4 p = position.w != 0.0 ? vec4(position.xyz, 1.0) : vec4(light.w * position.xyz - light.xyz, 0.0);
  gl_Position = transform * p;
}
