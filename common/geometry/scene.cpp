#include "geometry/scene.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "geometry/csg.h"
#include "geometry/shadow_volume.h"
#include "geometry/shapes.h"
#include "geometry/solid.h"
#include "geometry/weld.h"

namespace stencil {

namespace {

// The text with every byte that is not printable ASCII written as \xNN: messages quote the
// files, which may hold anything.
std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      static const char hex[] = "0123456789abcdef";
      out += {'\\', 'x', hex[byte >> 4], hex[byte & 15]};
    }
  }
  return out;
}

// A word from a file as a message quotes it: in single quotes, at most 40 characters of it.
std::string quote(std::string_view word) {
  constexpr std::size_t most = 40;
  std::string quoted(1, '\'');
  quoted.append(printable(word.substr(0, most)));
  quoted.append(word.size() > most ? "...'" : "'");
  return quoted;
}

// The whole text of a regular file of at most maxBytes bytes. Throws std::runtime_error with the
// reason, without the path.
std::string readFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw std::runtime_error("no such file");
  if (ec) throw std::runtime_error(ec.message());
  if (status.type() == fs::file_type::directory) throw std::runtime_error("it is a directory");
  if (status.type() != fs::file_type::regular) throw std::runtime_error("it is not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(ec.message());
  if (size > maxBytes)
    throw std::runtime_error("it is " + std::to_string(size) + " bytes; at most " + std::to_string(maxBytes) +
                             " are read");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("it cannot be opened");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

}  // namespace

SceneError::SceneError(const std::string& message) : std::runtime_error(printable(message)) {}

std::vector<OracleObject> oracleObjects(const Scene& scene, double time) {
  std::vector<OracleObject> objects;
  for (const SceneObject& o : scene.objects)
    objects.push_back({&o.mesh, o.modelAt(time), o.casts, o.receives});
  return objects;
}

SceneObject sceneObject(std::string name, Mesh mesh, const glm::mat4& model, const glm::vec3& colour,
                        bool casts) {
  SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.model = model;
  o.colour = colour;
  o.casts = casts;
  if (casts) o.caster = prepareCaster(o.mesh);
  return o;
}

glm::mat4 SceneObject::modelAt(double time) const {
  const float t = static_cast<float>(time);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, bob * std::sin(t), 0.0f)) * model;
  if (spinDegPerSecond != 0.0f) m = glm::rotate(m, glm::radians(spinDegPerSecond * t), spinAxis);
  return m;
}

// ---- OBJ files ------------------------------------------------------------------------------

