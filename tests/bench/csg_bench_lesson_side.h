// What csg_opencsg_benchmark takes from the lessons' framework, behind plain types so the
// benchmark's own file can include GLEW and GLX (which the framework's GL loader excludes): the
// camera matrices a lesson builds for a scene file's camera, and a lesson's raw stencil picture.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/scene.h"

namespace csgbench {

// The view and projection lesson 14 draws `camera` with at width x height pixels (gl/lesson.h's
// orbitCameraOf, OrbitCamera::view and ::projection): the same matrices, bit for bit.
void lessonCamera(const stencil::SceneCamera& camera, int width, int height, glm::mat4& view, glm::mat4& projection);

// A --stencil-out FILE.png's raw values (FILE.raw.png), one byte a pixel, the top row first.
// Throws std::runtime_error when the file cannot be read or is not width x height.
std::vector<std::uint8_t> readRawStencil(const std::filesystem::path& rawPng, int width, int height);

}  // namespace csgbench
