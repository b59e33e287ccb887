// Lesson 14 beside OpenCSG (Debian's libopencsg-dev, 1.5), on OpenCSG's own scenes
// (tests/scenes/opencsg/, its example program's shapes and camera), in one run: per size, per
// scene, rounds of every OpenCSG setting and every lesson 14 method in turn. Each measurement is
// the median of N frames, each frame ended by one glFinish and timed on the wall clock, without
// per-pass queries (the lesson runs with --stats-frames); the figure kept is the median of the
// rounds' medians. Beside the time: the draw calls of one frame (OpenCSG's: its calls to the
// primitives' render() and the shading pass's draws; the lesson's: its --stats draw_calls), the
// pixels the solid covers, and the pixels whose coverage differs from OpenCSG Automatic with
// bounding boxes (the lesson's: its stencil's primitive tags; OpenCSG's: a depth nearer than the
// far plane).
//
// OpenCSG 1.5 draws with the fixed-function pipeline and needs GLEW, so it runs in a GLX
// compatibility context, on a pbuffer (an X display: xvfb-run without one); the lesson runs as
// its own program, headless, as a user runs it. Both contexts are Mesa's llvmpipe here; the CSV
// names each renderer.
//
//   csg_opencsg_benchmark OUT [--quick] [--goal] [--scene NAME]... [--check] [--page FILE.md]
//
// writes OUT.csv (one row per size, scene and method) and OUT.md (the table for the page, with the
// machine and its load); --page FILE.md puts OUT.md into FILE.md between its markers
// <!-- opencsg-benchmark begin --> and <!-- opencsg-benchmark end -->. tests/sweeps/plot_sweeps.py
// draws OUT.svg from the CSV. --quick: 320x240, three scenes, three frames. --goal: only the
// comparison the lesson's automatic method is held to (OpenCSG Automatic, with and without
// bounding boxes, and the lesson's automatic method), three rounds. --scene NAME: that scene only
// (repeatable). --check: exit 1 unless every lesson 14 method that accepts a scene agrees with the
// CSG ray cast off its edges (its own --set oracle=1) and the lesson's automatic method shows
// the ray cast's primitive and depth on at least as many edge pixels as OpenCSG Automatic with
// bounding boxes, or on a GL error. Exit 77 without an X display or a GLX context.
//
// Both sides are judged by the same CSG ray cast (geometry/csg.h: rayCastCsg, csgEdgePixels,
// compareCsg, as lesson 14's oracle): OpenCSG's picture through an untimed pass after its frame
// that draws each object's index where the shading pass drew it.
#include <GL/glew.h>
// GLEW before GL: GL/glx.h includes GL/gl.h.
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <opencsg.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "csg_bench_lesson_side.h"
#include "geometry/csg.h"
#include "geometry/scene.h"
#include "gl/context.h"
#include "lesson_stats.h"

namespace fs = std::filesystem;

namespace {

struct Size {
  int width, height;
  std::string text() const { return std::to_string(width) + "x" + std::to_string(height); }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Row {
  std::string size, scene, renderer, method;
  int primitives = 0;
  std::vector<double> roundMedians, roundCpuMedians;  // wall and CPU milliseconds a frame, per round
  long long draws = 0, covered = 0, coverageDiff = -1;
  // Against the CSG ray cast (geometry/csg.h's compareCsg): pixels showing another primitive or
  // depth, off the edges the geometry decides and on them; -1 where not judged.
  long long offEdges = -1, onEdges = -1;
  double medianMs() const { return median(roundMedians); }
  double medianCpuMs() const { return median(roundCpuMedians); }
};

// ---- the GLX context ------------------------------------------------------------------------------

struct Glx {
  Display* display = nullptr;
  GLXFBConfig config{};
  GLXContext context = nullptr;
  GLXPbuffer pbuffer = 0;
  std::string renderer;

  // A compatibility context (glXCreateNewContext: the legacy profile OpenCSG 1.5 draws with) and a
  // pbuffer of the size with 8 bits of stencil and 24 of depth. False with a line on stderr.
  bool open() {
    display = XOpenDisplay(nullptr);
    if (!display) {
      std::cerr << "csg_opencsg_benchmark: no X display (OpenCSG needs GLX: run under xvfb-run -a)\n";
      return false;
    }
    const int attributes[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8,
                              GLX_GREEN_SIZE,    8,               GLX_BLUE_SIZE,   8,            GLX_DEPTH_SIZE, 24,
                              GLX_STENCIL_SIZE,  8,               None};
    int count = 0;
    GLXFBConfig* configs = glXChooseFBConfig(display, DefaultScreen(display), attributes, &count);
    if (!configs || count == 0) {
      std::cerr << "csg_opencsg_benchmark: the X display has no GLX pbuffer config with depth 24 and stencil 8\n";
      return false;
    }
    config = configs[0];
    XFree(configs);
    context = glXCreateNewContext(display, config, GLX_RGBA_TYPE, nullptr, True);
    if (!context) {
      std::cerr << "csg_opencsg_benchmark: glXCreateNewContext failed\n";
      return false;
    }
    return true;
  }

