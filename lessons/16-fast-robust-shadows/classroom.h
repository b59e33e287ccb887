// Lesson 16 around its algorithm (main.cpp): the options, variants and cameras a class chooses
// from, the built-in scene the options shape, and two overlays that show what the algorithm left
// in the buffers. Nothing here changes how a shadow is counted.
#pragma once
#include "geometry/scene.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

namespace stencil::fast_robust_shadows {

// The lesson's name, options, variants (with their cameras) and passes.
LessonInfo lessonInfo();

// In the spirit of the paper's figures: stairs, a grid of cubes, a sphere of `slices` slices, two
// moving casters (`moving`), and four coloured lights, one of them directional, or (`many`) a
// ring of thirty-two dim point lights.
Scene builtInScene(int slices, bool many, bool moving);

// The light sum doubled `times` times in the bound colour buffer, so that 8-bit bands show.
void stretchContrast(const Program& flat, const WindowRectangle& window, int times);

// A blue tint where the stencil is not 0 (the light drawn last is blocked). Writes colour only.
void tintShadow(const Program& flat, const WindowRectangle& window);

}  // namespace stencil::fast_robust_shadows
