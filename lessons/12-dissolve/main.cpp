// Lesson 12: the digital dissolve (Kilgard, "Improving Shadows and Reflections via the Stencil
// Buffer", section 7, and the GLUT 3.7 demo it cites, progs/advanced/dissolve.c).
//
// A threshold pattern in the stencil decides, per pixel, which of two scenes is shown. Write the
// pattern once: one value 0..255 per pixel, with the colour writes off and a stencil test that
// always fails, REPLACE on fail (8 draws, one bit plane each through the write mask). Then, for
// dissolve state k (0..256):
//     scene A where k - 1 <  stencil   glStencilFunc(GL_LESS,   k - 1, 0xFF)
//     scene B where k - 1 >= stencil   glStencilFunc(GL_GEQUAL, k - 1, 0xFF)
// so B covers the pixels whose value is below k, and k rising from 0 to 256 dissolves A into B.
// Each pixel passes exactly one of the two tests: one scene, never both, is shaded there.
//
// The ends. Eight bits hold 256 values, but a dissolve has 257 states: k pixels-below-k from 0
// (all A) to 256 (all B). States 1..256 take the reference k - 1 = 0..255. State 0 would need a
// reference of -1, which GL clamps to 0 (the reference is clamped to 0..2^bits - 1), so B would
// show where the stencil is 0: 1/256 of the pixels at t = 0. The exact ends draw state 0 with A's
// test ALWAYS and B's NEVER instead (the `exact-ends` option; off shows the clamped reference).
//
// The pattern is equalized (geometry/dither.h): every value 0..255 on the same number of pixels
// (within one), so state k shows B on k/256 of the pixels within 1/n, n the pixel count, whatever
// the pattern: white noise, an ordered (Bayer) dither, blue noise from the lesson's own
// void-and-cluster, or a linear, radial or clock wipe. The GLUT demo's painted mask is the seventh:
// the stencil set to 255 and a brush that sprays 0 into it, so B shows through A where it went
// (in the window the right mouse button sprays).
//
// The pattern lives in the lesson's framebuffer, which keeps its stencil from frame to frame; a
// window's own stencil could not be trusted to hold it (EGL 1.5, section 3.10.1: the contents of
// ancillary buffers are always undefined after eglSwapBuffers).
//
// For comparison (the `method` option), what engines do instead: draw both scenes whole into
// textures and pick per pixel in a full-screen pass, or shade every fragment of both and discard
// by the pattern in the fragment shader (a dithered cross-fade). Both shade every fragment of both
// scenes; the stencil shades each pixel's own scene only. Rasterizers shade in blocks of pixels,
// though, and a block with one pixel to draw is shaded whole: a pattern finer than the block
// (noise, Bayer) spends most of the saving, which the `cell` option (the pattern held over blocks)
// and the `work` option (costly shading) let one measure; docs/12-dissolve.md has the figures.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <string>
#include <vector>

#include "geometry/dither.h"
#include "geometry/shapes.h"
#include "gl/errors.h"
#include "gl/gpu_mesh.h"
#include "gl/image.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr int kStates = 257;            // k = 0..256: 0 all A, 256 all B
constexpr double kDissolveSeconds = 4;  // with step -1, k climbs 0..256 every 4 s
constexpr int kMethodStencil = 0, kMethodMix = 1, kMethodDiscard = 2;
constexpr int kPainted = 6;  // the pattern option: 0..5 PatternKind, 6 painted
constexpr int kWindow = 8;   // the side of the windows the clumpiness is measured over

// The dissolve state for a frame: the step option, or time climbing 0..256 every kDissolveSeconds.
int dissolveState(const Frame& f) {
  if (f.option("step") >= 0) return f.option("step");
  const double phase = f.time / kDissolveSeconds - std::floor(f.time / kDissolveSeconds);
  return std::min(kStates - 1, static_cast<int>(phase * kStates));
}

