#include "gl/shader.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>
#include <utility>

#include "gl/errors.h"

namespace stencil {
namespace {

std::optional<std::filesystem::path> shaderDirFlag;

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The uniforms' initial values that the browser's GLSL cannot declare (glslForWebGl): compile adds
// each stage's, the Program sets them after linking.
// clipPlanes: in, the clip planes the vertex shader wrote as an output (the fragment shader's
// discard, without WEBGL_clip_cull_distance); out, for a vertex shader, how many it writes so.
GLuint compile(GLenum stage, const std::string& relative, std::vector<UniformDefault>& defaults, int& clipPlanes) {
  const std::filesystem::path path = findShader(relative);
#ifdef __EMSCRIPTEN__
  WebGlShader es = glslForWebGl(readText(path), webClipDistance(), stage == GL_FRAGMENT_SHADER ? clipPlanes : 0);
  const std::string source = std::move(es.source);
  defaults.insert(defaults.end(), es.defaults.begin(), es.defaults.end());
  if (stage == GL_VERTEX_SHADER) clipPlanes = es.clipPlanes;
#else
  const std::string source = readText(path);
  (void)defaults;
  (void)clipPlanes;
#endif
  const char* text = source.c_str();
  GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw UsageError(formatCompileLog(path.string(), log.c_str()));
  }
  return shader;
}

}  // namespace

void setShaderDirFlag(std::optional<std::filesystem::path> dir) {
  shaderDirFlag = std::move(dir);
}

std::vector<std::filesystem::path> shaderSearchPath() {
  if (shaderDirFlag) return {*shaderDirFlag};
  if (const char* env = std::getenv("STENCIL_SHADER_DIR"); env && *env) return {env};
  return {std::filesystem::path(STENCIL_SOURCE_DIR) / "shaders"};
}

std::filesystem::path findShader(const std::string& relative) {
  std::string tried;
  for (const auto& dir : shaderSearchPath()) {
    std::filesystem::path candidate = dir / relative;
    if (std::filesystem::is_regular_file(candidate)) return candidate;
    tried += (tried.empty() ? "" : ", ") + candidate.string();
  }
  throw UsageError("shader '" + relative + "' not found; tried: " + tried);
}

WebGlShader glslForWebGl(const std::string& source, bool clipDistance, int clipPlanesIn) {
  static const std::string desktop = "#version 330 core";
  if (source.compare(0, desktop.size(), desktop) != 0) return {source, {}};
  const std::size_t lineEnd = source.find('\n');
  if (lineEnd == std::string::npos || source.find_first_not_of(" \t\r", desktop.size()) < lineEnd)
    return {source, {}};
  WebGlShader out;
  out.source = "#version 300 es\n";
  const bool writesClip = source.find("gl_ClipDistance") != std::string::npos;
  if (writesClip && clipDistance) out.source += "#extension GL_ANGLE_clip_cull_distance : enable\n";
  out.source += "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n";
  for (const char* sampler : {"isampler2D", "usampler2D"})  // GLSL ES gives these no default precision
    if (std::regex_search(source, std::regex(std::string("\\b") + sampler + "\\b")))
      out.source += std::string("precision highp ") + sampler + ";\n";
  std::string body = source.substr(lineEnd + 1);
  if (writesClip && !clipDistance) {  // the planes written become an output the fragment shader reads
    static const std::regex index(R"(gl_ClipDistance\s*\[\s*(\d+)\s*\])");
    for (auto it = std::sregex_iterator(body.begin(), body.end(), index); it != std::sregex_iterator(); ++it)
      out.clipPlanes = std::max(out.clipPlanes, std::stoi((*it)[1].str()) + 1);
    body = std::regex_replace(body, std::regex(R"(\bgl_ClipDistance\b)"), "stencil_clipDistance");
    out.source += "out float stencil_clipDistance[" + std::to_string(out.clipPlanes) + "];\n";
  }
  if (clipPlanesIn > 0) out.source += "in float stencil_clipDistance[" + std::to_string(clipPlanesIn) + "];\n";
  out.source += "#line 2\n";
  // Line by line, so the line numbers stay; an initialiser is cut from its line.
  static const std::regex initialised(R"(^(\s*uniform\s+(float|int)\s+(\w+))\s*=\s*([-+0-9.eE]+)\s*;(.*)$)");
  static const std::regex mainOpens(R"(^(\s*void\s+main\s*\(\s*(void)?\s*\)\s*\{)(.*)$)");
  // A desktop extension asked for where present (": enable"): WebGL has none of the ARB ones, and
  // GLSL ES allows no #extension after the precision lines. Its macro stays undefined, so the
  // shader's #ifdef takes the path without it.
  static const std::regex desktopExtension(R"(^\s*#\s*extension\s+GL_ARB_\w+\s*:\s*enable\b.*$)");
  std::istringstream lines(body);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, desktopExtension)) {
      line.clear();
    } else if (std::regex_match(line, m, initialised)) {
      out.defaults.push_back({m[3].str(), m[2].str() == "int", std::strtod(m[4].str().c_str(), nullptr)});
      line = m[1].str() + ";" + m[5].str();
    } else if (clipPlanesIn > 0 && std::regex_match(line, m, mainOpens)) {
      std::string clipped;
      for (int i = 0; i < clipPlanesIn; ++i)
        clipped += (i ? " || " : "") + std::string("stencil_clipDistance[") + std::to_string(i) + "] < 0.0";
      line = m[1].str() + " if (" + clipped + ") discard;" + m[3].str();
    }
    out.source += line + "\n";
  }
  return out;
}

std::string formatCompileLog(const std::string& file, const std::string& log) {
  static const std::regex mesa(R"(^\s*\d+:(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(.*)$)");
  static const std::regex angle(R"(^\s*(?:ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$)");
  std::istringstream lines(log);
  std::string line, first;
  int count = 0;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (count++ > 0) continue;
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia) || std::regex_match(line, m, angle))
      first = file + ":" + m[1].str() + ": " + m[2].str();
    else
      first = file + ": " + line;
  }
  // The first message is the cause; the rest usually follow from it.
  if (count == 0) return file + ": compile failed with an empty log";
  return count == 1 ? first : first + " (and " + std::to_string(count - 1) + " more)";
}

Program::Program(const std::string& vertexFile, const std::string& fragmentFile) {
  std::vector<UniformDefault> defaults;
  int clipPlanes = 0;
  GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, defaults, clipPlanes);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defaults, clipPlanes);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw UsageError(vertexFile + " + " + fragmentFile + ": link failed: " + log.c_str());
  }
  for (const UniformDefault& d : defaults) {
    if (d.isInt)
      set(d.name.c_str(), static_cast<int>(d.value));
    else
      set(d.name.c_str(), static_cast<float>(d.value));
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}
Program::Program(Program&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
Program& Program::operator=(Program&& other) noexcept {
  std::swap(id_, other.id_);
  return *this;
}

void Program::use() const {
  glUseProgram(id_);
}
void Program::set(const char* name, const glm::mat4& m) const {
  use();
  glUniformMatrix4fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(m));
}
void Program::set(const char* name, const glm::vec4& v) const {
  use();
  glUniform4fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) const {
  use();
  glUniform3fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, float v) const {
  use();
  glUniform1f(glGetUniformLocation(id_, name), v);
}
void Program::set(const char* name, int v) const {
  use();
  glUniform1i(glGetUniformLocation(id_, name), v);
}

}  // namespace stencil
