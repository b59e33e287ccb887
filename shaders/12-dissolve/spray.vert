#version 330 core
// Lesson 12's brush: dots pointSize pixels across. The desktop sizes them by glPointSize (its
// program point size is off); WebGL 2 only by gl_PointSize: both are given the same size.
layout(location = 0) in vec4 position;

uniform mat4 transform;  // the dots' positions to clip space
uniform float pointSize;

void main() {
  gl_Position = transform * position;
  gl_PointSize = pointSize;
}