namespace {

// A line's words: what is between spaces, tabs and the other white space.
std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// Calls visit(number, line) for each line of OBJ text as tinyobjloader splits it: at \n, \r\n
// or \r, numbered from 1. A line is passed as a std::string, so a NUL in it ends what C
// functions read of it, as it does for tinyobjloader.
template <class Visit>
void forEachObjLine(std::string_view text, Visit visit) {
  std::size_t number = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    visit(++number, std::string(text.substr(start, end - start)));
    start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
}

// A line's statement as tinyobjloader tells them apart: after leading spaces and tabs, the
// keyword and a space or tab.
bool isStatement(const char* line, const char* keyword) {
  const std::size_t n = std::strlen(keyword);
  return std::strncmp(line, keyword, n) == 0 && (line[n] == ' ' || line[n] == '\t');
}

// Whether a word holds a number whose exponent has more than 4 digits, leading zeros aside
// (floats reach only 1e38 and 1e-45). tinyobjloader's number reader overflows an int on some of
// them (an exponent of 2147483648), so they are refused before it reads them.
bool absurdExponent(std::string_view word) {
  for (std::size_t i = 1; i < word.size(); ++i) {
    if (word[i] != 'e' && word[i] != 'E') continue;
    std::size_t j = i + 1;
    if (j < word.size() && (word[j] == '+' || word[j] == '-')) ++j;
    while (j < word.size() && word[j] == '0') ++j;
    std::size_t digits = 0;
    for (; j < word.size() && word[j] >= '0' && word[j] <= '9'; ++j) ++digits;
    if (digits > 4) return true;
  }
  return false;
}

// Whether a word is a number tinyobjloader would not read as one but that means an infinite
// value: inf or infinity, in any case, with or without a sign.
bool infiniteWord(std::string_view word) {
  if (!word.empty() && (word.front() == '+' || word.front() == '-')) word.remove_prefix(1);
  const auto is = [&](std::string_view name) {
    return word.size() == name.size() &&
           std::equal(word.begin(), word.end(), name.begin(),
                      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
  };
  return is("inf") || is("infinity");
}

struct ObjCounts {
  long long positions = 0, texcoords = 0, normals = 0;
};

// Checks one `f` line's corners (v, v/t, v//n or v/t/n each), read the way tinyobjloader's
// parseTriple reads them, against the counts so far (relative indices) and in the whole file.
// Returns the number of corners.
std::size_t checkFace(const char* p, const ObjCounts& sofar, const ObjCounts& total,
                      const std::function<void(const std::string&)>& fail) {
  const auto index = [&](const char*& q, const std::string& kind, long long before, long long all) {
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(q, &end, 10);
    if (end == q)
      fail("expected a " + kind + " index, got " + quote(std::string_view(q, std::strcspn(q, " \t/"))));
    if (errno == ERANGE || value > INT_MAX || value < INT_MIN) {
      const std::string_view written(q, static_cast<std::size_t>(end - q));
      fail(kind + " index " + quote(written.substr(written.find_first_not_of(" \t\v\f"))) + " is too large");
    }
    if (value == 0) fail(kind + " index 0: OBJ counts from 1");
    if (value > all)
      fail(kind + " index " + std::to_string(value) + " is past the file's " + std::to_string(all) + " " +
           (all == 1           ? kind
            : kind == "vertex" ? "vertices"
                               : kind + "s"));
    if (value < 0 && -value > before)
      fail(kind + " index " + std::to_string(value) + " counts back past the first " + kind + ": " +
           std::to_string(before) + " defined above it");
    q = end + std::strcspn(end, "/ \t\r");
  };
  std::size_t corners = 0;
  p += std::strspn(p, " \t");
  while (*p != '\0' && *p != '\r' && *p != '\n') {
    index(p, "vertex", sofar.positions, total.positions);
    if (*p == '/') {
      ++p;
      if (*p == '/') {
        ++p;
        index(p, "normal", sofar.normals, total.normals);
      } else {
        index(p, "texture coordinate", sofar.texcoords, total.texcoords);
        if (*p == '/') {
          ++p;
          index(p, "normal", sofar.normals, total.normals);
        }
      }
    }
    p += std::strspn(p, " \t\r");
    if (++corners > kMaxObjFaceCorners)
      fail("a face of more than " + std::to_string(kMaxObjFaceCorners) + " corners");
  }
  return corners;
}

// What the pre-scan learnt: the text tinyobjloader is to read, and where the file's v and vn
// lines are, for messages about them.
struct ObjLines {
  std::string text;  // the v, vt, vn and f lines; every other line left empty
  std::vector<std::size_t> positions, normals;
};

// Reads the text as tinyobjloader will, checking what it does not: every face index in range,
// no absurd exponents, no more than kMaxSceneTriangles triangles. Only the statements the
// lessons use are passed on: tinyobjloader's other statements (skin weights, tags, materials)
// have nothing to give them and have bugs of their own. Throws SceneError "NAME:LINE: ...".
ObjLines prescanObj(std::string_view text, const std::string& name) {
  ObjCounts total;
  ObjLines lines;
  forEachObjLine(text, [&](std::size_t number, const std::string& line) {
    const char* p = line.c_str() + std::strspn(line.c_str(), " \t");
    const bool vertexData = isStatement(p, "v") || isStatement(p, "vt") || isStatement(p, "vn");
    if (vertexData || isStatement(p, "f")) lines.text += line;
    lines.text += '\n';
    if (vertexData)
      for (const std::string& word : words(p)) {
        if (absurdExponent(word))
          throw SceneError(name + ":" + std::to_string(number) + ": the number " + quote(word) +
                           " has an exponent of more than 4 digits");
        if (infiniteWord(word))
          throw SceneError(name + ":" + std::to_string(number) + ": the number " + quote(word) +
                           " is not finite");
      }
    if (isStatement(p, "v")) {
      ++total.positions;
      lines.positions.push_back(number);
    } else if (isStatement(p, "vt")) {
      ++total.texcoords;
    } else if (isStatement(p, "vn")) {
      ++total.normals;
      lines.normals.push_back(number);
    }
  });
  ObjCounts sofar;
  std::size_t triangles = 0;
  forEachObjLine(text, [&](std::size_t number, const std::string& line) {
    const auto fail = [&](const std::string& message) {
      throw SceneError(name + ":" + std::to_string(number) + ": " + message);
    };
    const char* p = line.c_str() + std::strspn(line.c_str(), " \t");
    if (isStatement(p, "v")) {
      ++sofar.positions;
    } else if (isStatement(p, "vt")) {
      ++sofar.texcoords;
    } else if (isStatement(p, "vn")) {
      ++sofar.normals;
    } else if (isStatement(p, "f")) {
      const std::size_t corners = checkFace(p + 2, sofar, total, fail);
      if (corners >= 3) triangles += corners - 2;
      if (triangles > kMaxSceneTriangles)
        fail("more than " + std::to_string(kMaxSceneTriangles) + " triangles, the most a scene holds");
    }
  });
  return lines;
}

glm::vec3 vec3At(const std::vector<tinyobj::real_t>& values, int index) {
  const auto i = static_cast<std::size_t>(index);
  return {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
}

// A unit normal in the direction of n, or +y where n has none (a zero-area triangle draws
// nothing; any unit normal keeps the arrays finite).
glm::vec3 unitOr(const glm::vec3& n) {
  const float length = glm::length(n);
  if (length > 0.0f && std::isfinite(length)) return glm::normalize(n);
  const glm::dvec3 d(n);  // too long for a float's length
  const double dLength = glm::length(d);
  return dLength > 0.0 ? glm::vec3(d / dLength) : glm::vec3(0, 1, 0);
}

}  // namespace

ObjMesh parseObj(std::string_view text, const std::string& name) {
  const ObjLines lines = prescanObj(text, name);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(lines.text, "", config)) {
    const std::string error = reader.Error();
    throw SceneError(name + ": " + error.substr(0, error.find_first_of("\r\n")));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto checkCoordinates = [&](const std::vector<tinyobj::real_t>& values,
                                    const std::vector<std::size_t>& lineOf, const char* what, float limit) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (std::isfinite(values[i]) && std::abs(values[i]) <= limit) continue;
      const std::size_t line = i / 3 < lineOf.size() ? lineOf[i / 3] : 0;
      throw SceneError(name + ":" + std::to_string(line) + ": " + what + " " + std::to_string(i / 3 + 1) +
                       (std::isfinite(values[i])
                            ? " has a coordinate beyond +-" + std::to_string(static_cast<long>(limit))
                            : " is not finite"));
    }
  };
  checkCoordinates(attrib.vertices, lines.positions, "vertex", kMaxObjCoordinate);
  checkCoordinates(attrib.normals, lines.normals, "normal", std::numeric_limits<float>::infinity());

