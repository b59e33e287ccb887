#version 330 core
// Lesson 14's automatic method, into the work buffer: only the primitive whose fragment writes the
// depth (its colour there is the pass stepper's alone, and this method writes none). Fewer inputs
// than merge.frag's: llvmpipe stores a triangle's interpolation per input.
flat in int fragmentPrimitive;  // this primitive's index + 1 (merge.vert)

layout(location = 1) out uint fragPrimitive;

void main() { fragPrimitive = uint(fragmentPrimitive); }
