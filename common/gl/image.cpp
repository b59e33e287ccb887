#include "gl/image.h"

#include <fcntl.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "gl/errors.h"

namespace stencil {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const std::string& flag, const fs::path& path, const std::string& why) {
  throw OutputError(flag + " " + path.string() + ": " + why);
}

// Whether a new file can be made in the existing folder `dir`: one is made and removed again.
// Returns the system's reason when not, else an empty string.
std::string cannotCreateIn(const fs::path& dir) {
  const fs::path probe = dir / (".stencil-probe-" + std::to_string(getpid()));
  const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) return std::strerror(errno);
  close(fd);
  unlink(probe.c_str());
  return {};
}

// `dir` is a folder that exists and takes new files, or can be made: the nearest thing above it
// that exists is such a folder.
void checkFolderCanHoldFiles(const fs::path& dir, const std::string& flag, const fs::path& path) {
  fs::path existing = dir.empty() ? fs::path(".") : dir;
  for (;;) {
    std::error_code ec;
    const fs::file_status status = fs::status(existing, ec);
    if (status.type() != fs::file_type::not_found) {
      if (ec) refuse(flag, path, existing.string() + ": " + ec.message());
      if (!fs::is_directory(status)) refuse(flag, path, existing.string() + " is not a folder");
      break;
    }
    const fs::path up = existing.parent_path();
    if (up.empty() || up == existing) {
      if (existing == ".") refuse(flag, path, "the current folder does not exist");
      existing = ".";
    } else {
      existing = up;
    }
  }
  const std::string why = cannotCreateIn(existing);
  if (!why.empty()) refuse(flag, path, "cannot create files in " + existing.string() + ": " + why);
}

[[noreturn]] void cannotWrite(const fs::path& path, const std::string& why) {
  throw OutputError("could not write " + path.string() + ": " + why);
}

}  // namespace

void writeFile(const fs::path& path, std::string_view bytes) {
  if (path.empty()) throw OutputError("could not write a file with an empty name");
  if (path.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) cannotWrite(path, ec.message());
  }
  fs::path temporary = path;
  temporary += ".tmp-" + std::to_string(getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) cannotWrite(path, std::strerror(errno));
  int error = 0;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size() || std::fflush(file) != 0)
    error = errno;
  if (std::fclose(file) != 0 && error == 0) error = errno;
  if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    std::remove(temporary.c_str());
    cannotWrite(path, std::strerror(error));
  }
}

void writePng(const fs::path& path, const Image& image) {
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, image.width, image.height, image.channels, image.pixels.data(),
                              image.width * image.channels))
    throw OutputError("could not encode " + path.string() + " as PNG");
  writeFile(path, png);
}

Image readPng(const fs::path& path, int channels) {
  int w = 0, h = 0, fileChannels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &fileChannels, channels);
  if (!data) throw std::runtime_error("could not read " + path.string() + ": " + stbi_failure_reason());
  Image image(w, h, channels);
  std::copy(data, data + image.pixels.size(), image.pixels.begin());
  stbi_image_free(data);
  return image;
}

void checkOutputFile(const fs::path& path, const std::string& flag) {
  if (path.empty()) throw OutputError(flag + ": the file name is empty");
  if (!path.has_filename()) refuse(flag, path, "names a folder; a file name is expected");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) refuse(flag, path, "is a folder; a file name is expected");
  if (fs::exists(status) && !fs::is_regular_file(status))
    refuse(flag, path, "is not a regular file; files are written beside their name and renamed onto it");
  checkFolderCanHoldFiles(path.parent_path(), flag, path);
}

void checkOutputFolder(const fs::path& path, const std::string& flag) {
  if (path.empty()) throw OutputError(flag + ": the folder name is empty");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_directory(status)) refuse(flag, path, "is not a folder");
  checkFolderCanHoldFiles(path, flag, path);
}

}  // namespace stencil
