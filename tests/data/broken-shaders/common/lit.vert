#version 330 core
// Deliberately broken: the error test checks that the compile error names this file and line.
layout(location = 0) in vec3 position;

void main() {
  gl_Position = vec4(position, 1.0) + undeclaredVariable;
}
