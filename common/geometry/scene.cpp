#include "geometry/scene.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>
#include <sstream>

#include "geometry/shapes.h"
#include "geometry/weld.h"

namespace stencil {

namespace {

// Zero area, exactly: a repeated vertex, or three vertices on one line. A sliver keeps its
// place, however thin: dropping it would open the mesh.
bool degenerate(const std::vector<glm::vec3>& positions, const std::uint32_t* triangle) {
  const std::uint32_t a = triangle[0], b = triangle[1], c = triangle[2];
  if (a == b || b == c || c == a) return true;
  const glm::dvec3 pa(positions[a]), pb(positions[b]), pc(positions[c]);
  return glm::cross(pb - pa, pc - pa) == glm::dvec3(0.0);
}

std::string plural(std::size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

PreparedCaster prepareCaster(const Mesh& mesh) {
  validateMesh(mesh);
  PreparedCaster result;
  CasterReport& report = result.report;
  report.inputVertices = mesh.positions.size();

  Mesh positionsOnly;
  positionsOnly.positions = mesh.positions;
  positionsOnly.indices = mesh.indices;
  Mesh welded = weldByPosition(positionsOnly).mesh;
  report.weldedVertices = welded.positions.size();

  result.mesh.positions = std::move(welded.positions);
  for (std::size_t t = 0; t < welded.triangleCount(); ++t) {
    if (degenerate(result.mesh.positions, &welded.indices[3 * t])) {
      ++report.droppedDegenerate;
      continue;
    }
    result.mesh.indices.insert(result.mesh.indices.end(), welded.indices.begin() + 3 * t,
                               welded.indices.begin() + 3 * t + 3);
  }
  result.adjacency = buildEdgeAdjacency(result.mesh.indices, result.mesh.positions.size());
  report.borderEdges = result.adjacency.report.borderEdges;
  report.nonManifoldEdges = result.adjacency.report.nonManifoldEdges;
  report.inconsistentEdges = result.adjacency.report.inconsistentEdges;

  if (report.weldedVertices < report.inputVertices)
    report.messages.push_back("welded " + std::to_string(report.inputVertices) + " vertices into " +
                              std::to_string(report.weldedVertices) + " (vertices split at seams)");
  if (report.droppedDegenerate > 0)
    report.messages.push_back("dropped " + plural(report.droppedDegenerate, "degenerate triangle"));
  if (report.borderEdges > 0)
    report.messages.push_back("open: " + plural(report.borderEdges, "border edge") +
                              " extrude as silhouette edges, and its faces cap the volume from both sides");
  if (report.nonManifoldEdges > 0)
    report.messages.push_back("not two-manifold: " + plural(report.nonManifoldEdges, "edge") +
                              " shared by three or more faces");
  if (report.inconsistentEdges > 0)
    report.messages.push_back("inconsistently wound: " + plural(report.inconsistentEdges, "edge") +
                              " walked the same way by both faces");
  return result;
}

std::vector<OracleObject> oracleObjects(const Scene& scene, double time) {
  std::vector<OracleObject> objects;
  for (const SceneObject& o : scene.objects)
    objects.push_back({&o.mesh, o.modelAt(time), o.casts, o.receives});
  return objects;
}

SceneObject sceneObject(std::string name, Mesh mesh, const glm::mat4& model, const glm::vec3& color,
                        bool casts) {
  SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.model = model;
  o.color = color;
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

// ---- scene files (docs/scenes.md) ----------------------------------------------------------

namespace {

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
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(value))
      fail("expected " + what + " (a finite number), got '" + w + "'");
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
  glm::vec3 direction(const std::string& what) {
    const glm::vec3 d = vec3(what);
    if (glm::length(d) == 0.0f) fail("expected " + what + " to be a direction, got 0 0 0");
    return glm::normalize(d);
  }
  glm::vec3 color() {
    const float r = number("the colour's R"), g = number("the colour's G"), b = number("the colour's B");
    const glm::vec3 c(r, g, b);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f)))) fail("expected a colour R G B of 0 or more each");
    return c;
  }
  bool yesNo(const std::string& what) {
    const std::string w = word(what + " (yes or no)");
    if (w == "yes") return true;
    if (w == "no") return false;
    fail("expected " + what + " (yes or no), got '" + w + "'");
  }
  void end() const {
    if (!done()) fail("unexpected '" + words_[next_] + "' at the end of the line");
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
        line.fail("unknown parameter '" + key + "' for " + shape + "; expected " +
                  (list.empty() ? std::string("none") : list));
      }
      if (!seen_.insert(key).second) line.fail("parameter '" + key + "' given twice");
      values_[key] = numbers(line);
    }
  }
  float positive(const std::string& key, float fallback) { return get(key, fallback, true); }
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

  LineReader& line_;
  std::set<std::string> seen_;
  std::map<std::string, std::vector<float>> values_;
};