  // The pre-scan checked every index; these are checked again, cheaply, in case the two readings
  // of the text ever differ.
  const auto inRange = [](int i, std::size_t count, bool optional) {
    return (optional && i == -1) || (i >= 0 && static_cast<std::size_t>(i) < count);
  };
  bool allNormals = true;
  std::size_t corners = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    if (shape.mesh.indices.size() % 3 != 0) throw SceneError(name + ": a face that did not triangulate");
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      if (!inRange(i.vertex_index, attrib.vertices.size() / 3, false) ||
          !inRange(i.normal_index, attrib.normals.size() / 3, true) ||
          !inRange(i.texcoord_index, attrib.texcoords.size() / 2, true))
        throw SceneError(name + ": a face index out of range");
      allNormals &= i.normal_index >= 0;
      ++corners;
    }
  }
  if (corners == 0) throw SceneError(name + ": no faces");
  if (corners / 3 > kMaxSceneTriangles)
    throw SceneError(name + ": more than " + std::to_string(kMaxSceneTriangles) +
                     " triangles, the most a scene holds");

  ObjMesh result;
  Mesh& drawn = result.drawn;
  Mesh& shared = result.shared;
  std::map<int, std::uint32_t> sharedOf;  // file position -> shared vertex
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      const auto [it, added] =
          sharedOf.emplace(i.vertex_index, static_cast<std::uint32_t>(shared.positions.size()));
      if (added) shared.positions.push_back(vec3At(attrib.vertices, i.vertex_index));
      shared.indices.push_back(it->second);
    }
  if (allNormals) {
    std::map<std::pair<int, int>, std::uint32_t> vertexOf;  // (position, normal) -> vertex
    for (const tinyobj::shape_t& shape : reader.GetShapes())
      for (const tinyobj::index_t& i : shape.mesh.indices) {
        const auto [it, added] = vertexOf.emplace(std::pair(i.vertex_index, i.normal_index),
                                                  static_cast<std::uint32_t>(drawn.positions.size()));
        if (added) {
          drawn.positions.push_back(vec3At(attrib.vertices, i.vertex_index));
          drawn.normals.push_back(unitOr(vec3At(attrib.normals, i.normal_index)));
        }
        drawn.indices.push_back(it->second);
      }
  } else {
    for (std::size_t c = 0; c < shared.indices.size(); c += 3) {
      const glm::vec3 a = shared.positions[shared.indices[c]], b = shared.positions[shared.indices[c + 1]],
                      d = shared.positions[shared.indices[c + 2]];
      const glm::vec3 normal = unitOr(glm::cross(b - a, d - a));
      for (const glm::vec3& p : {a, b, d}) {
        drawn.indices.push_back(static_cast<std::uint32_t>(drawn.positions.size()));
        drawn.positions.push_back(p);
        drawn.normals.push_back(normal);
      }
    }
  }
  return result;
}

std::string readObjFile(const std::filesystem::path& path) {
  return readFile(path, kMaxObjFileBytes);
}

// ---- scene files (docs/scenes.md) ----------------------------------------------------------

namespace {

// A number as the file may have written it: the shortest text that reads back as this float
// (1e-40, where six digits would say 9.99995e-41; 1000000.5, where they would say 1e+06).
std::string shortestText(float v) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, v);
  return ec == std::errc() ? std::string(text, end) : std::to_string(v);
}

// One line of a scene file as words, read left to right; every complaint names FILE:LINE.
class LineReader {
 public:
  LineReader(std::vector<std::string> words, std::string where)
      : words_(std::move(words)), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& message) const { throw SceneError(where_ + ": " + message); }
  bool done() const { return next_ == words_.size(); }
  const std::string& peek() const { return words_[next_]; }

  std::string word(const std::string& what) {
    if (done()) fail("expected " + what + " at the end of the line");
    return words_[next_++];
  }
  float number(const std::string& what) {
    const std::string w = word(what);
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (ec == std::errc::result_out_of_range && end == w.data() + w.size())
      fail("expected " + what + " (a number a float holds: 0, or from about 1.4e-45 to 3.4e+38 in size), got " +
           quote(w));
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(value))
      fail("expected " + what + " (a finite number), got " + quote(w));
    return value;
  }
  float positive(const std::string& what) {
    const float value = number(what);
    if (!(value > 0.0f)) fail("expected " + what + " greater than 0, got " + format(value));
    return value;
  }
  glm::vec3 vec3(const std::string& what) {
    const float x = number(what + " x"), y = number(what + " y"), z = number(what + " z");
    return {x, y, z};
  }
  // A unit vector, normalised in double: a float's squared length overflows past 1.8e19 and
  // underflows below 1e-19, and neither says anything about the direction.
  glm::vec3 direction(const std::string& what) {
    const glm::dvec3 d(vec3(what));
    const double length = glm::length(d);
    if (length == 0.0) fail("expected " + what + " to be a direction, got 0 0 0");
    return glm::vec3(d / length);
  }
  // A point within kMaxSceneCoordinate of the origin on each axis.
  glm::vec3 point(const std::string& what) {
    const glm::vec3 p = vec3(what);
    if (glm::any(glm::greaterThan(glm::abs(p), glm::vec3(kMaxSceneCoordinate))))
      fail("expected " + what + " within " + format(kMaxSceneCoordinate) + " of the origin on each axis, got " +
           format(p.x) + " " + format(p.y) + " " + format(p.z));
    return p;
  }
  glm::vec3 colour() {
    const float r = number("the colour's R"), g = number("the colour's G"), b = number("the colour's B");
    const glm::vec3 c(r, g, b);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f)))) fail("expected a colour R G B of 0 or more each");
    return c;
  }
  bool yesNo(const std::string& what) {
    const std::string w = word(what + " (yes or no)");
    if (w == "yes") return true;
    if (w == "no") return false;
    fail("expected " + what + " (yes or no), got " + quote(w));
  }
  void end() const {
    if (!done()) fail("unexpected " + quote(words_[next_]) + " at the end of the line");
  }
  static std::string format(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
  }

 private:
  std::vector<std::string> words_;
  std::string where_;
  std::size_t next_ = 0;
};

