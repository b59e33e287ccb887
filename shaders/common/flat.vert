#version 330 core
// Geometry with one colour: stencil tags, full-screen quads, overlays.
layout(location = 0) in vec3 position;

uniform mat4 transform;

void main() { gl_Position = transform * vec4(position, 1.0); }
