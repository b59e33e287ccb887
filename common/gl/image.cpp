#include "gl/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

namespace stencil {

void writePng(const std::filesystem::path& path, const Image& image) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  if (!stbi_write_png(path.c_str(), image.width, image.height, image.channels, image.pixels.data(),
                      image.width * image.channels))
    throw std::runtime_error("could not write " + path.string());
}

Image readPng(const std::filesystem::path& path, int channels) {
  int w = 0, h = 0, fileChannels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &fileChannels, channels);
  if (!data) throw std::runtime_error("could not read " + path.string() + ": " + stbi_failure_reason());
  Image image(w, h, channels);
  std::copy(data, data + image.pixels.size(), image.pixels.begin());
  stbi_image_free(data);
  return image;
}

}  // namespace stencil