  bool use(const Size& s) {
    if (pbuffer) {
      glXMakeContextCurrent(display, None, None, nullptr);
      glXDestroyPbuffer(display, pbuffer);
    }
    const int attributes[] = {GLX_PBUFFER_WIDTH, s.width, GLX_PBUFFER_HEIGHT, s.height, None};
    pbuffer = glXCreatePbuffer(display, config, attributes);
    if (!pbuffer || !glXMakeContextCurrent(display, pbuffer, pbuffer, context)) {
      std::cerr << "csg_opencsg_benchmark: cannot make a " << s.text() << " pbuffer current\n";
      return false;
    }
    glewExperimental = GL_TRUE;
    if (glewInit() != GLEW_OK) {
      std::cerr << "csg_opencsg_benchmark: glewInit failed\n";
      return false;
    }
    renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    glViewport(0, 0, s.width, s.height);
    return true;
  }

  ~Glx() {
    if (!display) return;
    glXMakeContextCurrent(display, None, None, nullptr);
    if (pbuffer) glXDestroyPbuffer(display, pbuffer);
    if (context) glXDestroyContext(display, context);
    XCloseDisplay(display);
  }
};

// ---- the scene for OpenCSG -------------------------------------------------------------------------

// One object's triangles in buffers: positions for OpenCSG's passes, normals for the shading pass.
struct GlMesh {
  GLuint positions = 0, normals = 0, indices = 0;
  GLsizei count = 0;
  glm::vec3 low{0}, high{0};  // its object-space bounding box

  explicit GlMesh(const stencil::Mesh& m) {
    glGenBuffers(1, &positions);
    glBindBuffer(GL_ARRAY_BUFFER, positions);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.positions.size() * sizeof(glm::vec3)),
                 m.positions.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &normals);
    glBindBuffer(GL_ARRAY_BUFFER, normals);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.normals.size() * sizeof(glm::vec3)), m.normals.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glGenBuffers(1, &indices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)),
                 m.indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    count = static_cast<GLsizei>(m.indices.size());
    low = high = m.positions.front();
    for (const glm::vec3& p : m.positions) low = glm::min(low, p), high = glm::max(high, p);
  }
  GlMesh(const GlMesh&) = delete;
  GlMesh& operator=(const GlMesh&) = delete;
  ~GlMesh() {
    glDeleteBuffers(1, &positions);
    glDeleteBuffers(1, &normals);
    glDeleteBuffers(1, &indices);
  }

  void draw(bool withNormals) const {
    glBindBuffer(GL_ARRAY_BUFFER, positions);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, nullptr);
    if (withNormals) {
      glBindBuffer(GL_ARRAY_BUFFER, normals);
      glEnableClientState(GL_NORMAL_ARRAY);
      glNormalPointer(GL_FLOAT, 0, nullptr);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisableClientState(GL_VERTEX_ARRAY);
    if (withNormals) glDisableClientState(GL_NORMAL_ARRAY);
  }
};

long long drawCount = 0;  // draws in the current frame

// An OpenCSG primitive: an object of the scene file, drawn with its model matrix on the view
// (the modelview OpenCSG finds set).
class MeshPrimitive final : public OpenCSG::Primitive {
 public:
  MeshPrimitive(int object, const GlMesh& mesh, const glm::mat4& model, const glm::vec3& colour,
                OpenCSG::Operation op, unsigned convexity)
      : OpenCSG::Primitive(op, convexity), object_(object), mesh_(mesh), model_(model), colour_(colour) {}
  void render() override {
    glPushMatrix();
    glMultMatrixf(&model_[0][0]);
    mesh_.draw(false);
    glPopMatrix();
    ++drawCount;
  }
  // Its bounding box in normalized device coordinates (OpenCSG's setBoundingBox), or the whole
  // view where a corner of its box lies behind the eye.
  void boundInView(const glm::mat4& viewProjection) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p((c & 1) ? mesh_.high.x : mesh_.low.x, (c & 2) ? mesh_.high.y : mesh_.low.y,
                        (c & 4) ? mesh_.high.z : mesh_.low.z);
      const glm::vec4 clip = viewProjection * model_ * glm::vec4(p, 1.0f);
      if (clip.w <= 0.0f) {
        setBoundingBox(-1, -1, -1, 1, 1, 1);
        return;
      }
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      lo = glm::min(lo, ndc), hi = glm::max(hi, ndc);
    }
    lo = glm::clamp(lo, glm::vec3(-1), glm::vec3(1)), hi = glm::clamp(hi, glm::vec3(-1), glm::vec3(1));
    setBoundingBox(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  }
  void unbound() { setBoundingBox(-1, -1, -1, 1, 1, 1); }  // OpenCSG's default: no bound
  int object() const { return object_; }  // its index in the scene file's objects
  const GlMesh& mesh() const { return mesh_; }
  const glm::mat4& model() const { return model_; }
  const glm::vec3& colour() const { return colour_; }

 private:
  int object_;
  const GlMesh& mesh_;
  glm::mat4 model_;
  glm::vec3 colour_;
};