// key value pairs after a shape's name, each key at most once, unknown keys refused.
class ShapeParams {
 public:
  ShapeParams(LineReader& line, const std::string& shape, std::vector<std::string> keys) : line_(line) {
    while (!line.done()) {
      const std::string key = line.word("a parameter");
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        std::string list;
        for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
        line.fail("unknown parameter " + quote(key) + " for " + shape + "; expected " +
                  (list.empty() ? std::string("none") : list));
      }
      if (!seen_.insert(key).second) line.fail("parameter " + quote(key) + " given twice");
      values_[key] = numbers(line);
    }
  }
  // A size in scene units, within kMinSceneScale..kMaxSceneCoordinate.
  float size(const std::string& key, float fallback) { return sized(key, get(key, fallback, true)); }
  int count(const std::string& key, int fallback, int minimum) {
    if (!values_.count(key)) return fallback;
    const float v = get(key, 0.0f, false);
    // Whole numbers above 2^24 no longer have a float each.
    if (v != std::floor(v) || v < static_cast<float>(minimum) || v > 16777216.0f)
      line_.fail("expected " + key + " to be a whole number, at least " + std::to_string(minimum) +
                 " and at most 16777216, got " + LineReader::format(v));
    return static_cast<int>(v);
  }
  glm::vec3 half(const std::string& key, float fallback) {
    if (!values_.count(key)) return glm::vec3(fallback);
    const std::vector<float>& v = values_[key];
    if (v.size() != 1 && v.size() != 3)
      line_.fail("expected one or three numbers after " + key + ", got " + std::to_string(v.size()));
    for (const float h : v)
      if (!(h > 0.0f)) line_.fail("expected " + key + " sizes greater than 0, got " + LineReader::format(h));
    for (const float h : v) sized(key, h);
    return v.size() == 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(v[0]);
  }

 private:
  // A key takes the numbers up to the next word that is not a number (box half takes 1 or 3).
  static std::vector<float> numbers(LineReader& line) {
    std::vector<float> numbers{line.number("a number")};
    while (!line.done()) {
      float v = 0.0f;
      const std::string& w = line.peek();
      const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
      if (ec != std::errc() || end != w.data() + w.size()) break;
      numbers.push_back(line.number("a number"));
    }
    return numbers;
  }
  float get(const std::string& key, float fallback, bool mustBePositive) {
    if (!values_.count(key)) return fallback;
    const std::vector<float>& v = values_[key];
    if (v.size() != 1) line_.fail("expected one number after " + key + ", got " + std::to_string(v.size()));
    if (mustBePositive && !(v[0] > 0.0f))
      line_.fail("expected " + key + " greater than 0, got " + LineReader::format(v[0]));
    return v[0];
  }

  float sized(const std::string& key, float v) const {
    if (v < kMinSceneScale || v > kMaxSceneCoordinate)
      line_.fail("expected " + key + " from " + LineReader::format(kMinSceneScale) + " to " +
                 LineReader::format(kMaxSceneCoordinate) + " scene units, got " + shortestText(v));
    return v;
  }

  LineReader& line_;
  std::set<std::string> seen_;
  std::map<std::string, std::vector<float>> values_;
};

// An object's shape: `drawn`, and for an OBJ file `shared`, the mesh its caster is prepared from
// (empty for the other shapes: their caster is prepared from what is drawn). `room` is how many
// triangles the scene has left; a shape with more is refused before it is made.
ObjMesh readShape(LineReader& line, const std::string& shape, const std::filesystem::path& sceneFile,
                  const ObjFileReader& readObj, std::size_t room) {
  const auto fits = [&](double triangles) {
    if (triangles > static_cast<double>(room))
      line.fail("a " + shape + " of " + std::to_string(static_cast<unsigned long long>(triangles)) +
                " triangles; a scene holds at most " + std::to_string(kMaxSceneTriangles) + " (" +
                std::to_string(room) + " left)");
  };
  const auto made = [](Mesh mesh) { return ObjMesh{std::move(mesh), {}}; };
  if (shape == "plane") {
    ShapeParams p(line, shape, {"half", "divisions"});
    const float half = p.size("half", 5.0f);
    const int divisions = p.count("divisions", 1, 1);
    fits(2.0 * divisions * divisions);
    return made(makePlane(half, divisions));
  }
  if (shape == "box") {
    ShapeParams p(line, shape, {"half"});
    const glm::vec3 half = p.half("half", 0.5f);
    fits(12.0);
    Mesh box = makeCube(1.0f);  // faces on the axes: scaling its corners keeps its normals
    for (glm::vec3& position : box.positions) position *= half;
    return made(std::move(box));
  }
  if (shape == "sphere") {
    ShapeParams p(line, shape, {"radius", "slices", "stacks"});
    const float radius = p.size("radius", 1.0f);
    const int slices = p.count("slices", 32, 3), stacks = p.count("stacks", 16, 2);
    fits(2.0 * slices * (stacks - 1));
    return made(makeSphere(radius, slices, stacks));
  }
  if (shape == "cylinder" || shape == "cone") {
    ShapeParams p(line, shape, {"radius", "height", "slices"});
    const float radius = p.size("radius", 0.5f), height = p.size("height", 1.0f);
    const int slices = p.count("slices", 32, 3);
    fits((shape == "cylinder" ? 4.0 : 2.0) * slices);
    return made(shape == "cylinder" ? makeCylinder(radius, height, slices)
                                    : makeCone(radius, height, slices));
  }
  if (shape == "torus") {
    ShapeParams p(line, shape, {"major", "minor", "segments", "sides"});
    const float major = p.size("major", 1.0f), minor = p.size("minor", 0.25f);
    if (!(minor < major)) line.fail("expected the torus's minor radius less than its major radius");
    const int segments = p.count("segments", 32, 3), sides = p.count("sides", 16, 3);
    fits(2.0 * segments * sides);
    return made(makeTorus(major, minor, segments, sides));
  }
  if (shape == "stairs") {
    ShapeParams p(line, shape, {"steps", "width", "rise", "run"});
    const int steps = p.count("steps", 5, 1);
    const float width = p.size("width", 1.0f), rise = p.size("rise", 0.2f), run = p.size("run", 0.3f);
    fits(12.0 * steps);
    return made(makeStairs(steps, width, rise, run));
  }
  if (shape == "mesh") {
    const std::string file = line.word("an OBJ file name after 'mesh'");
    line.end();
    const std::filesystem::path path = sceneFile.parent_path() / file;
    std::string text;
    try {
      text = readObj(path);
    } catch (const std::runtime_error& e) {
      line.fail("cannot read mesh '" + path.string() + "': " + e.what());
    }
    ObjMesh mesh;
    try {
      mesh = parseObj(text, path.string());
    } catch (const SceneError& e) {
      line.fail(e.what());
    }
    fits(static_cast<double>(mesh.drawn.triangleCount()));
    return mesh;
  }
  line.fail("unknown shape " + quote(shape) +
            "; expected plane, box, sphere, cylinder, cone, torus, stairs or mesh");
}