// An OBJ file's triangles (polygons fanned), all its shapes in one mesh. Normals: the file's
// where every corner has one, else one per triangle (each triangle its own three vertices).
Mesh loadObj(const std::filesystem::path& path, const LineReader& line) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!std::filesystem::is_regular_file(path))
    line.fail("cannot read mesh '" + path.string() + "': no such file");
  if (!reader.ParseFromFile(path.string(), config)) {
    std::string error = reader.Error();
    while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
    line.fail("cannot read mesh '" + path.string() + "': " + error.substr(0, error.find('\n')));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  bool allNormals = true;
  std::size_t corners = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      allNormals &= i.normal_index >= 0;
      ++corners;
    }
  if (corners == 0) line.fail("mesh '" + path.string() + "' has no faces");

  Mesh mesh;
  auto position = [&](const tinyobj::index_t& i) {
    return glm::vec3(attrib.vertices[3 * i.vertex_index], attrib.vertices[3 * i.vertex_index + 1],
                     attrib.vertices[3 * i.vertex_index + 2]);
  };
  if (allNormals) {
    std::map<std::pair<int, int>, std::uint32_t> vertexOf;  // (position, normal) -> vertex
    for (const tinyobj::shape_t& shape : reader.GetShapes())
      for (const tinyobj::index_t& i : shape.mesh.indices) {
        const auto [it, added] = vertexOf.emplace(std::pair(i.vertex_index, i.normal_index),
                                                  static_cast<std::uint32_t>(mesh.positions.size()));
        if (added) {
          mesh.positions.push_back(position(i));
          const glm::vec3 n(attrib.normals[3 * i.normal_index], attrib.normals[3 * i.normal_index + 1],
                            attrib.normals[3 * i.normal_index + 2]);
          mesh.normals.push_back(glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 1, 0));
        }
        mesh.indices.push_back(it->second);
      }
  } else {
    for (const tinyobj::shape_t& shape : reader.GetShapes())
      for (std::size_t c = 0; c + 2 < shape.mesh.indices.size(); c += 3) {
        const glm::vec3 a = position(shape.mesh.indices[c]), b = position(shape.mesh.indices[c + 1]),
                        d = position(shape.mesh.indices[c + 2]);
        const glm::vec3 n = glm::cross(b - a, d - a);
        // A zero-area triangle draws nothing; any unit normal keeps the arrays finite.
        const glm::vec3 normal = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 1, 0);
        for (const glm::vec3& p : {a, b, d}) {
          mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
          mesh.positions.push_back(p);
          mesh.normals.push_back(normal);
        }
      }
  }
  if (const auto bad = firstNonFiniteVertex(mesh))
    line.fail("mesh '" + path.string() + "' has a vertex that is not finite (vertex " +
              std::to_string(*bad + 1) + ")");
  return mesh;
}

Mesh readShape(LineReader& line, const std::string& shape, const std::filesystem::path& sceneFile) {
  if (shape == "plane") {
    ShapeParams p(line, shape, {"half", "divisions"});
    return makePlane(p.positive("half", 5.0f), p.count("divisions", 1, 1));
  }
  if (shape == "box") {
    ShapeParams p(line, shape, {"half"});
    const glm::vec3 half = p.half("half", 0.5f);
    if (glm::any(glm::lessThanEqual(half, glm::vec3(0.0f)))) line.fail("expected half sizes greater than 0");
    return transformed(makeCube(1.0f), glm::scale(glm::mat4(1.0f), half));
  }
  if (shape == "sphere") {
    ShapeParams p(line, shape, {"radius", "slices", "stacks"});
    return makeSphere(p.positive("radius", 1.0f), p.count("slices", 32, 3), p.count("stacks", 16, 2));
  }
  if (shape == "cylinder" || shape == "cone") {
    ShapeParams p(line, shape, {"radius", "height", "slices"});
    const float radius = p.positive("radius", 0.5f), height = p.positive("height", 1.0f);
    const int slices = p.count("slices", 32, 3);
    return shape == "cylinder" ? makeCylinder(radius, height, slices) : makeCone(radius, height, slices);
  }
  if (shape == "torus") {
    ShapeParams p(line, shape, {"major", "minor", "segments", "sides"});
    const float major = p.positive("major", 1.0f), minor = p.positive("minor", 0.25f);
    if (!(minor < major)) line.fail("expected the torus's minor radius less than its major radius");
    return makeTorus(major, minor, p.count("segments", 32, 3), p.count("sides", 16, 3));
  }
  if (shape == "stairs") {
    ShapeParams p(line, shape, {"steps", "width", "rise", "run"});
    return makeStairs(p.count("steps", 5, 1), p.positive("width", 1.0f), p.positive("rise", 0.2f),
                      p.positive("run", 0.3f));
  }
  if (shape == "mesh") {
    const std::string file = line.word("an OBJ file name after 'mesh'");
    line.end();
    const std::filesystem::path path = sceneFile.parent_path() / file;
    return loadObj(path, line);
  }
  line.fail("unknown shape '" + shape +
            "'; expected plane, box, sphere, cylinder, cone, torus, stairs or mesh");
}