struct OpenCsgSetting {
  std::string name;
  int algorithm, depthComplexity;
  bool boundingBoxes;
};

// The scene as OpenCSG draws it: a product (one OpenCSG::render call) per product of the csg
// line's sum of products, each primitive that product's intersected and subtracted objects.
struct OpenCsgScene {
  std::vector<std::unique_ptr<GlMesh>> meshes;
  std::vector<std::vector<std::unique_ptr<MeshPrimitive>>> products;

  OpenCsgScene(const stencil::Scene& scene, unsigned convexity) {
    std::vector<std::string> names;
    for (const auto& o : scene.objects) {
      names.push_back(o.name);
      meshes.push_back(std::make_unique<GlMesh>(o.mesh));
    }
    const stencil::SumOfProducts sop = stencil::normalize(stencil::parseCsg(scene.csg, names));
    for (const stencil::CsgProduct& p : sop.products) {
      auto& prims = products.emplace_back();
      for (int i : p.intersected)
        prims.push_back(std::make_unique<MeshPrimitive>(i, *meshes[i], scene.objects[i].modelAt(0),
                                                        scene.objects[i].colour, OpenCSG::Intersection, convexity));
      for (int i : p.subtracted)
        prims.push_back(std::make_unique<MeshPrimitive>(i, *meshes[i], scene.objects[i].modelAt(0),
                                                        scene.objects[i].colour, OpenCSG::Subtraction, convexity));
    }
  }

  // One frame as OpenCSG's example draws it: OpenCSG::render per product (the depth of the
  // solid), then each product's primitives shaded where their depth is the solid's (GL_EQUAL).
  void frame(const OpenCsgSetting& s, const glm::mat4& view, const glm::mat4& projection) {
    OpenCSG::setOption(OpenCSG::AlgorithmSetting, s.algorithm);
    OpenCSG::setOption(OpenCSG::DepthComplexitySetting, s.depthComplexity);
    const glm::mat4 viewProjection = projection * view;
    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(&projection[0][0]);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(&view[0][0]);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (auto& prims : products) {
      std::vector<OpenCSG::Primitive*> list;
      for (auto& p : prims) {
        if (s.boundingBoxes)
          p->boundInView(viewProjection);  // per frame, as an application whose view moves does
        else
          p->unbound();
        list.push_back(p.get());
      }
      OpenCSG::render(list);
    }
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glDepthFunc(GL_EQUAL);
    for (auto& prims : products)
      for (auto& p : prims) {
        const glm::vec3& c = p->colour();
        glColor3f(c.r, c.g, c.b);
        glPushMatrix();
        glMultMatrixf(&p->model()[0][0]);
        p->mesh().draw(true);
        glPopMatrix();
        ++drawCount;
      }
    glDepthFunc(GL_LESS);
    glDisable(GL_LIGHTING);
  }

  // After a frame: which object each pixel shows, as the frame's shading pass chose it (its
  // draws in the same order, GL_EQUAL against the solid's depth, the last one drawn winning a
  // tie), and the depth; top row first, stencil::kNoSurface where nothing is drawn. Untimed.
  void seen(const Size& size, std::vector<int>& object, std::vector<float>& depth) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DITHER);
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    for (auto& prims : products)
      for (auto& p : prims) {
        const unsigned id = static_cast<unsigned>(p->object()) + 1;  // 0: nothing drawn
        glColor3ub(static_cast<GLubyte>(id >> 16), static_cast<GLubyte>(id >> 8), static_cast<GLubyte>(id));
        glPushMatrix();
        glMultMatrixf(&p->model()[0][0]);
        p->mesh().draw(false);
        glPopMatrix();
      }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    const std::size_t w = static_cast<std::size_t>(size.width), h = static_cast<std::size_t>(size.height);
    std::vector<GLubyte> rgb(w * h * 3);
    std::vector<float> rows(w * h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.width, size.height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    glReadPixels(0, 0, size.width, size.height, GL_DEPTH_COMPONENT, GL_FLOAT, rows.data());
    object.assign(w * h, stencil::kNoSurface);
    depth.assign(w * h, 1.0f);
    for (std::size_t i = 0; i < w * h; ++i) {
      const std::size_t row = (h - 1 - i / w) * w + i % w;  // GL's rows bottom up
      const unsigned id = (unsigned{rgb[3 * row]} << 16) | (unsigned{rgb[3 * row + 1]} << 8) | rgb[3 * row + 2];
      object[i] = id == 0 ? stencil::kNoSurface : static_cast<int>(id) - 1;
      depth[i] = rows[row];
    }
  }
};

