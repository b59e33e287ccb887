#version 330 core
// Shadow-volume triangles with homogeneous positions: w = 0 vertices are points at infinity
// (common/geometry/shadow_volume.h), carried through the same matrices as any other point.
layout(location = 0) in vec4 position;

uniform mat4 transform;  // viewProjection * model

void main() { gl_Position = transform * position; }