class Dissolve final : public Lesson {
 public:
  Dissolve()
      : lit_("common/lit.vert", "12-dissolve/lit_work.frag"),
        litDiscard_("common/lit.vert", "12-dissolve/lit_discard.frag"),
        patternBit_("common/flat.vert", "12-dissolve/pattern_bit.frag"),
        mix_("common/flat.vert", "12-dissolve/mix.frag"),
        spray_("12-dissolve/spray.vert", "common/flat.frag"),
        screen_(makeScreenQuad()),
        groundA_(makePlane(3.0f, 1)),
        torus_(makeTorus(0.75f, 0.28f, 48, 24)),
        cube_(makeCube(0.4f)),
        groundB_(makeSquareRing(3.0f, 0.9f)),
        sphere_(makeSphere(0.6f, 48, 24)),
        cone_(makeCone(0.45f, 1.3f, 40)),
        cylinder_(makeCylinder(0.3f, 1.0f, 32)),
        dots_(GL_POINTS) {
    glGenTextures(1, &patternTexture_);
    glGenQueries(1, &query_);
  }
  ~Dissolve() override {
    glDeleteTextures(1, &patternTexture_);
    glDeleteQueries(1, &query_);
  }

  void render(Frame& f) override {
    // The clumpiness is measured over 8x8 windows: a smaller frame is refused before anything is drawn.
    if (f.on("measure") && (f.size.x < kWindow || f.size.y < kWindow))
      throw UsageError("--set measure=1 needs a frame of at least " + std::to_string(kWindow) + "x" +
                       std::to_string(kWindow) + " pixels (its clumpiness window), got " +
                       std::to_string(f.size.x) + "x" + std::to_string(f.size.y));
    const int k = dissolveState(f);
    f.count("state", static_cast<std::uint64_t>(k));
    framebuffer_ = f.framebuffer();
    // The colour and depth of the last frame go (the stencil stays: it holds the pattern), so that
    // the passes before the dissolve show what they wrote, not the frame before.
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // 1. The pattern, once: written only when the pattern or the size changes. The stencil keeps
    // it from frame to frame (and keeps what the brush sprayed into it).
    const int pattern = f.option("pattern"), cell = f.option("cell");
    if (pattern != writtenPattern_ || cell != writtenCell_ || f.size != writtenSize_) {
      writePattern(f, pattern, cell);
      writtenPattern_ = pattern, writtenCell_ = cell, writtenSize_ = f.size;
      f.count("pattern_written");
    }
    f.pass("pattern");

    // 2. The brush (the painted mask's stroke, and the window's pointer): 0 into the stencil.
    if (pattern == kPainted || (f.pointer && f.on("brush"))) paint(f, pattern == kPainted);
    f.pass("paint");

    if (f.on("measure")) measure(f);  // before the frame, which it would overwrite
    f.pass("measure");

    // 3. The dissolve itself.
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // the stencil holds the pattern: not cleared
    drawDissolve(f, k, f.option("method"), f.on("which"), /*markPasses=*/true);
  }

 private:
  // ---- the pattern into the stencil -------------------------------------------------------------