// Pixels whose depth is nearer than the far plane, top row first.
std::vector<std::uint8_t> coveredByDepth(const Size& s) {
  std::vector<float> depth(static_cast<std::size_t>(s.width) * s.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, s.width, s.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  std::vector<std::uint8_t> covered(depth.size());
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      covered[static_cast<std::size_t>(s.height - 1 - y) * s.width + x] =
          depth[static_cast<std::size_t>(y) * s.width + x] < 1.0f;
  return covered;
}

long long countSet(const std::vector<std::uint8_t>& v) {
  return std::count_if(v.begin(), v.end(), [](std::uint8_t b) { return b != 0; });
}
long long countDiffering(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  long long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += (a[i] != 0) != (b[i] != 0);
  return n;
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string commandOutput(const char* command) {
  std::string out;
  if (FILE* p = popen(command, "r")) {
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, p)) out += buffer;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

struct LessonMethod {
  std::string name, settings;
  bool convexOnly = false;  // SCS: refuses nothing, draws a concave primitive wrong
};

enum class Table { Wall, Cpu, RayCast };  // the page's tables per size

struct BenchScene {
  std::string name;
  bool concave = false;
  bool tooSlowForMost = false;  // the cube rack: OpenCSG's SCS settings and the lesson's automatic only
};

}  // namespace

int main(int argc, char** argv) {
  stencil::keepFreedHeap();  // OpenCSG's side keeps its heap as the lesson's does
  // Every argument is read, and every mistake refused (exit 2), before X is opened (77 without it).
  const auto usage = [](const std::string& why) {
    std::cerr << "csg_opencsg_benchmark: " << why << " (--help)\n";
    return 2;
  };
  if (argc >= 2 && std::string(argv[1]) == "--help") {
    std::cout
        << "usage: csg_opencsg_benchmark OUT [--quick] [--goal] [--scene NAME]... [--check] [--page F.md]\n"
           "  OUT        the output's path without extension: writes OUT.csv and OUT.md (the page's table)\n"
           "  --quick    320x240, three scenes, three frames\n"
           "  --goal     OpenCSG Automatic, with and without bounding boxes, and lesson 14's automatic\n"
           "             method only, three rounds\n"
           "  --scene N  that scene only (repeatable): simple widget grid2d grid3d pipe concave cuberack\n"
           "  --check    exit 1 unless every lesson 14 method that accepts a scene agrees with the CSG ray\n"
           "             cast off its edges and the automatic method is right on at least as many edge\n"
           "             pixels as OpenCSG Automatic with bounding boxes\n"
           "  --page F   rewrites F.md's table between <!-- opencsg-benchmark begin --> and\n"
           "             <!-- opencsg-benchmark end --> with OUT.md\n"
           "exit: 0 done (and checked); 1 a check failed or a GL error; 2 bad arguments;\n"
           "  77 no X display or GLX context (run under xvfb-run -a)\n";
    return 0;
  }
  if (argc < 2) return usage("OUT expected: the output's path without extension");
  const std::string first = argv[1];
  if (first.empty() || first[0] == '-')
    return usage("OUT expected first, got '" + first + "': the output's path without extension may not start with '-'");
  const fs::path out = first;
  bool quick = false, check = false, goal = false;
  std::vector<std::string> only;
  std::optional<fs::path> page;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const bool takesValue = a == "--scene" || a == "--page";
    if (takesValue && (i + 1 >= argc || argv[i + 1][0] == '-' || argv[i + 1][0] == '\0'))
      return usage(a + (a == "--scene" ? " needs a scene name" : " needs a page FILE.md"));
    if (a == "--quick")
      quick = true;
    else if (a == "--check")
      check = true;
    else if (a == "--goal")
      goal = true;
    else if (a == "--scene")
      only.push_back(argv[++i]);
    else if (a == "--page")
      page = argv[++i];
    else
      return usage("unknown flag '" + a + "'");
  }
  const std::string beginMarker = "<!-- opencsg-benchmark begin -->\n", endMarker = "<!-- opencsg-benchmark end -->";
  std::string pageText;
  if (page) {
    std::ifstream in(*page);
    std::stringstream s;
    s << in.rdbuf();
    pageText = s.str();
    const auto b = pageText.find(beginMarker), e = pageText.find(endMarker);
    if (!in || b == std::string::npos || e == std::string::npos || e < b) {
      std::cerr << "csg_opencsg_benchmark: --page " << page->string()
                << ": not a readable page with the markers <!-- opencsg-benchmark begin --> and <!-- "
                   "opencsg-benchmark end -->\n";
      return 2;
    }
  }
  std::vector<BenchScene> scenes =
      quick ? std::vector<BenchScene>{{"simple"}, {"grid2d"}, {"concave", true}}
            : std::vector<BenchScene>{{"simple"},  {"widget"}, {"grid2d"},         {"grid3d"},
                                      {"pipe"},    {"concave", true}, {"cuberack", false, true}};
  for (const std::string& name : only)
    if (std::none_of(scenes.begin(), scenes.end(), [&](const BenchScene& b) { return b.name == name; })) {
      std::cerr << "csg_opencsg_benchmark: --scene " << name << ": not a benchmark scene (--help)\n";
      return 2;
    }
  if (!only.empty())
    std::erase_if(scenes, [&](const BenchScene& b) { return std::find(only.begin(), only.end(), b.name) == only.end(); });

  Glx glx;
  if (!glx.open()) return 77;
  const fs::path work = fs::temp_directory_path() / ("csg_opencsg_benchmark-" + std::to_string(getpid()));
  fs::create_directories(work);
  fs::create_directories(fs::absolute(out).parent_path());


  const std::vector<Size> sizes = quick ? std::vector<Size>{{320, 240}} : std::vector<Size>{{320, 240}, {640, 480}};
  // The first frames pay for set-up (llvmpipe compiles a shader variant at a state's first use,
  // over the first few frames): left out of both sides' medians. The lesson starts a process of
  // its own for each measurement, cold: on the pipe at 640x480 its first seven frames took 35, 11-14,
  // 9-10 and 6-9 ms, then 5.5-5.8 from the eighth on, so eight are left out.
  const int warmup = 8, frames = 5, rounds = quick ? 1 : goal ? 3 : 2;
  // A measurement whose first round's median is longer than this is not repeated: its rounds'
  // spread is a small part of it, and the run stays within minutes.
  constexpr double kRepeatBelowMs = 400.0;
  const std::vector<OpenCsgSetting> settings = {
      {"goldfeather", OpenCSG::Goldfeather, OpenCSG::NoDepthComplexitySampling, false},
      {"goldfeather+dc", OpenCSG::Goldfeather, OpenCSG::DepthComplexitySampling, false},
      {"goldfeather+oq", OpenCSG::Goldfeather, OpenCSG::OcclusionQuery, false},
      {"scs", OpenCSG::SCS, OpenCSG::NoDepthComplexitySampling, false},
      {"scs+oq", OpenCSG::SCS, OpenCSG::OcclusionQuery, false},
      {"automatic", OpenCSG::Automatic, OpenCSG::NoDepthComplexitySampling, false},
      {"automatic+bbox", OpenCSG::Automatic, OpenCSG::NoDepthComplexitySampling, true},
  };
  const std::vector<LessonMethod> methods = {
      {"goldfeather", "--set method=1"},
      {"goldfeather+queries", "--set method=1 --set queries=1"},
      {"layered", "--set method=2"},
      {"layered+queries", "--set method=2 --set queries=1"},
      {"scs", "--set method=3", true},
      {"automatic", "--set method=4"},
  };
  const fs::path sceneDir = fs::path(SOURCE_DIR) / "tests/scenes/opencsg";

  std::vector<Row> rows;
  std::string lessonRenderer;
  bool ok = true;
  for (const Size& size : sizes) {
    if (!glx.use(size)) return 77;
    for (const BenchScene& bs : scenes) {
      const fs::path file = sceneDir / (bs.name + ".scene");
      const stencil::Scene scene = stencil::loadScene(file);
      glm::mat4 view, projection;
      csgbench::lessonCamera(scene.camera, size.width, size.height, view, projection);
      const unsigned convexity = bs.concave ? 2 : 1;
      OpenCsgScene ocsg(scene, convexity);
      const int primitives = static_cast<int>(scene.objects.size());
      // The CSG ray cast of the scene and the pixels its edges cross, as lesson 14's --set oracle=1
      // makes them (oracle.cpp), once per scene and size: what each side's picture is judged by.
      std::vector<stencil::CsgPrimitive> csgPrimitives;
      std::vector<std::string> names;
      for (const auto& o : scene.objects) {
        csgPrimitives.push_back({&o.mesh, o.modelAt(0)});
        names.push_back(o.name);
      }
      const stencil::CsgImage rayCast =
          stencil::rayCastCsg(csgPrimitives, stencil::parseCsg(scene.csg, names), projection * view,
                              {size.width, size.height});
      GLint subpixelBits = 4;
      glGetIntegerv(GL_SUBPIXEL_BITS, &subpixelBits);
      const float snap = std::ldexp(1.0f, -std::max(subpixelBits, 4));
      const std::vector<bool> edges =
          stencil::csgEdgePixels(csgPrimitives, projection * view, {size.width, size.height}, snap);

      // This scene's rows, in the order they are measured each round.
      std::vector<Row> sceneRows;
      std::vector<const OpenCsgSetting*> rowSetting;
      std::vector<const LessonMethod*> rowMethod;
      for (const OpenCsgSetting& s : settings) {
        if (goal && s.algorithm != OpenCSG::Automatic) continue;
        if (bs.concave && s.algorithm == OpenCSG::SCS) continue;  // SCS: convex primitives only
        // The cube rack: Goldfeather's parity passes grow as n (n - 1), and its depth complexity
        // sampling (k n) took minutes a frame here too.
        if (bs.tooSlowForMost && s.algorithm == OpenCSG::Goldfeather) continue;
        if (bs.tooSlowForMost && s.name == "scs") continue;
        sceneRows.emplace_back();
        sceneRows.back().size = size.text(), sceneRows.back().scene = bs.name, sceneRows.back().renderer = "opencsg";
        sceneRows.back().method = s.name, sceneRows.back().primitives = primitives;
        rowSetting.push_back(&s);
        rowMethod.push_back(nullptr);
      }
      for (const LessonMethod& m : methods) {
        if (goal && m.name != "automatic") continue;
        if (bs.concave && m.convexOnly) continue;
        // The cube rack's depth complexity runs to dozens of layers: the layered methods take
        // tens of seconds a frame there, so the rack is the automatic method's alone.
        if (bs.tooSlowForMost && m.name != "automatic") continue;
        sceneRows.emplace_back();
        sceneRows.back().size = size.text(), sceneRows.back().scene = bs.name, sceneRows.back().renderer = "lesson14";
        sceneRows.back().method = m.name, sceneRows.back().primitives = primitives;
        rowSetting.push_back(nullptr);
        rowMethod.push_back(&m);
      }
      std::vector<std::vector<std::uint8_t>> coverage(sceneRows.size());
      for (int round = 0; round < rounds; ++round) {
        for (std::size_t r = 0; r < sceneRows.size(); ++r) {
          Row& row = sceneRows[r];
          if (round > 0 && row.roundMedians.front() > kRepeatBelowMs) continue;
          if (rowSetting[r]) {
            std::vector<double> ms, cpuMs;
            for (int f = 0; f < warmup + frames; ++f) {
              drawCount = 0;
              const auto start = std::chrono::steady_clock::now();
              const std::clock_t cpuStart = std::clock();  // the process's: llvmpipe's threads too
              ocsg.frame(*rowSetting[r], view, projection);
              glFinish();
              const double t =
                  std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
              const double cpu = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
              if (f >= warmup) ms.push_back(t), cpuMs.push_back(cpu);
            }
            row.roundMedians.push_back(median(ms));
            row.roundCpuMedians.push_back(median(cpuMs));
            row.draws = drawCount;
            if (round == 0) {
              coverage[r] = coveredByDepth(size);
              std::vector<int> object;
              std::vector<float> depth;
              ocsg.seen(size, object, depth);
              const stencil::CsgReport report =
                  stencil::compareCsg(rayCast, depth, object, edges, 4.0f * std::ldexp(1.0f, -24), snap);
              row.onEdges = static_cast<long long>(report.onEdges);
              row.offEdges =
                  static_cast<long long>(report.primitiveDisagreements + report.depthDisagreements - report.onEdges);
            }
            if (GLenum e = glGetError(); e != GL_NO_ERROR) {
              std::cerr << "csg_opencsg_benchmark: GL error 0x" << std::hex << e << std::dec << " in OpenCSG "
                        << row.method << " on " << bs.name << "\n";
              ok = false;
            }
          } else {
            const LessonMethod& m = *rowMethod[r];
            const fs::path stats = work / "stats.json", stencilOut = work / "stencil.png";
            const std::string command =
                std::string(LESSON_14) + " --headless --quiet --size " + size.text() + " --scene " +
                shellQuote(file.string()) + " " + m.settings + (bs.concave ? " --set convexity=2" : "") +
                " --stats-frames --frames " + std::to_string(warmup + frames) +
                (round == 0 ? " --stencil-out " + shellQuote(stencilOut.string()) : std::string()) + " > " +
                shellQuote(stats.string());
            const int status = std::system(command.c_str());
            if (status != 0) {
              std::cerr << "csg_opencsg_benchmark: failed (" << status << "): " << command << "\n";
              return WIFEXITED(status) && WEXITSTATUS(status) == 77 ? 77 : 1;
            }
            const auto json = stencil::testing::LessonStats::read(stats);
            std::vector<double> ms;
            for (const auto& t : json.json().at("frame_ms").at("all")) ms.push_back(t.get<double>());
            ms.erase(ms.begin(), ms.begin() + warmup);
            row.roundMedians.push_back(median(ms));
            std::vector<double> cpuMs;
            for (const auto& t : json.json().at("frame_cpu_ms").at("all")) cpuMs.push_back(t.get<double>());
            cpuMs.erase(cpuMs.begin(), cpuMs.begin() + warmup);
            row.roundCpuMedians.push_back(median(cpuMs));
            row.draws = json.total("draw_calls");
            if (lessonRenderer.empty()) lessonRenderer = json.json().at("renderer").get<std::string>();
            if (round == 0) {
              coverage[r] = csgbench::readRawStencil(work / "stencil.raw.png", size.width, size.height);
              // The same judgement, from the lesson's own oracle: one more frame, untimed.
              const std::string judged = std::string(LESSON_14) + " --headless --quiet --size " + size.text() +
                                         " --scene " + shellQuote(file.string()) + " " + m.settings +
                                         (bs.concave ? " --set convexity=2" : "") + " --set oracle=1 --stats > " +
                                         shellQuote(stats.string()) + " 2> /dev/null";
              // Exit 1: the oracle found pixels wrong off the edges; its counts say how many.
              if (const int judgedStatus = std::system(judged.c_str());
                  !WIFEXITED(judgedStatus) || WEXITSTATUS(judgedStatus) > 1) {
                std::cerr << "csg_opencsg_benchmark: failed (" << judgedStatus << "): " << judged << "\n";
                return 1;
              }
              const auto oracle = stencil::testing::LessonStats::read(stats);
              row.onEdges = static_cast<long long>(oracle.count("oracle_on_edges"));
              row.offEdges = static_cast<long long>(oracle.count("oracle_primitive_disagreements") +
                                                    oracle.count("oracle_depth_disagreements")) -
                             row.onEdges;
            }
          }
          std::fprintf(stderr, "bench: %s %-9s %-8s %-20s %9.2f ms %9.2f CPU ms %7lld draws\n",
                       size.text().c_str(), bs.name.c_str(), row.renderer.c_str(), row.method.c_str(),
                       row.roundMedians.back(), row.roundCpuMedians.back(), row.draws);
        }
      }
      // Coverage against OpenCSG Automatic's picture (measured on every scene).
      std::size_t reference = 0;
      for (std::size_t r = 0; r < sceneRows.size(); ++r)
        if (sceneRows[r].renderer == "opencsg" && sceneRows[r].method == "automatic") reference = r;
      for (std::size_t r = 0; r < sceneRows.size(); ++r) {
        sceneRows[r].covered = countSet(coverage[r]);
        sceneRows[r].coverageDiff = countDiffering(coverage[r], coverage[reference]);
        if (sceneRows[r].coverageDiff != 0)
          std::fprintf(stderr, "bench: %s %s %s %s: %lld pixels covered other than by OpenCSG automatic\n",
                       size.text().c_str(), bs.name.c_str(), sceneRows[r].renderer.c_str(),
                       sceneRows[r].method.c_str(), sceneRows[r].coverageDiff);
        if (sceneRows[r].renderer == "lesson14" && sceneRows[r].offEdges != 0) {
          std::fprintf(stderr, "bench: %s %s lesson14 %s: %lld pixels off the ray cast, off its edges\n",
                       size.text().c_str(), bs.name.c_str(), sceneRows[r].method.c_str(), sceneRows[r].offEdges);
          ok = false;
        }
        rows.push_back(sceneRows[r]);
      }
      // On the edges: the lesson's automatic method right at least as often as OpenCSG's.
      const Row* lessonAutomatic = nullptr;
      const Row* openCsgBoxes = nullptr;
      for (const Row& row : sceneRows) {
        if (row.renderer == "lesson14" && row.method == "automatic") lessonAutomatic = &row;
        if (row.renderer == "opencsg" && row.method == "automatic+bbox") openCsgBoxes = &row;
      }
      if (lessonAutomatic && openCsgBoxes && lessonAutomatic->onEdges > openCsgBoxes->onEdges) {
        std::fprintf(stderr,
                     "bench: %s %s: lesson14 automatic is off the ray cast on %lld edge pixels, OpenCSG "
                     "automatic+bbox on %lld\n",
                     size.text().c_str(), bs.name.c_str(), lessonAutomatic->onEdges, openCsgBoxes->onEdges);
        ok = false;
      }
    }
  }

  // The machine and its load, said with the figures.
  utsname u{};
  uname(&u);
  const std::string cpu = commandOutput("grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'");
  const std::string cores = commandOutput("nproc");
  const std::string load = commandOutput("cat /proc/loadavg | cut -d' ' -f1-3");
  const std::string date = commandOutput("date -u +%Y-%m-%d");

  std::ofstream csv(out.string() + ".csv");
  csv << "size,scene,primitives,renderer,method,frame_ms,frame_cpu_ms,draws,covered_px,coverage_diff_px,"
         "off_ray_cast_px,off_ray_cast_on_edges_px\n";
  for (const Row& r : rows)
    csv << r.size << "," << r.scene << "," << r.primitives << "," << r.renderer << "," << r.method << ","
        << r.medianMs() << "," << r.medianCpuMs() << "," << r.draws << "," << r.covered << "," << r.coverageDiff
        << "," << r.offEdges << "," << r.onEdges << "\n";
  csv.close();

  // The page's table, one per size: a row per method, a column per scene.
  std::ostringstream md;
  md << "Measured " << date << " by `csg_opencsg_benchmark` (" << (quick ? "quick: " : "") << frames
     << " frames a measurement after " << warmup << " left out, the median; " << rounds
     << (rounds == 1 ? " round" : " rounds") << " alternating, the median of their medians; one round where the first"
     << " took over " << kRepeatBelowMs << " ms) on " << cpu << " ("
     << cores << " cores, shared), " << u.sysname << " " << u.release << "; load average " << load
     << " (1, 5, 15 min) at the end. " << OPENCSG_VERSION_STRING << " on " << glx.renderer
     << " (GLX pbuffer); lesson 14 on " << lessonRenderer
     << " (headless, its own process). Per size two tables: wall-clock milliseconds a frame, draw "
        "calls a frame in brackets, after a /, the pixels whose coverage differs from OpenCSG Automatic's "
        "picture; and CPU milliseconds a frame, every thread's (llvmpipe draws on the CPU: its CPU time "
        "hardly changes when other work shares the machine; its wall time does); and each picture against the CSG "
        "ray cast (the lesson's --set oracle=1, and the same for OpenCSG's picture): pixels showing another "
        "primitive or depth off the edges the geometry decides, and in brackets on them. - not run (SCS on the "
        "concave scene; on the cube rack, OpenCSG's Goldfeather settings and the lesson's methods but the automatic one, tens of seconds to minutes a frame).\n\n";
  for (const Size& size : sizes) {
    for (const Table table : {Table::Wall, Table::Cpu, Table::RayCast}) {
      std::vector<std::pair<std::string, std::string>> methodsSeen;
      for (const Row& r : rows)
        if (r.size == size.text() && std::find(methodsSeen.begin(), methodsSeen.end(),
                                               std::make_pair(r.renderer, r.method)) == methodsSeen.end())
          methodsSeen.emplace_back(r.renderer, r.method);
      md << "| " << size.text()
         << (table == Table::Wall ? ", wall ms" : table == Table::Cpu ? ", CPU ms" : ", off the ray cast");
      for (const BenchScene& bs : scenes) {
        int n = 0;
        for (const Row& r : rows)
          if (r.scene == bs.name) n = r.primitives;
        md << " | " << bs.name << " (" << n << ")";
      }
      md << " |\n|---";
      for (std::size_t i = 0; i < scenes.size(); ++i) md << "|---:";
      md << "|\n";
      for (const auto& [renderer, method] : methodsSeen) {
        md << "| " << (renderer == "opencsg" ? "OpenCSG " : "lesson ") << method;
        for (const BenchScene& bs : scenes) {
          const Row* found = nullptr;
          for (const Row& r : rows)
            if (r.size == size.text() && r.scene == bs.name && r.renderer == renderer && r.method == method) found = &r;
          if (!found) {
            md << " | -";
            continue;
          }
          char cell[96];
          if (table == Table::Cpu)
            std::snprintf(cell, sizeof cell, " | %.1f", found->medianCpuMs());
          else if (table == Table::Wall)
            std::snprintf(cell, sizeof cell, " | %.1f (%lld)", found->medianMs(), found->draws);
          else
            std::snprintf(cell, sizeof cell, " | %lld (%lld)", found->offEdges, found->onEdges);
          md << cell;
          if (table == Table::Wall && found->coverageDiff != 0) md << " / " << found->coverageDiff;
        }
        md << " |\n";
      }
      md << "\n";
    }
  }
  std::ofstream(out.string() + ".md") << md.str();
  std::cerr << "bench: wrote " << out.string() << ".csv and .md; load average " << load << "\n";

  if (page) {
    // Read again: the page may have been edited during the run (markers checked at the start).
    std::ifstream in(*page);
    std::stringstream again;
    again << in.rdbuf();
    pageText = again.str();
    const auto b = pageText.find(beginMarker), e = pageText.find(endMarker);
    if (b == std::string::npos || e == std::string::npos || e < b) {
      std::cerr << "csg_opencsg_benchmark: --page " << page->string() << ": its markers went during the run\n";
      return 1;
    }
    pageText.replace(b + beginMarker.size(), e - b - beginMarker.size(), md.str());
    const fs::path temporary = page->string() + ".new";
    std::ofstream(temporary) << pageText;
    fs::rename(temporary, *page);
    std::cerr << "bench: wrote the table into " << page->string() << "\n";
  }
  fs::remove_all(work);
  if (!check) return 0;
  std::cerr << (ok ? "bench check ok: " : "bench check FAILED: ")
            << "every lesson 14 method agrees with the CSG ray cast off its edges, and the automatic method on "
               "as many edge pixels as OpenCSG automatic+bbox\n";
  return ok ? 0 : 1;
}