void readCamera(LineReader& line, SceneCamera& camera) {
  bool eye = false, target = false, nearGiven = false, farGiven = false;
  std::set<std::string> seen;
  while (!line.done()) {
    const std::string key = line.word("a camera setting");
    if (!seen.insert(key).second) line.fail("camera setting " + quote(key) + " given twice");
    if (key == "eye") {
      camera.eye = line.point("the eye");
      eye = true;
    } else if (key == "target") {
      camera.target = line.point("the target");
      target = true;
    } else if (key == "up") {
      const glm::vec3 up = line.direction("the up direction");
      if (glm::length(up - glm::vec3(0, 1, 0)) > 1e-6f)
        line.fail("expected up 0 1 0: the camera orbits about +y");
      camera.up = up;
    } else if (key == "fovy") {
      camera.fovyDeg = line.positive("fovy in degrees");
      if (!(camera.fovyDeg < 180.0f)) line.fail("expected fovy less than 180 degrees");
    } else if (key == "near") {
      camera.nearPlane = line.positive("the near plane's distance");
      nearGiven = true;
    } else if (key == "far") {
      camera.farPlane = line.positive("the far plane's distance");
      farGiven = true;
    } else if (key == "orthographic") {
      camera.orthographic = true;
      camera.orthoHeight = line.positive("the orthographic view's height");
    } else if (key == "mirrored") {
      camera.mirrored = true;
    } else {
      line.fail("unknown camera setting " + quote(key) +
                "; expected eye, target, up, fovy, near, far, orthographic or mirrored");
    }
  }
  if (!eye || !target || !nearGiven) line.fail("expected the camera's eye, target and near");
  if (camera.orthographic && !farGiven)
    line.fail("expected far with orthographic: a parallel view needs a far plane");
  if (farGiven && !(camera.farPlane > camera.nearPlane)) line.fail("expected far beyond near");
  const glm::vec3 d = camera.eye - camera.target;
  if (glm::length(glm::vec2(d.x, d.z)) <= 1e-6f * glm::length(d) || glm::length(d) == 0.0f)
    line.fail("expected the eye off the vertical through the target (the camera's up is +y)");
}

// `light sun LAT LON YYYY-MM-DD HH:MM ZONE`: the place, the local date and clock, and the zone's
// hours from UTC; the light is directional, towards where the sun then stands (solar.h).
void readSun(LineReader& line, SceneLight& light, bool sunMayBeDown) {
  SunLight sun;
  sun.place.latitudeDeg = line.number("the sun's latitude in degrees (north positive)");
  if (std::abs(sun.place.latitudeDeg) > 90.0)
    line.fail("expected a latitude of -90 to 90 degrees, got " +
              LineReader::format(float(sun.place.latitudeDeg)));
  sun.place.longitudeDeg = line.number("the sun's longitude in degrees (east positive)");
  if (std::abs(sun.place.longitudeDeg) > 180.0)
    line.fail("expected a longitude of -180 to 180 degrees, got " +
              LineReader::format(float(sun.place.longitudeDeg)));
  const std::string date = line.word("the date (YYYY-MM-DD)"), clock = line.word("the local time (HH:MM)");
  const std::optional<CivilTime> time = parseCivilTime(date, clock);
  if (!time) line.fail("expected a date YYYY-MM-DD and a local time HH:MM, got " + quote(date + " " + clock));
  sun.time = *time;
  // The zone as it is usually written, with its sign: +2, -7, +5.5 (from_chars takes no '+').
  const std::string zone = line.word("the time zone in hours from UTC (+2 for CEST)");
  const std::string digits = zone.starts_with('+') ? zone.substr(1) : zone;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), sun.time.zoneHours);
  if (digits.empty() || (digits[0] == '-' && zone[0] == '+') || ec != std::errc() ||
      end != digits.data() + digits.size() || !std::isfinite(sun.time.zoneHours))
    line.fail("expected the time zone in hours from UTC (+2 for CEST), got " + quote(zone));
  if (const std::string problem = civilTimeProblem(sun.time); !problem.empty())
    line.fail("expected a date and time that exist: " + problem);
  const SunPosition p = sunPosition(sun.place, sun.time);
  if (p.elevationDeg <= 0.0 && !sunMayBeDown)
    line.fail("the sun is below the horizon then (elevation " + LineReader::format(float(p.elevationDeg)) +
              " degrees): it lights nothing");
  light.position = glm::vec4(sunDirection(p.elevationDeg, p.azimuthDeg), 0.0f);
  light.sun = sun;
}

void readLight(LineReader& line, SceneLight& light, bool sunMayBeDown) {
  const std::string type = line.word("the light's type (point, directional or sun)");
  if (type == "point")
    light.position = glm::vec4(line.point("the light's position"), 1.0f);
  else if (type == "directional")
    light.position = glm::vec4(line.direction("the direction towards the light"), 0.0f);
  else if (type == "sun")
    readSun(line, light, sunMayBeDown);
  else
    line.fail("expected the light's type (point, directional or sun), got " + quote(type));
  std::set<std::string> seen;
  while (!line.done()) {
    const std::string key = line.word("a light setting");
    if (!seen.insert(key).second) line.fail("light setting " + quote(key) + " given twice");
    if (key == "color")
      light.colour = line.colour();
    else if (key == "radius") {
      if (type != "point") line.fail("a directional light has no radius: its light reaches everywhere");
      light.radius = line.positive("the light's radius");
    } else
      line.fail("unknown light setting " + quote(key) + "; expected color" +
                (type == "point" ? " or radius" : ""));
  }
}