  void writePattern(Frame& f, int pattern, int cell) {
    glDisable(GL_DEPTH_TEST);
    if (pattern == kPainted) {
      // The painted mask starts as all A: every pixel 255, above every state but the last.
      glStencilMask(0xFF);
      glClearStencil(255);
      glClear(GL_STENCIL_BUFFER_BIT);
      glClearStencil(0);
      values_.assign(static_cast<std::size_t>(f.size.x) * static_cast<std::size_t>(f.size.y), 255);
      uploadPattern(f.size);  // for the methods that read it in a shader (mix, discard)
    } else {
      const auto start = std::chrono::steady_clock::now();
      values_ = makePattern(static_cast<PatternKind>(pattern), f.size.x, f.size.y);
      if (cell > 1) values_ = inCells(static_cast<PatternKind>(pattern), f.size, cell);
      patternMicroseconds_ = static_cast<std::uint64_t>(
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
      // Clear to 0, then set each bit plane where the pattern has that bit.
      glStencilMask(0xFF);
      glClearStencil(0);
      glClear(GL_STENCIL_BUFFER_BIT);
      glEnable(GL_STENCIL_TEST);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the pattern is invisible
      glStencilFunc(GL_NEVER, 0xFF, 0xFF);                  // the test always fails...
      glStencilOp(GL_REPLACE, GL_KEEP, GL_KEEP);            // ...and fail writes the reference
      uploadPattern(f.size);  // read here, and by the methods that read it in a shader (mix, discard)
      patternBit_.set("pattern", 0);
      patternBit_.set("transform", glm::mat4(1.0f));
      for (int bit = 0; bit < 8; ++bit) {
        glStencilMask(1u << bit);  // REPLACE writes 0xFF through the mask: this bit only
        patternBit_.set("bit", bit);
        screen_.draw();  // pixels without the bit discard their fragment before the test
      }
      glStencilMask(0xFF);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glDisable(GL_STENCIL_TEST);
    }
  }

  // The pattern made for a frame `cell` times smaller, each value held over a cell x cell block.
  static std::vector<std::uint8_t> inCells(PatternKind kind, glm::ivec2 size, int cell) {
    const int w = (size.x + cell - 1) / cell, h = (size.y + cell - 1) / cell;
    const std::vector<std::uint8_t> small = makePattern(kind, w, h);
    std::vector<std::uint8_t> values(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x)
        values[static_cast<std::size_t>(y * size.x + x)] =
            small[static_cast<std::size_t>((y / cell) * w + x / cell)];
    return values;
  }

  // The pattern values as an R8 texture, texel (x, y) for window pixel (x, y).
  void uploadPattern(glm::ivec2 size) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, patternTexture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, size.x, size.y, 0, GL_RED, GL_UNSIGNED_BYTE, values_.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }

  // The brush: dabs of dots along a stroke (the time so far along a fixed curve, a dab every
  // 1/60 s) and, in the window, under the pointer while the right button is held. Each dot sets
  // its pixel to 0, so B shows there from state 1 on.
  void paint(Frame& f, bool stroke) {
    std::vector<glm::vec4> dots;
    const auto dab = [&](glm::vec2 centre, std::uint32_t id) {  // centre in pixels
      const float radius = 0.06f * static_cast<float>(f.size.y);
      for (std::uint32_t i = 0; i < 48; ++i) {
        const std::uint64_t h = pixelHash(id, i, 7);
        const float a = static_cast<float>(h & 0xFFFF) / 65536.0f * 6.2831853f;
        const float r = radius * std::sqrt(static_cast<float>((h >> 16) & 0xFFFF) / 65536.0f);
        // At a pixel's centre, the dot's square edges lie half a pixel from every pixel centre:
        // the same 3x3 pixels on every rasterizer (a centre on a pixel's corner is a tie).
        const glm::vec2 p = glm::floor(centre + r * glm::vec2(std::cos(a), std::sin(a))) + 0.5f;
        dots.push_back({2.0f * p.x / static_cast<float>(f.size.x) - 1.0f,
                        2.0f * p.y / static_cast<float>(f.size.y) - 1.0f, 0.0f, 1.0f});
      }
    };
    const int length = f.option("stroke") >= 0 ? f.option("stroke") : static_cast<int>(f.time * 60.0);
    const int dabs = stroke ? std::clamp(length, 0, 60 * 30) : 0;
    for (int d = 0; d < dabs; ++d) {
      const float s = static_cast<float>(d) / 60.0f;  // a figure of eight across the frame
      const glm::vec2 c(0.5f + 0.35f * std::sin(1.3f * s), 0.5f + 0.3f * std::sin(2.6f * s));
      dab(c * glm::vec2(f.size), static_cast<std::uint32_t>(d));
    }
    if (f.pointer && f.on("brush"))
      dab(*f.pointer, 100000u + paintedDabs_++);  // the window's brush adds to the stencil
    if (dots.empty()) return;
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the brush paints the stencil only
    glStencilFunc(GL_NEVER, 0, 0xFF);                     // the test always fails...
    glStencilOp(GL_REPLACE, GL_KEEP, GL_KEEP);            // ...and fail writes 0: B from state 1
    constexpr float kDotPixels = 3.0f;
    glPointSize(kDotPixels);
    spray_.set("pointSize", kDotPixels);
    spray_.set("transform", glm::mat4(1.0f));
    dots_.upload(dots);
    dots_.draw();
    glPointSize(1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    // What the CPU knows of the pattern follows (the methods that read it as a texture).
    const Image stencil = readStencil(f.size);
    values_.assign(stencil.pixels.begin(), stencil.pixels.end());
    uploadPattern(f.size);
  }

  Image readStencil(glm::ivec2 size) const {
    Image s(size.x, size.y, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.pixels.data());
    return s;  // bottom row first, as the pattern
  }

  // ---- the dissolve -----------------------------------------------------------------------------

  // Scene A's and B's stencil tests for state k, the paper's LESS and GEQUAL with reference k - 1.
  void stencilForA(int k, bool exactEnds) {
    if (k == 0 && exactEnds)
      glStencilFunc(GL_ALWAYS, 0, 0xFF);  // state 0: every pixel (k - 1 = -1 has no 8-bit reference)
    else
      glStencilFunc(GL_LESS, k - 1, 0xFF);  // k - 1 < stencil: the pattern is at or above k
  }
  void stencilForB(int k, bool exactEnds) {
    if (k == 0 && exactEnds)
      glStencilFunc(GL_NEVER, 0, 0xFF);  // state 0: no pixel
    else
      glStencilFunc(GL_GEQUAL, k - 1, 0xFF);  // k - 1 >= stencil: below k (at k = 256, every pixel)
  }

  void drawDissolve(Frame& f, int k, int method, bool which, bool markPasses) {
    const bool exact = f.on("exact-ends");
    const auto pass = [&](const char* name) {
      if (markPasses) f.pass(name);
    };
    if (method == kMethodStencil) {
      glEnable(GL_STENCIL_TEST);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);  // the pattern is only read from here on
      stencilForA(k, exact);                   // A where the pattern is at or above k
      drawScene(f, false, &lit_, which);
      pass("scene-a");
      stencilForB(k, exact);  // B where it is below k: the pixels A left
      drawScene(f, true, &lit_, which);
      pass("scene-b");
      glDisable(GL_STENCIL_TEST);
      pass("mix");
      return;
    }
    if (method == kMethodMix) {
      // Both scenes whole, each into its own texture, no stencil test; then one pass picks.
      targetA_.ensure(f.size), targetB_.ensure(f.size);
      for (const auto& [target, isB] : {std::pair{&targetA_, false}, std::pair{&targetB_, true}}) {
        glBindFramebuffer(GL_FRAMEBUFFER, target->fbo());
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawScene(f, isB, &lit_, which);
        pass(isB ? "scene-b" : "scene-a");
      }
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
      glDisable(GL_DEPTH_TEST);
      bindTextures({targetA_.colour(), targetB_.colour(), patternTexture_});
      mix_.set("transform", glm::mat4(1.0f));
      mix_.set("sceneA", 0), mix_.set("sceneB", 1), mix_.set("pattern", 2);
      mix_.set("state", exact ? k : std::max(k, 1));  // the clamped reference's error, reproduced
      screen_.draw();
      bindTextures({0, 0, 0});
      pass("mix");
      return;
    }
    // Discard: each scene whole, every fragment shaded, kept or discarded by the pattern.
    bindTextures({0, 0, patternTexture_});
    litDiscard_.set("pattern", 2);
    litDiscard_.set("state", exact ? k : std::max(k, 1));
    litDiscard_.set("sceneB", 0);
    drawScene(f, false, &litDiscard_, which);
    pass("scene-a");
    litDiscard_.set("sceneB", 1);
    drawScene(f, true, &litDiscard_, which);
    pass("scene-b");
    bindTextures({0, 0, 0});
    pass("mix");
  }

