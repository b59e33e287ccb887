#include "csg_bench_lesson_side.h"

#include <stdexcept>

#include "gl/image.h"
#include "gl/lesson.h"

namespace csgbench {

void lessonCamera(const stencil::SceneCamera& camera, int width, int height, glm::mat4& view, glm::mat4& projection) {
  const stencil::OrbitCamera orbit = stencil::orbitCameraOf(camera);
  view = orbit.view();
  projection = orbit.projection(static_cast<float>(width) / static_cast<float>(height));
}

std::vector<std::uint8_t> readRawStencil(const std::filesystem::path& rawPng, int width, int height) {
  const stencil::Image image = stencil::readPng(rawPng, 1);
  if (image.width != width || image.height != height)
    throw std::runtime_error(rawPng.string() + ": " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + ", expected " + std::to_string(width) + "x" +
                             std::to_string(height));
  return image.pixels;
}

}  // namespace csgbench