// The singular values of a 3x3 matrix, largest first, in double: the square roots of the
// eigenvalues of M^T M, a symmetric matrix, by the closed form for its characteristic cubic
// (Smith, "Eigenvalues of a symmetric 3x3 matrix", CACM 4(4), 1961).
glm::dvec3 singularValues(const glm::dmat3& m) {
  const glm::dmat3 a = glm::transpose(m) * m;
  const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  glm::dvec3 eig;
  if (p1 == 0.0) {
    eig = {a[0][0], a[1][1], a[2][2]};
  } else {
    const double p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
                      (a[2][2] - q) * (a[2][2] - q) + 2.0 * p1;
    const double p = std::sqrt(p2 / 6.0);
    const glm::dmat3 b = (a - q * glm::dmat3(1.0)) / p;
    const double r = std::clamp(glm::determinant(b) / 2.0, -1.0, 1.0);
    const double phi = std::acos(r) / 3.0;
    eig.x = q + 2.0 * p * std::cos(phi);
    eig.z = q + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0);
    eig.y = 3.0 * q - eig.x - eig.z;
  }
  std::sort(&eig.x, &eig.x + 3, std::greater<>());
  return glm::sqrt(glm::max(eig, glm::dvec3(0.0)));
}

// What an object's transforms and motion make of it, checked at the line that sets them, so a
// scene that would break the float maths later is refused there (the limits in scene.h): the
// model matrix's stretch (its singular values) within kMinSceneScale..kMaxSceneCoordinate, a
// spin whose angle stays finite up to kMaxSceneTime, and every point the object reaches at any
// time within kMaxSceneCoordinate of the origin (spin turns the shape within its bounding sphere
// about its origin; bob moves it up to |bob| along y).
void checkPlacement(const LineReader& line, const SceneObject& o) {
  const auto fmt = [](double v) { return LineReader::format(static_cast<float>(v)); };
  const glm::dmat4 model(o.model);
  const glm::dvec3 sigma = singularValues(glm::dmat3(model));
  bool finite = true;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) finite &= std::isfinite(model[c][r]);
  if (!finite || sigma.x > kMaxSceneCoordinate || sigma.z < kMinSceneScale)
    line.fail("the transforms up to this line scale the object by " + fmt(sigma.z) +
              (sigma.x != sigma.z ? " to " + fmt(sigma.x) : std::string()) + "; a scene's scales lie within " +
              fmt(kMinSceneScale) + " to " + fmt(kMaxSceneCoordinate));
  const float turns = o.spinDegPerSecond * static_cast<float>(kMaxSceneTime);
  if (!std::isfinite(glm::radians(turns)))
    line.fail("a spin of " + fmt(o.spinDegPerSecond) + " degrees per second turns past what a float holds by " +
              fmt(kMaxSceneTime) + " s");
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high = -low;
  if (o.spinDegPerSecond != 0.0f) {
    double radius = 0.0;
    for (const glm::vec3& p : o.mesh.positions) radius = std::max(radius, glm::length(glm::dvec3(p)));
    const glm::dvec3 centre(model[3]);
    low = centre - sigma.x * radius;
    high = centre + sigma.x * radius;
  } else {
    for (const glm::vec3& p : o.mesh.positions) {
      const glm::dvec3 world(model * glm::dvec4(glm::dvec3(p), 1.0));
      low = glm::min(low, world);
      high = glm::max(high, world);
    }
  }
  const glm::dvec3 bob(0.0, std::abs(o.bob), 0.0);
  const glm::dvec3 far = glm::max(glm::abs(low - bob), glm::abs(high + bob));
  const double reach = std::max({far.x, far.y, far.z});
  if (!(reach <= kMaxSceneCoordinate))
    line.fail("the object reaches " + shortestText(static_cast<float>(reach)) + " from the origin" +
              (o.spinDegPerSecond != 0.0f || o.bob != 0.0f ? " as it moves" : "") + "; a scene lies within " +
              fmt(kMaxSceneCoordinate) + " of the origin on each axis");
}

void readObjectLine(LineReader& line, SceneObject& object) {
  const std::string key = line.word("an object setting");
  if (key == "translate")
    object.model = glm::translate(glm::mat4(1.0f), line.vec3("the translation")) * object.model;
  else if (key == "rotate") {
    const float degrees = line.number("the angle in degrees");
    object.model =
        glm::rotate(glm::mat4(1.0f), glm::radians(degrees), line.direction("the axis")) * object.model;
  } else if (key == "scale") {
    glm::vec3 s(line.number("the scale"));
    if (!line.done()) {  // y, then z: a function's arguments are read in no set order
      const float y = line.number("the scale y");
      const float z = line.number("the scale z");
      s = glm::vec3(s.x, y, z);
    }
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f)
      line.fail("expected a scale other than 0 (it flattens the object)");
    object.model = glm::scale(glm::mat4(1.0f), s) * object.model;
  } else if (key == "color")
    object.colour = line.colour();
  else if (key == "casts")
    object.casts = line.yesNo("whether it casts shadows");
  else if (key == "receives")
    object.receives = line.yesNo("whether it receives shadows");
  else if (key == "spin") {
    object.spinDegPerSecond = line.number("the spin in degrees per second");
    if (!line.done()) object.spinAxis = line.direction("the spin axis");
  } else if (key == "bob")
    object.bob = line.number("the bob's amplitude");
  else
    line.fail("unknown object setting " + quote(key) +
              "; expected translate, rotate, scale, color, casts, receives, spin or bob");
  line.end();
  if (key == "translate" || key == "rotate" || key == "scale" || key == "spin" || key == "bob")
    checkPlacement(line, object);
}

}  // namespace

