#version 330 core
// The caster flattened onto a receiver plane by the planar shadow matrix, clipped to the
// part that can block the light: on the light's side of the receiver and nearer to the
// receiver than the light. Outside that slab the matrix still projects points onto the
// plane, where they would be false shadows (a buried part, a part beyond the light).
layout(location = 0) in vec3 position;

uniform mat4 model;
uniform mat4 shadowMatrix;  // planarShadowMatrix(receiver, light)
uniform mat4 viewProjection;
uniform vec4 receiver;  // plane (a, b, c, d): a x + b y + c z + d = 0
uniform vec4 light;     // w = 1 a point, w = 0 a direction towards the light

void main() {
  vec4 world = model * vec4(position, 1.0);
  float side = sign(dot(receiver, light));                           // which side the light is on
  gl_ClipDistance[0] = side * dot(receiver, world);                  // on the light's side of the plane
  gl_ClipDistance[1] = side * (dot(receiver, light) - light.w * dot(receiver, world));  // nearer than the light
  gl_Position = viewProjection * shadowMatrix * world;
}