void readCamera(LineReader& line, SceneCamera& camera) {
  bool eye = false, target = false, nearGiven = false, farGiven = false;
  std::set<std::string> seen;
  while (!line.done()) {
    const std::string key = line.word("a camera setting");
    if (!seen.insert(key).second) line.fail("camera setting '" + key + "' given twice");
    if (key == "eye") {
      camera.eye = line.vec3("the eye");
      eye = true;
    } else if (key == "target") {
      camera.target = line.vec3("the target");
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
      line.fail("unknown camera setting '" + key +
                "'; expected eye, target, up, fovy, near, far, orthographic or mirrored");
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

void readLight(LineReader& line, SceneLight& light) {
  const std::string type = line.word("the light's type (point or directional)");
  if (type == "point")
    light.position = glm::vec4(line.vec3("the light's position"), 1.0f);
  else if (type == "directional")
    light.position = glm::vec4(line.direction("the direction towards the light"), 0.0f);
  else
    line.fail("expected the light's type (point or directional), got '" + type + "'");
  std::set<std::string> seen;
  while (!line.done()) {
    const std::string key = line.word("a light setting");
    if (!seen.insert(key).second) line.fail("light setting '" + key + "' given twice");
    if (key == "color")
      light.color = line.color();
    else if (key == "radius") {
      if (type != "point") line.fail("a directional light has no radius: its light reaches everywhere");
      light.radius = line.positive("the light's radius");
    } else
      line.fail("unknown light setting '" + key + "'; expected color" +
                (type == "point" ? " or radius" : ""));
  }
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
    if (!line.done()) s = glm::vec3(s.x, line.number("the scale y"), line.number("the scale z"));
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f)
      line.fail("expected a scale other than 0 (it flattens the object)");
    object.model = glm::scale(glm::mat4(1.0f), s) * object.model;
  } else if (key == "color")
    object.color = line.color();
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
    line.fail("unknown object setting '" + key +
              "'; expected translate, rotate, scale, color, casts, receives, spin or bob");
  line.end();
}

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

Scene parseScene(std::string_view text, const std::filesystem::path& file) {
  Scene scene;
  scene.file = file;
  const std::string name = file.string();
  bool haveCamera = false, haveAmbient = false;
  bool inObject = false;  // the last unindented line was an object: indented lines are its settings
  std::vector<int> objectLines;
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
      scene.ambient = line.color();
      line.end();
    } else if (keyword == "light") {
      readLight(line, scene.lights.emplace_back());
    } else if (keyword == "object") {
      SceneObject object;
      object.name = line.word("the object's name");
      for (const SceneObject& o : scene.objects)
        if (o.name == object.name) line.fail("a second object named '" + object.name + "'");
      const std::string shape = line.word("the object's shape");
      try {
        object.mesh = readShape(line, shape, file);
      } catch (const std::invalid_argument& e) {
        line.fail(e.what());
      }
      scene.objects.push_back(std::move(object));
      objectLines.push_back(lineNumber);
      inObject = true;
    } else {
      line.fail("unknown keyword '" + keyword +
                "'; expected camera, ambient, light or object (settings of an object are indented)");
    }
  }
  // Casters are prepared once their settings are read: 'casts no' spares a mesh that cannot cast.
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    SceneObject& o = scene.objects[i];
    if (!o.casts) continue;
    o.caster = prepareCaster(o.mesh);
    if (!o.caster.report.usable()) {
      std::string problems;
      for (const std::string& m : o.caster.report.messages)
        if (m.starts_with("not two-manifold") || m.starts_with("inconsistently wound"))
          problems += (problems.empty() ? "" : "; ") + m;
      throw SceneError(name + ":" + std::to_string(objectLines[i]) + ": object '" + o.name +
                       "' cannot cast shadow volumes: " + problems +
                       " (repair the mesh, or give it 'casts no')");
    }
  }
  const std::string end = name + ":" + std::to_string(std::max(lineNumber, 1)) + ": ";
  if (!haveCamera) throw SceneError(end + "the scene has no camera line");
  if (scene.lights.empty()) throw SceneError(end + "the scene has no light");
  if (scene.objects.empty()) throw SceneError(end + "the scene has no object");
  return scene;
}

Scene loadScene(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file.string() + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), file);
}

}  // namespace stencil
