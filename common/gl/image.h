// 8-bit images in memory, rows top to bottom, and PNG files (stb); output files written
// all or nothing.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace stencil {

struct Image {
  int width = 0, height = 0;
  int channels = 0;  // 1 (stencil values, grey) or 4 (RGBA)
  std::vector<std::uint8_t> pixels;

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(static_cast<size_t>(w) * h * c) {}
  std::uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * channels]; }
  const std::uint8_t* at(int x, int y) const {
    return &pixels[(static_cast<size_t>(y) * width + x) * channels];
  }
};

// Writes a PNG with writeFile. Throws OutputError (gl/errors.h) on failure.
void writePng(const std::filesystem::path&, const Image&);
// The PNG file's bytes for an image (1 channel: grey; 4: RGBA). Throws OutputError when stb cannot
// encode it.
std::string encodePng(const Image&);
// Reads a PNG with the given channel count (1 or 4). Throws std::runtime_error on failure.
Image readPng(const std::filesystem::path&, int channels);

// A run's output files, written as one: each is staged in memory (add, addPng) and commit()
// writes them all or none. Each file is first written with no name (O_TMPFILE in its folder), so
// a killed run leaves nothing named and no link planted at a guessable name is followed; once
// every file is written, each gets a fresh random name beside its own (linkat, which never
// replaces or follows a link) and is renamed onto it, with SIGINT, SIGTERM and SIGHUP held off
// until all are renamed. Folders are made as needed. On any failure commit removes what it made
// (the files and the folders it created) and throws OutputError "could not write PATH: reason".
// Staging a path again replaces what was staged for it.
class OutputSet {
 public:
  void add(const std::filesystem::path&, std::string bytes);
  // Encodes now; throws OutputError when stb cannot encode it.
  void addPng(const std::filesystem::path&, const Image&);
  bool empty() const { return files_.empty(); }
  std::size_t size() const { return files_.size(); }
  // Writes every staged file and empties the set (also when it throws).
  void commit();

 private:
  struct Staged {
    std::filesystem::path path;
    std::string bytes;
  };
  std::vector<Staged> files_;
};

// One file written all or nothing: an OutputSet of one, committed.
void writeFile(const std::filesystem::path&, std::string_view bytes);

// Checks, without writing anything that stays, that writeFile could write a file at `path`: a
// name, not an existing folder or special file, in a folder that exists or can be made and
// takes new files, its name within the folder's limit (NAME_MAX, 255 bytes on Linux) and the whole
// path within PATH_MAX. Throws OutputError "FLAG PATH: why".
void checkOutputFile(const std::filesystem::path&, const std::string& flag);
// The same for a folder that files will be written into: a folder or nothing there yet, in
// which new files can be made.
void checkOutputFolder(const std::filesystem::path&, const std::string& flag);

}  // namespace stencil
