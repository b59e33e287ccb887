// GLSL programs loaded from shaders/, found at run time.
#pragma once
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl.h"

namespace stencil {

// Where shader files are looked for: --shader-dir if given, else $STENCIL_SHADER_DIR if
// set, else the source tree's shaders/ compiled in at build time. Each replaces the next,
// so an override never silently falls back to a different file.
std::vector<std::filesystem::path> shaderSearchPath();
void setShaderDirFlag(std::optional<std::filesystem::path>);
// Finds e.g. "common/lit.vert"; throws UsageError listing every path tried.
std::filesystem::path findShader(const std::string& relative);

class Program {
 public:
  // Compiles and links; a compile error throws UsageError naming file:line.
  Program(const std::string& vertexFile, const std::string& fragmentFile);
  ~Program();
  Program(Program&&) noexcept;
  Program& operator=(Program&&) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  void use() const;  // glUseProgram
  GLuint id() const { return id_; }
  // Each setter binds the program first (glUseProgram, then glUniform*) and leaves it bound, so
  // the draw that follows a set draws with this program: in plain GL, bind the program before
  // drawing. Unknown names are ignored, as GL does (-1 location).
  void set(const char* name, const glm::mat4&) const;
  void set(const char* name, const glm::vec4&) const;
  void set(const char* name, const glm::vec3&) const;
  void set(const char* name, float) const;
  void set(const char* name, int) const;

 private:
  GLuint id_ = 0;
};

// Turns a driver's info log into one line, "file:line: message (and N more)", from its
// first message. Drivers write "0:12(5): error: ..." (Mesa) or "0(12) : error ..." (NVIDIA).
std::string formatCompileLog(const std::string& file, const std::string& log);

}  // namespace stencil
