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

// The one rule that turns a GLSL 330 core shader into GLSL ES 3.00 for WebGL 2, applied at load in
// the browser build (there is no second copy of any shader): the "#version 330 core" line becomes
// "#version 300 es", the ANGLE clip-distance extension where the shader writes gl_ClipDistance,
// and high precision for floats, ints and samplers; a #line keeps the file's line numbers. GLSL ES
// has no uniform initialisers: a float or int uniform's ("uniform float radius = 1e30;") is taken
// out and kept in `defaults`, which Program sets once the program is linked, as GL would.
// A source without that first line is returned as it is (the compiler then says why).
struct UniformDefault {
  std::string name;
  bool isInt = false;
  double value = 0;
  bool operator==(const UniformDefault&) const = default;
};
//
// Where the browser lacks WEBGL_clip_cull_distance (clipDistance false), a vertex shader's
// gl_ClipDistance[i] becomes an output, stencil_clipDistance[i] (clipPlanes: how many), and its
// program's fragment shader (clipPlanesIn: that count) discards a fragment where any of them is
// below 0, on main's first line: the plane clips by pixel centre instead of by triangle. It clips
// whether or not GL_CLIP_DISTANCEi is enabled, as Mesa's llvmpipe does: the lessons use a shader
// that writes clip distances only while its planes are enabled.
struct WebGlShader {
  std::string source;
  std::vector<UniformDefault> defaults;
  int clipPlanes = 0;
};
WebGlShader glslForWebGl(const std::string& source, bool clipDistance = true, int clipPlanesIn = 0);

// Turns a driver's info log into one line, "file:line: message (and N more)", from its
// first message. Drivers write "0:12(5): error: ..." (Mesa), "0(12) : error ..." (NVIDIA) or
// "ERROR: 0:12: ..." (ANGLE, the browsers' WebGL).
std::string formatCompileLog(const std::string& file, const std::string& log);

}  // namespace stencil