  void bindTextures(std::array<GLuint, 3> textures) {
    for (int i = 2; i >= 0; --i) {
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + i));
      glBindTexture(GL_TEXTURE_2D, textures[static_cast<std::size_t>(i)]);
    }
  }

  // ---- the two scenes (no stencil state in here) -----------------------------------------------

  // Scene A: a day, a torus and a cube on grass under a pale sky. Scene B: a night, a moon-like
  // sphere, a cone and a column on a ring under a dark sky. Each draws its own sky as a
  // full-screen quad first (glClear would ignore the stencil test): every pixel gets exactly one.
  void drawScene(const Frame& f, bool sceneB, const Program* program, bool which) {
    const glm::vec3 flatColour = sceneB ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const auto draw = [&](const GpuMesh& mesh, const glm::mat4& model, const glm::mat4& viewProjection,
                          glm::vec3 colour, float ambient) {
      program->set("model", model);
      program->set("viewProjection", viewProjection);
      program->set("colour", which ? flatColour : colour);
      program->set("toLight",
                   glm::normalize(sceneB ? glm::vec3(-0.5f, 0.6f, 0.3f) : glm::vec3(0.4f, 0.8f, 0.5f)));
      program->set("ambient", which ? 1.0f : ambient);
      program->set("work", f.option("work"));
      mesh.draw();
    };
    glDisable(GL_DEPTH_TEST);  // the sky lies behind everything
    draw(screen_, glm::mat4(1.0f), glm::mat4(1.0f),
         sceneB ? glm::vec3(0.05f, 0.06f, 0.16f) : glm::vec3(0.62f, 0.8f, 0.95f), 1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const glm::mat4 vp = f.projection * f.view;
    const float t = static_cast<float>(f.time);
    if (!sceneB) {
      draw(groundA_, glm::mat4(1.0f), vp, {0.45f, 0.7f, 0.35f}, 0.35f);
      glm::mat4 torus = glm::translate(glm::mat4(1.0f), {-0.5f, 0.85f, 0.0f});
      torus = glm::rotate(torus, 0.5f * t, {0, 1, 0});
      torus = glm::rotate(torus, 1.2f, {1, 0, 0});
      draw(torus_, torus, vp, {0.95f, 0.5f, 0.15f}, 0.35f);
      draw(cube_, glm::translate(glm::mat4(1.0f), {1.1f, 0.4f, 0.7f}), vp, {0.25f, 0.45f, 0.9f}, 0.35f);
    } else {
      draw(groundB_, glm::mat4(1.0f), vp, {0.35f, 0.3f, 0.45f}, 0.25f);
      draw(sphere_, glm::translate(glm::mat4(1.0f), {0.3f, 1.3f, -0.6f}), vp, {0.95f, 0.9f, 0.6f}, 0.25f);
      draw(cone_, glm::translate(glm::mat4(1.0f), {-1.2f, 0.0f, 0.6f}), vp, {0.85f, 0.2f, 0.3f}, 0.25f);
      draw(cylinder_, glm::translate(glm::mat4(1.0f), {1.3f, 0.0f, 0.5f}), vp, {0.3f, 0.8f, 0.75f}, 0.25f);
    }
  }

  // ---- measurements (--set measure=1) -----------------------------------------------------------

  // Counts of the frame's own state k, then the state swept 0..256 with each scene flat (A red,
  // B blue) through the method's own passes, read back: how many pixels show B at each state
  // against k n / 256, and how many pixels go back from B to A as k rises.
  void measure(Frame& f) {
    const int k = dissolveState(f), method = f.option("method");
    const std::uint64_t n = static_cast<std::uint64_t>(f.size.x) * static_cast<std::uint64_t>(f.size.y);
    f.count("pixels", n);
    // The pattern's own measures, on the CPU: its clumpiness (the variance of the share below k
    // over every 8x8 window, in billionths) at a few states and averaged over 1..255, and the time
    // it took to make (blue noise: the void-and-cluster tile included; a time, not a count).
    f.count("pattern_us", patternMicroseconds_);
    double varianceSum = 0;
    for (int s = 1; s < 256; ++s) {
      const double v = coverageVariance(values_, f.size.x, f.size.y, s, kWindow);
      varianceSum += v;
      if (s % 32 == 0)
        f.count("coverage_variance_e9.k" + std::to_string(s),
                static_cast<std::uint64_t>(std::lround(v * 1e9)));
    }
    f.count("coverage_variance_e9.mean", static_cast<std::uint64_t>(std::lround(varianceSum / 255 * 1e9)));
    // Fragments shaded per scene (pipeline statistics) and the pixels each scene's sky covers
    // (occlusion queries: the sky is one quad over the whole frame, drawn without the depth test).
    const bool statistics = hasFeature(f.features, Feature::PipelineStatistics);
    const auto frameCounts = [&](const char* prefix) {
      GLuint queries[2];
      glGenQueries(2, queries);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      if (statistics) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, queries[0]);
      f.ownOcclusionQueries([&] {
        glBeginQuery(GL_SAMPLES_PASSED, queries[1]);
        drawDissolve(f, k, method, f.on("which"), false);
        glEndQuery(GL_SAMPLES_PASSED);
      });
      if (statistics) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
      GLuint64 shaded = 0, passed = 0;
      if (statistics) glGetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &shaded);
      glGetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &passed);
      glDeleteQueries(2, queries);
      if (statistics) f.count(std::string(prefix) + "fragments_shaded", shaded);
      f.count(std::string(prefix) + "samples_passed", passed);
    };
    frameCounts("");
    // The same frame's two scenes drawn whole, no test: what drawing both costs before any mixing.
    {
      GLuint q = 0;
      glGenQueries(1, &q);
      for (const bool isB : {false, true}) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (statistics) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, q);
        drawScene(f, isB, &lit_, f.on("which"));
        if (statistics) {
          glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
          GLuint64 shaded = 0;
          glGetQueryObjectui64v(q, GL_QUERY_RESULT, &shaded);
          f.count(isB ? "whole_b_fragments_shaded" : "whole_a_fragments_shaded", shaded);
        }
      }
      glDeleteQueries(1, &q);
    }
    // Pixels per scene at state k by the stencil tests alone: a full-screen quad under each.
    if (method == kMethodStencil) {
      f.ownOcclusionQueries([&] {
        glEnable(GL_STENCIL_TEST);
        glDisable(GL_DEPTH_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        for (const bool isB : {false, true}) {
          if (isB)
            stencilForB(k, f.on("exact-ends"));
          else
            stencilForA(k, f.on("exact-ends"));
          glBeginQuery(GL_SAMPLES_PASSED, query_);
          lit_.set("model", glm::mat4(1.0f));
          lit_.set("viewProjection", glm::mat4(1.0f));
          screen_.draw();
          glEndQuery(GL_SAMPLES_PASSED);
          GLuint64 pixels = 0;
          glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &pixels);
          f.count(isB ? "b_pixels" : "a_pixels", pixels);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_STENCIL_TEST);
      });
    }

    // The sweep: every state, each scene flat, through the method's own passes.
    std::vector<std::uint8_t> wasB(n, 0);
    std::uint64_t maxError256 = 0, switchBacks = 0, neither = 0, bAtStart = 0, aAtEnd = 0;
    std::vector<std::uint8_t> rgba(4 * n);
    for (int s = 0; s < kStates; ++s) {
      glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      drawDissolve(f, s, method, /*which=*/true, false);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
      std::uint64_t showsB = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const bool red = rgba[4 * i] > 127, blue = rgba[4 * i + 2] > 127;
        neither += red == blue;
        showsB += blue;
        switchBacks += wasB[i] && !blue;
        wasB[i] = blue;
      }
      const std::uint64_t expected = static_cast<std::uint64_t>(s) * n, got = 256 * showsB;
      maxError256 = std::max(maxError256, got > expected ? got - expected : expected - got);
      if (s == 0) bAtStart = showsB;
      if (s == kStates - 1) aAtEnd = n - showsB;
    }
    f.count("sweep_states", kStates);
    f.count("sweep_max_error_256ths_of_a_pixel", maxError256);  // max |256 B(k) - k n|
    f.count("sweep_switch_backs", switchBacks);
    f.count("sweep_neither_or_both", neither);
    f.count("sweep_b_at_start", bAtStart);
    f.count("sweep_a_at_end", aAtEnd);
  }

  // ---- a framebuffer per scene (method mix) ------------------------------------------------------

  // A colour texture and a depth buffer the size of the frame: one scene drawn whole (method mix).
  class SceneTarget {
   public:
    ~SceneTarget() { release(); }
    void ensure(glm::ivec2 size) {
      if (size == size_ && fbo_) return;
      release();
      size_ = size;
      glGenTextures(1, &colour_);
      glBindTexture(GL_TEXTURE_2D, colour_);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glGenRenderbuffers(1, &depth_);
      glBindRenderbuffer(GL_RENDERBUFFER, depth_);
      glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
      glGenFramebuffers(1, &fbo_);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    }
    GLuint fbo() const { return fbo_; }
    GLuint colour() const { return colour_; }

   private:
    void release() {
      if (fbo_) glDeleteFramebuffers(1, &fbo_);
      if (colour_) glDeleteTextures(1, &colour_);
      if (depth_) glDeleteRenderbuffers(1, &depth_);
      fbo_ = colour_ = depth_ = 0;
    }
    GLuint fbo_ = 0, colour_ = 0, depth_ = 0;
    glm::ivec2 size_{0};
  };

  Program lit_, litDiscard_, patternBit_, mix_, spray_;
  GpuMesh screen_, groundA_, torus_, cube_, groundB_, sphere_, cone_, cylinder_;
  GpuVertexStream dots_;
  SceneTarget targetA_, targetB_;
  GLuint patternTexture_ = 0, query_ = 0, framebuffer_ = 0;
  std::vector<std::uint8_t> values_;  // the pattern, bottom row first
  int writtenPattern_ = -1, writtenCell_ = 0;
  glm::ivec2 writtenSize_{0};
  std::uint32_t paintedDabs_ = 0;
  std::uint64_t patternMicroseconds_ = 0;
};

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "12-dissolve";
  info.title = "The digital dissolve";
  info.summary =
      "A threshold pattern written once into the stencil picks, per pixel, scene A (stencil LESS) or\n"
      "scene B (GEQUAL); the reference rising dissolves A into B in 257 exact states.";
  info.options = {
      {"method", 'M',
       "0 the stencil (the paper), 1 draw both into textures and mix, 2 shade both and discard by the "
       "pattern",
       kMethodStencil, 2},
      {"pattern", 'N',
       "0 white noise, 1 Bayer 16x16, 2 blue noise (void-and-cluster 64x64), 3 linear wipe,\n"
       "      4 radial wipe, 5 clock wipe, 6 painted (right mouse button in the window)",
       static_cast<int>(PatternKind::BlueNoise), kPainted},
      {"step", 'K', "the dissolve state k: the share k/256 of pixels show B; -1 follows time (0..256 in 4 s)",
       -1, 256, -1},
      {"exact-ends", 'E', "state 0 by ALWAYS/NEVER (off: the reference -1, clamped to 0, shows B at t = 0)",
       1},
      {"which", 'W', "which scene each pixel shows, flat: A red, B blue", 0},
      {"brush", 'B',
       "in the window, the right mouse button sprays B through A (0 into the stencil), on any pattern", 1},
      {"work", 'H',
       "extra arithmetic per fragment of the scenes (iterations), a stand-in for costly shading: what\n"
       "      shading fewer fragments saves shows in the time",
       0, 4096},
      {"cell", 'C',
       "the pattern's cell, in pixels: 1 per pixel; 2, 4, 8 hold one value over each 2x2, 4x4, 8x8 block\n"
       "      (the share of B is then exact only where the cells fit the frame)",
       1, 8, 1},
      {"stroke", 'D',
       "the painted mask's brush stroke, in dabs of 1/60 s along a fixed figure of eight; -1 follows\n"
       "      time (a dab each 1/60 s)",
       -1, 1800, -1},
      {"measure", 'Q',
       "count per frame: pixels of each scene by occlusion queries, fragments shaded (pipeline\n"
       "      statistics where present), and the state swept 0..256 (the share of B, switch-backs)",
       0},
  };
  info.variants = {
      {"dissolve",
       "blue noise, k following time (0..256 every 4 s): all A at t = 0, a quarter of the way at --time 1",
       {}},
      {"white-noise",
       "half way (k = 128) through white noise: clumps and holes",
       {{"pattern", 0}, {"step", 128}}},
      {"bayer",
       "half way through an ordered 16x16 Bayer dither: even, and a visible grid",
       {{"pattern", 1}, {"step", 128}}},
      {"blue-noise",
       "half way through void-and-cluster blue noise: even, without a grid",
       {{"pattern", 2}, {"step", 128}}},
      {"blue-noise-cells",
       "half way through blue noise held over 4x4 cells: coarser, and whole blocks of pixels to one scene",
       {{"pattern", 2}, {"step", 128}, {"cell", 4}}},
      {"linear-wipe", "half way through a left-to-right wipe", {{"pattern", 3}, {"step", 128}}},
      {"radial-wipe", "half way through a wipe from the centre out", {{"pattern", 4}, {"step", 128}}},
      {"clock-wipe",
       "half way through a clockwise wipe from twelve o'clock",
       {{"pattern", 5}, {"step", 128}}},
      {"painted",
       "the GLUT demo's mask: B sprayed through A along a brush stroke of 60 dabs (1 s), at any time",
       {{"pattern", kPainted}, {"step", 128}, {"stroke", 60}}},
      {"start", "state 0 with the exact ends: only scene A", {{"step", 0}}},
      {"end", "state 256: only scene B", {{"step", 256}}},
      {"start-clamped",
       "state 0 by the reference -1, clamped to 0: B shows on 1/256 of the pixels",
       {{"step", 0}, {"exact-ends", 0}, {"which", 1}}},
      {"which-scene", "blue noise half way, each scene flat: A red, B blue", {{"step", 128}, {"which", 1}}},
      {"mix",
       "draw both whole into textures, mix by the pattern: the same picture, both scenes shaded",
       {{"method", kMethodMix}, {"step", 128}}},
      {"discard",
       "shade both, discard by the pattern: the same picture, both scenes shaded",
       {{"method", kMethodDiscard}, {"step", 128}}},
  };
  info.passes = {"pattern", "paint", "measure", "scene-a", "scene-b", "mix"};
  info.brush = true;  // right-drag sprays B through A (the brush option)
  info.camera.target = {0.0f, 0.6f, 0.0f};
  info.camera.distance = 6.5f;
  info.camera.azimuthDeg = 25.0f;
  info.camera.elevationDeg = 20.0f;
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  return runLesson(
      lessonInfo(), [] { return std::make_unique<Dissolve>(); }, argc, argv);
}