namespace {

// The csg line against the objects read: its names, its syntax, its sum of products' size, and
// the solids it names closed (lesson 14's counting and its ray cast need an inside).
void checkCsg(Scene& scene, const std::string& file, std::size_t column) {
  const std::string where = file + ":" + std::to_string(scene.csgLine) + ": ";
  std::vector<std::string> names;
  for (const SceneObject& o : scene.objects) {
    // Any printable word names an object, but the csg line reads only letters, digits and '_'
    // ("drill-x" would read as drill - x): with a csg line, every name must be one it can write.
    if (!isCsgName(o.name))
      throw SceneError(file + ":" + std::to_string(o.line) + ": object '" + o.name +
                       "': a scene with a csg line names objects by letters, digits and '_' only, not "
                       "starting with a digit (the csg line could not name it); rename it");
    names.push_back(o.name);
  }
  CsgTree tree;
  try {
    tree = parseCsg(scene.csg, names);
  } catch (const std::invalid_argument& e) {
    // "column N: ..." counts in the expression; the user counts in the line.
    std::string message = e.what();
    std::size_t n = 0;
    if (std::sscanf(message.c_str(), "column %zu", &n) == 1) {
      const std::size_t colon = message.find(':');
      message = "column " + std::to_string(n + column) + message.substr(colon);
    }
    throw SceneError(where + "csg: " + message);
  }
  try {
    normalize(tree, kMaxSceneCsgProducts);
  } catch (const std::length_error& e) {
    throw SceneError(where + "csg: " + e.what() + "; a scene's expression may have at most " +
                     std::to_string(kMaxSceneCsgProducts) + " (factor it, or subtract a union)");
  }
  std::vector<bool> named(scene.objects.size(), false);
  for (const CsgTree::Node& n : tree.nodes)
    if (n.kind == CsgTree::Kind::Primitive) named[static_cast<std::size_t>(n.primitive)] = true;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!named[i]) continue;
    const SceneObject& o = scene.objects[i];
    const PreparedCaster prepared = o.casts ? PreparedCaster{} : prepareCaster(o.mesh);
    const PreparedCaster& caster = o.casts ? o.caster : prepared;
    const CasterReport& report = caster.report;
    if (report.closedManifold() && signedVolume(caster.mesh) < 0.0)
      throw SceneError(where + "csg: object '" + o.name +
                       "' faces inwards (a solid written inside out): CSG counts a primitive's front "
                       "faces as where a ray enters it; turn its faces round");
    if (!report.closedManifold()) {
      const auto edges = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " edge" : " edges"); };
      std::string problems;
      if (report.borderEdges > 0) problems = "open: " + edges(report.borderEdges) + " with one face";
      if (report.nonManifoldEdges > 0)
        problems += (problems.empty() ? "" : "; ") + edges(report.nonManifoldEdges) + " shared by three or more faces";
      if (report.inconsistentEdges > 0)
        problems += (problems.empty() ? "" : "; ") + edges(report.inconsistentEdges) + " walked the same way by both faces";
      throw SceneError(where + "csg: object '" + o.name + "' is not a closed, consistently wound solid (" + problems +
                       "): lesson 14 tells a primitive's inside by the parity of its faces along a ray, which "
                       "needs each edge shared by two faces that walk it in opposite directions; repair the mesh");
    }
  }
}

}  // namespace

