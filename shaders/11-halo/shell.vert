#version 330 core
// The halo's shell: the object's surface pushed out by one of lesson 11's methods.
//   grow     a scale about a centre (the whole object's, or one convex piece's): Kilgard's recipe;
//   extrude  a distance along the (smoothed) vertex normal, in world units;
//   shift    a screen offset in pixels: the object's own outline moved sideways (screen-space dilation).
// objectDepth keeps the depth of the surface point the shell vertex grew from, so the shell lies at
// the object's own depth and an occluder just in front of the object hides the halo.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;  // object to world, rigid
uniform mat4 grow;   // in object space; the identity for the other methods
uniform float extrude;
uniform vec4 shift;  // xy: the offset in pixels, zw: the viewport's size in pixels
uniform mat4 viewProjection;
uniform int objectDepth;

void main() {
  vec4 surface = model * vec4(position, 1.0);
  vec3 n = normalize(mat3(model) * normal);
  vec4 shell = model * (grow * vec4(position, 1.0)) + vec4(extrude * n, 0.0);
  vec4 clip = viewProjection * shell;
  if (objectDepth != 0) {
    vec4 own = viewProjection * surface;
    clip.z = own.z / own.w * clip.w;  // the surface's depth at the shell's place on screen
  }
  clip.xy += 2.0 * shift.xy / shift.zw * clip.w;  // a whole pixel offset, whatever the depth
  gl_Position = clip;
}
