#version 330 core
// light.vert with one clip plane: a reflection keeps only what lies behind its mirror as
// drawn (the mirrored images of what stands on the reflective side). Enable GL_CLIP_DISTANCE0
// only around draws with this shader, and use light.vert where nothing is clipped.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;  // may contain reflections: normals stay unit under orthogonal matrices
uniform mat4 viewProjection;
uniform vec4 clipPlane;  // world plane (a, b, c, d); the side with a x + b y + c z + d >= 0 is kept

out vec3 worldPosition;
out vec3 worldNormal;
invariant gl_Position;

void main() {
  vec4 world = model * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(model) * normal;
  gl_ClipDistance[0] = dot(clipPlane, world);
  gl_Position = viewProjection * world;
}