Scene parseScene(std::string_view text, const std::filesystem::path& file, const ObjFileReader& readObj,
                 bool sunMayBeDown) {
  Scene scene;
  scene.file = file;
  const std::string name = file.string();
  bool haveCamera = false, haveAmbient = false;
  bool inObject = false;           // the last unindented line was an object: indented lines are its settings
  std::vector<Mesh> casterInputs;  // per object: an OBJ file's shared positions, else empty
  std::size_t triangles = 0;
  std::size_t csgColumn = 0;  // where the csg expression starts in its line, 0-based
  std::istringstream in{std::string(text)};
  int lineNumber = 0;
  std::string raw;
  while (std::getline(in, raw)) {
    ++lineNumber;
    const std::string content = raw.substr(0, raw.find('#'));
    LineReader line(words(content), name + ":" + std::to_string(lineNumber));
    if (line.done()) continue;
    const bool indented = content[0] == ' ' || content[0] == '\t';
    if (indented) {
      if (!inObject) line.fail("an indented line is an object's setting, and no object line is above it");
      readObjectLine(line, scene.objects.back());
      continue;
    }
    inObject = false;
    const std::string keyword = line.word("a keyword");
    if (keyword == "camera") {
      if (haveCamera) line.fail("a second camera line; a scene has one camera");
      haveCamera = true;
      readCamera(line, scene.camera);
    } else if (keyword == "ambient") {
      if (haveAmbient) line.fail("a second ambient line");
      haveAmbient = true;
      scene.ambient = line.colour();
      line.end();
    } else if (keyword == "light") {
      if (scene.lights.size() == kMaxSceneLights)
        line.fail("more than " + std::to_string(kMaxSceneLights) + " lights; a scene has at most " +
                  std::to_string(kMaxSceneLights));
      readLight(line, scene.lights.emplace_back(), sunMayBeDown);
      if (scene.lights.back().sun && std::count_if(scene.lights.begin(), scene.lights.end(),
                                                   [](const SceneLight& l) { return bool(l.sun); }) > 1)
        line.fail("a second sun; a scene has one sun (--shadow-hours moves it)");
    } else if (keyword == "object") {
      if (scene.objects.size() == kMaxSceneObjects)
        line.fail("more than " + std::to_string(kMaxSceneObjects) + " objects; a scene has at most " +
                  std::to_string(kMaxSceneObjects));
      SceneObject object;
      object.name = line.word("the object's name");
      object.line = lineNumber;
      if (!std::all_of(object.name.begin(), object.name.end(), [](char c) { return c > ' ' && c < 0x7f; }))
        line.fail("expected the object's name in printable ASCII, got " + quote(object.name));
      for (const SceneObject& o : scene.objects)
        if (o.name == object.name) line.fail("a second object named " + quote(object.name));
      const std::string shape = line.word("the object's shape");
      ObjMesh meshes;
      try {
        meshes = readShape(line, shape, file, readObj, kMaxSceneTriangles - triangles);
      } catch (const std::invalid_argument& e) {
        line.fail(e.what());
      }
      if (const auto bad = firstNonFiniteVertex(meshes.drawn))
        line.fail("vertex " + std::to_string(*bad + 1) + " of the " + shape +
                  " is not finite: its sizes are too large for a float");
      object.mesh = std::move(meshes.drawn);
      triangles += object.mesh.triangleCount();
      checkPlacement(line, object);
      scene.objects.push_back(std::move(object));
      casterInputs.push_back(std::move(meshes.shared));
      inObject = true;
    } else if (keyword == "csg") {
      if (scene.csgLine != 0) line.fail("a second csg line; a scene has one CSG expression");
      // The expression is the rest of the line, spaces and all: its columns are the line's.
      csgColumn = content.find("csg") + 3;
      scene.csg = content.substr(csgColumn);
      scene.csgLine = lineNumber;
      if (scene.csg.find_first_not_of(" \t\r") == std::string::npos)
        line.fail("expected a CSG expression after csg");
    } else {
      line.fail("unknown keyword " + quote(keyword) +
                "; expected camera, ambient, light, object or csg (settings of an object are indented)");
    }
  }
  // Casters are prepared once their settings are read: 'casts no' spares a mesh that cannot cast.
  const auto caster = [&](const SceneObject& o) {
    return name + ":" + std::to_string(o.line) + ": object '" + o.name + "' cannot cast shadow volumes: ";
  };
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    SceneObject& o = scene.objects[i];
    if (!o.casts) continue;
    try {
      o.caster = prepareCaster(casterInputs[i].positions.empty() ? o.mesh : casterInputs[i]);
    } catch (const std::invalid_argument& e) {
      throw SceneError(caster(o) + e.what());
    }
  }
  // What the csg line needs of the objects it names is said first: a closed, consistently wound
  // solid, whether it casts or not ('casts no' would not make one of a mesh that cannot cast).
  if (scene.csgLine != 0) checkCsg(scene, name, csgColumn);
  for (const SceneObject& o : scene.objects) {
    if (!o.casts || o.caster.report.usable()) continue;
    std::string problems;
    for (const std::string& m : o.caster.report.messages)
      if (m.starts_with("not two-manifold") || m.starts_with("inconsistently wound"))
        problems += (problems.empty() ? "" : "; ") + m;
    throw SceneError(caster(o) + problems + " (repair the mesh, or give it 'casts no')");
  }
  const std::string end = name + ":" + std::to_string(std::max(lineNumber, 1)) + ": ";
  if (!haveCamera) throw SceneError(end + "the scene has no camera line");
  if (scene.lights.empty()) throw SceneError(end + "the scene has no light");
  if (scene.objects.empty()) throw SceneError(end + "the scene has no object");
  return scene;
}

Scene loadScene(const std::filesystem::path& file, bool sunMayBeDown) {
  std::string text;
  try {
    text = readFile(file, kMaxSceneFileBytes);
  } catch (const std::runtime_error& e) {
    throw SceneError(file.string() + ": cannot open the scene file: " + e.what());
  }
  return parseScene(text, file, readObjFile, sunMayBeDown);
}

SolidsSeen solidsSeenFrom(const Scene& scene, const std::vector<glm::mat4>& models, const glm::vec3& eye) {
  SolidsSeen seen;
  seen.room.assign(scene.objects.size(), false);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.casts || !o.caster.report.closedManifold()) continue;
    const Mesh& mesh = o.caster.mesh;
    const bool facesIn = signedVolume(mesh) < 0.0;
    const glm::mat4 toObject = glm::inverse(models[i]);
    const glm::vec3 eyeHere = glm::vec3(toObject * glm::vec4(eye, 1.0f));
    const SolidSide side = solidSide(mesh, facesIn, eyeHere);
    seen.room[i] = side.room;
    if (!seen.refusal.empty()) continue;
    const std::string where =
        scene.file.empty() ? "" : scene.file.string() + ":" + std::to_string(o.line) + ": ";
    // On a caster's surface a point is neither inside nor outside its solid.
    std::string lightOn;
    for (std::size_t l = 0; l < scene.lights.size() && lightOn.empty(); ++l) {
      const glm::vec4 light = toObject * scene.lights[l].position;
      if (light.w != 0.0f && onSurface(mesh, glm::dvec3(glm::vec3(light) / light.w)))
        lightOn = std::to_string(l);
    }
    if (onSurface(mesh, glm::dvec3(eyeHere)))
      seen.refusal = where + "the eye lies on the surface of caster '" + o.name +
                     "', neither inside nor outside it: move the camera off it";
    else if (!lightOn.empty())
      seen.refusal = where + "light " + lightOn + " lies on the surface of caster '" + o.name +
                     "', neither inside nor outside it: move the light off it (a hair is enough)";
    else if (facesIn && !side.room)
      seen.refusal = where + "caster '" + o.name +
                     "' faces inwards and the eye is outside it: a solid written inside out (turn its faces "
                     "round, or put the eye inside: a mesh facing inwards is a room)";
    else if (side.room && !isConvex(mesh, o.caster.adjacency, facesIn))
      seen.refusal =
          where + "caster '" + o.name +
          "' holds the eye, so it is a room, and it is not convex: its walls would shadow parts of "
          "its own inside, which z-fail cannot count (its solid reaches to infinity; split it into "
          "convex rooms, or give it 'casts no')";
  }
  return seen;
}

bool lightBuried(const Scene& scene, const std::vector<glm::mat4>& models, const SolidsSeen& seen,
                 const glm::vec4& light) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.casts || !o.caster.report.closedManifold()) continue;
    const Mesh& mesh = o.caster.mesh;
    if (lightBuried(mesh, {signedVolume(mesh) < 0.0, seen.room[i]}, glm::inverse(models[i]) * light))
      return true;
  }
  return false;
}

}  // namespace stencil
