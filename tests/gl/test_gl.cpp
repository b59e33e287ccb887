// The GL glue against a real context (OSMesa where built in, else EGL): the framebuffer's
// verified stencil, the recorder's counts and snapshots, GL errors failing a pass, the depth
// precision a far plane at infinity costs, and the depth error per distance of a 24-bit buffer
// against a reversed float one.
// Without any context the tests are skipped, not passed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "geometry/projection.h"
#include "geometry/shapes.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/errors.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/recorder.h"
#include "gl/shader.h"
#include "gl_fixture.h"

using namespace stencil;

namespace {

class Gl : public GlFixture {};

}  // namespace

TEST_F(Gl, FramebufferHasVerifiedStencilBits) {
  EXPECT_EQ(Framebuffer(32, 16).stencilBits(), 8);
  EXPECT_EQ(Framebuffer(32, 16, 0).stencilBits(), 0);
}

TEST_F(Gl, StencilReadsBackExactlyAndClearHonoursTheWriteMask) {
  Framebuffer fb(7, 5);  // odd sizes catch row-alignment mistakes
  fb.bind();
  glClearStencil(0xA5);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0x0F);
  glClearStencil(0x00);
  glClear(GL_STENCIL_BUFFER_BIT);  // clears the low nibble only
  glStencilMask(0xFF);
  const Image s = fb.readStencil();
  ASSERT_EQ(s.pixels.size(), 35u);
  for (std::uint8_t v : s.pixels) EXPECT_EQ(v, 0xA0);
  checkGlErrors("in the test");
}

TEST_F(Gl, ReadbackIsTopRowFirst) {
  Framebuffer fb(4, 4);
  fb.bind();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 3, 4, 1);  // GL's top row (y measured from the bottom)
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  const Image c = fb.readColour();
  EXPECT_EQ(c.at(0, 0)[0], 255);  // image row 0 is the top
  EXPECT_EQ(c.at(0, 3)[0], 0);
}

TEST_F(Gl, RecorderCountsDrawsTrianglesAndFragments) {
  Framebuffer fb(64, 32);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  PassRecorder recorder({"first", "second"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({.measure = true, .captureAll = true, .captureOnly = {}});
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  flat.set("transform", glm::mat4(1));
  flat.set("colour", glm::vec4(1));
  quad.draw();
  quad.draw();
  recorder.pass("first");
  recorder.pass("second");  // an empty pass
  recorder.endFrame();

  const auto& stats = recorder.passStats();
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].name, "first");
  EXPECT_EQ(stats[0].drawCalls, 2u);
  EXPECT_EQ(stats[0].triangles, 4u);
  ASSERT_TRUE(stats[0].samplesPassed.has_value());
  EXPECT_EQ(*stats[0].samplesPassed, 2u * 64 * 32);  // two full-screen quads, no depth test
  EXPECT_EQ(stats[1].drawCalls, 0u);
  EXPECT_EQ(stats[1].samplesPassed, 0u);
  EXPECT_EQ(recorder.snapshots().size(), 2u);
  EXPECT_EQ(recorder.snapshots()[0].colour.at(10, 10)[0], 255);
}

// The passes are named as they ran: a detail the lesson gives goes beside the name, a name the
// frame repeats without one is numbered, and a snapshot carries its pass's label and index.
TEST_F(Gl, PassesAreLabelledAsTheyRan) {
  Framebuffer fb(16, 16);
  PassRecorder recorder({"ambient", "shadows", "reflection", "overlay"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({.measure = false, .captureAll = false, .captureOnly = 3});
  recorder.pass("ambient");
  recorder.pass("shadows", "light 2");
  recorder.pass("shadows", "light 0");
  recorder.pass("reflection");
  recorder.pass("reflection");
  recorder.pass("overlay");
  recorder.endFrame();
  std::vector<std::string> labels;
  for (const PassStats& p : recorder.passStats()) labels.push_back(p.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"ambient", "shadows (light 2)", "shadows (light 0)",
                                              "reflection #1", "reflection #2", "overlay"}));
  EXPECT_EQ(recorder.passStats()[1].name, "shadows");
  ASSERT_EQ(recorder.snapshots().size(), 1u);
  EXPECT_EQ(recorder.snapshots()[0].index, 3u);
  EXPECT_EQ(recorder.snapshots()[0].label, "reflection #1");
}

// A pass drawn into a framebuffer of the lesson's own is what its snapshot shows: the colour,
// stencil and depth drawn there, not the framework's untouched framebuffer.
TEST_F(Gl, APassDrawnOffScreenIsWhatItsSnapshotShows) {
  Framebuffer framework(32, 16), own(32, 16);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  PassRecorder recorder({"own", "framework"}, framework, context->features());
  framework.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  recorder.beginFrame({.measure = false, .captureAll = true, .captureOnly = {}});
  own.bind();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 7, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  flat.set("transform", glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.5f)));  // window depth 0.25
  flat.set("colour", glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  quad.draw();
  recorder.pass("own");
  framework.bind();
  recorder.pass("framework");
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  recorder.endFrame();

  ASSERT_EQ(recorder.snapshots().size(), 2u);
  const Snapshot& drawn = recorder.snapshots()[0];
  EXPECT_EQ(drawn.framebuffer, own.id());
  EXPECT_EQ(drawn.colour.at(5, 5)[0], 255);
  EXPECT_EQ(drawn.colour.at(5, 5)[1], 0);
  EXPECT_EQ(drawn.stencil.at(5, 5)[0], 7);
  EXPECT_NEAR(drawn.depth.at(5 * 32 + 5), 0.25f, 1e-6f);
  const Snapshot& untouched = recorder.snapshots()[1];  // the framework's: cleared, nothing drawn
  EXPECT_EQ(untouched.framebuffer, framework.id());
  EXPECT_EQ(untouched.colour.at(5, 5)[0], 0);
  EXPECT_EQ(untouched.stencil.at(5, 5)[0], 0);
  EXPECT_EQ(untouched.depth.at(5 * 32 + 5), 1.0f);
}

// A framebuffer whose stencil (or colour) cannot be read is not pictured: the snapshot is the
// framework's.
TEST_F(Gl, AFramebufferThatCannotBeReadWholeLeavesTheSnapshotToTheFrameworks) {
  Framebuffer framework(16, 16), noStencil(16, 16, 0);
  PassRecorder recorder({"only"}, framework, context->features());
  recorder.beginFrame({.measure = false, .captureAll = true, .captureOnly = {}});
  noStencil.bind();
  recorder.pass("only");
  recorder.endFrame();
  ASSERT_EQ(recorder.snapshots().size(), 1u);
  EXPECT_EQ(recorder.snapshots()[0].framebuffer, framework.id());
}

// Ending a pass, measured and captured, leaves the lesson's bindings as they were: the draw and
// read framebuffers, the viewport and the pack alignment.
TEST_F(Gl, APassLeavesTheBindingsAndViewportAsItFoundThem) {
  Framebuffer framework(32, 16), own(32, 16), other(32, 16);
  PassRecorder recorder({"first", "second"}, framework, context->features());
  for (bool measure : {false, true}) {
    recorder.beginFrame({.measure = measure, .captureAll = true, .captureOnly = {}});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, own.id());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, other.id());
    glViewport(3, 4, 20, 10);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    for (const char* name : {"first", "second"}) {
      recorder.pass(name);
      GLint draw = 0, read = 0, viewport[4] = {}, alignment = 0;
      glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
      glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
      glGetIntegerv(GL_VIEWPORT, viewport);
      glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
      EXPECT_EQ(static_cast<GLuint>(draw), own.id()) << name << (measure ? " measured" : "");
      EXPECT_EQ(static_cast<GLuint>(read), other.id()) << name;
      EXPECT_EQ(viewport[0], 3);
      EXPECT_EQ(viewport[1], 4);
      EXPECT_EQ(viewport[2], 20);
      EXPECT_EQ(viewport[3], 10);
      EXPECT_EQ(alignment, 2);
    }
    recorder.endFrame();
    EXPECT_EQ(recorder.snapshots().size(), 2u);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

// A new framebuffer's first measured frame: its GPU time is a real figure that fits inside the
// pass's CPU wall time (which ends after glFinish), not the timer's raw timestamp.
TEST_F(Gl, TheFirstFramesGpuTimeFitsInsideItsCpuTime) {
  GLint timerBits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &timerBits);
  Framebuffer fb(64, 32);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  PassRecorder recorder({"first"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({.measure = true, .captureAll = false, .captureOnly = {}});  // no clear before it
  flat.set("transform", glm::mat4(1));
  flat.set("colour", glm::vec4(1));
  quad.draw();
  recorder.pass("first");
  recorder.endFrame();
  const PassStats& first = recorder.passStats().at(0);
  if (timerBits == 0) {
    EXPECT_FALSE(first.gpuMs.has_value());
    EXPECT_FALSE(first.gpuMsNullReason.empty());
    return;
  }
  ASSERT_TRUE(first.gpuMs.has_value()) << first.gpuMsNullReason;
  EXPECT_GE(*first.gpuMs, 0.0);
  EXPECT_LE(*first.gpuMs, first.cpuMs);
}

TEST_F(Gl, RecorderSumsALessonsOwnCountsPerFrame) {
  Framebuffer fb(8, 8);
  PassRecorder recorder({"only"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({});
  recorder.count("scene_renderings", 1);
  recorder.count("mirrors", 3);
  recorder.count("scene_renderings", 4);
  recorder.pass("only");
  recorder.endFrame();
  using Counts = std::vector<std::pair<std::string, std::uint64_t>>;
  EXPECT_EQ(recorder.counts(), (Counts{{"scene_renderings", 5}, {"mirrors", 3}}));
  recorder.beginFrame({});  // every frame counts afresh
  recorder.pass("only");
  recorder.endFrame();
  EXPECT_TRUE(recorder.counts().empty());
}

TEST_F(Gl, AGlErrorFailsThePassItHappenedIn) {
  Framebuffer fb(8, 8);
  PassRecorder recorder({"broken"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({});
  glStencilFunc(0x1234, 0, 0xFF);  // GL_INVALID_ENUM
  try {
    recorder.pass("broken");
    FAIL() << "the GL error went unnoticed";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("in pass 'broken'"), std::string::npos) << e.what();
  }
}

TEST_F(Gl, UndeclaredPassAndDrawsAfterTheLastPassAreBugs) {
  Framebuffer fb(8, 8);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  PassRecorder recorder({"only"}, fb, context->features());
  fb.bind();
  recorder.beginFrame({});
  EXPECT_THROW(recorder.pass("typo"), std::logic_error);
  recorder.pass("only");
  quad.draw();
  EXPECT_THROW(recorder.endFrame(), std::logic_error);
}

// Everitt and Kilgard's far plane at infinity: Pinf maps eye distance d to window depth
// 1 - n/d, the finite P to f/(f - n) (1 - n/d). So Pinf gives [n, f] the fraction 1 - n/f of
// the depth range (99% for n = 1, f = 100) and the rest to everything beyond f. Measured by
// reading back the depth of a plane facing the eye at distance d through each projection.
TEST_F(Gl, FarPlaneAtInfinityCostsNOverFOfTheDepthRange) {
  const float n = 1.0f, f = 100.0f;
  const glm::mat4 p = glm::perspective(glm::radians(90.0f), 1.0f, n, f);
  const glm::mat4 pinf = glm::infinitePerspective(glm::radians(90.0f), 1.0f, n);
  Framebuffer fb(8, 8);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  fb.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  const auto depthAt = [&](const glm::mat4& projection, float d) {
    glClear(GL_DEPTH_BUFFER_BIT);
    // The screen quad spans [-1, 1]^2; at distance d with a 90 degree view that is d wide.
    flat.set("transform", projection * glm::scale(glm::translate(glm::mat4(1), {0, 0, -d}), glm::vec3(d)));
    flat.set("colour", glm::vec4(1));
    quad.draw();
    float depth = -1.0f;
    glReadPixels(4, 4, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    return static_cast<double>(depth);
  };
  const double quantum = 1.0 / ((1 << 24) - 1);  // one step of a 24-bit depth buffer
  // The vertex arithmetic is single precision: a few float epsilons on top of the rounding.
  const double tolerance = quantum + 4.0 * std::numeric_limits<float>::epsilon();
  for (float d : {2.0f, 10.0f, 50.0f, 99.0f}) {
    const double expectP = f / (f - n) * (1.0 - n / d), expectPinf = 1.0 - n / d;
    EXPECT_NEAR(depthAt(p, d), expectP, tolerance) << "P at " << d;
    EXPECT_NEAR(depthAt(pinf, d), expectPinf, tolerance) << "Pinf at " << d;
    EXPECT_NEAR(depthAt(pinf, d) / depthAt(p, d), 1.0 - n / f, 1e-5) << "the ratio at " << d;
  }
  const double farDepth = depthAt(pinf, f);  // where P puts 1: the share Pinf gives [n, f]
  EXPECT_NEAR(farDepth, 1.0 - n / f, tolerance);
  std::cout << "Pinf (n = 1) puts f = 100 at depth " << farDepth << ": [n, f] gets " << 100.0 * farDepth
            << "% of the depth range, " << std::llround(farDepth / quantum) << " of the "
            << std::llround(1.0 / quantum) << " 24-bit steps\n";
  checkGlErrors("in the test");
}

// The depth error per distance of four depth buffers with the far plane at infinity and a near
// plane of 1e-4 (tests/scenes/hard/near-plane-1e-4.scene's). A plane facing the eye at distance
// d is drawn, its stored depth read back (as a float) and turned back into a distance d' with
// the exact inverse of the mapping (in double); the error is |d' - d| / d, the largest over 40
// distances per decade. The mappings:
//   fixed24      GL_DEPTH24_STENCIL8, Pinf, GL's mapping: depth 1 - n/d, steps of 2^-24, so
//                d^2/n * 2^-24 units apart: the relative error grows as d/n * 2^-24;
//   float32      GL_DEPTH32F_STENCIL8, the same mapping: 1 - n/d lies in [0.5, 1), where a
//                float's steps are 2^-24 too; no better;
//   float32 glDepthRange(1, 0)  reversed by the depth range alone (GL 3.3, no clip control):
//                depth n/d, but computed as 0.5 - 0.5 z/w from z/w = 1 - 2n/d, a float near 1
//                whose steps are 2^-24: no better;
//   float32 reversed, clip control   glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and
//                reversedDepth(Pinf): depth = clip z / w = n/d with no remapping, a float's
//                relative step 2^-24 at every distance.
TEST_F(Gl, ReversedFloatDepthKeepsTheRelativeErrorAtEveryDistance) {
  if (!context->features().clipControl) GTEST_SKIP() << "no ARB_clip_control: the reversed float path is off";
  const double n = 1e-4;
  const glm::mat4 pinf = glm::infinitePerspective(glm::radians(90.0f), 1.0f, static_cast<float>(n));
  Program flat("common/flat.vert", "common/flat.frag");
  GpuMesh quad(makeScreenQuad());
  struct Mapping {
    std::string name;
    DepthFormat format;
    bool clipControl, depthRangeReversed;
    glm::mat4 projection;
    std::function<double(double depth)> distance;  // the exact inverse of the mapping
  };
  const auto fromPinf = [n](double depth) { return n / (1.0 - depth); };
  const auto fromReversed = [n](double depth) { return n / depth; };
  const std::vector<Mapping> mappings = {
      {"fixed24, GL's mapping (Pinf)", DepthFormat::Fixed24, false, false, pinf, fromPinf},
      {"float32, GL's mapping", DepthFormat::Float32, false, false, pinf, fromPinf},
      {"float32, glDepthRange(1, 0)", DepthFormat::Float32, false, true, pinf, fromReversed},
      {"float32, reversed, clip control", DepthFormat::Float32, true, false, reversedDepth(pinf),
       fromReversed},
  };
  const std::vector<double> decades = {1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1000.0};
  constexpr int kPerDecade = 40;
  std::vector<std::vector<double>> worst(mappings.size(), std::vector<double>(decades.size(), 0.0));
  for (std::size_t m = 0; m < mappings.size(); ++m) {
    const Mapping& mapping = mappings[m];
    Framebuffer fb(8, 8, 8, mapping.format);
    fb.bind();
    glClipControl(GL_LOWER_LEFT, mapping.clipControl ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    glDepthRange(mapping.depthRangeReversed ? 1.0 : 0.0, mapping.depthRangeReversed ? 0.0 : 1.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (std::size_t k = 0; k < decades.size(); ++k)
      for (int i = 0; i < kPerDecade; ++i) {
        const float d = static_cast<float>(decades[k] * std::pow(10.0, i / double(kPerDecade)));
        glClear(GL_DEPTH_BUFFER_BIT);
        // The screen quad spans [-1, 1]^2; at distance d with a 90 degree view that is d wide.
        flat.set("transform",
                 mapping.projection * glm::scale(glm::translate(glm::mat4(1), {0, 0, -d}), glm::vec3(d)));
        flat.set("colour", glm::vec4(1));
        quad.draw();
        float depth = -1.0f;
        glReadPixels(4, 4, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        const double back = mapping.distance(static_cast<double>(depth));
        const double error =
            std::isfinite(back) ? std::abs(back - d) / d : std::numeric_limits<double>::infinity();
        worst[m][k] = std::max(worst[m][k], error);
      }
    glDepthRange(0.0, 1.0);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  }
  checkGlErrors("in the test");

  // The table docs/15-robust-zfail.md shows: the largest relative error per decade of distance.
  std::cout << "| n = 1e-4, largest |d' - d| / d |";
  for (double d : decades) std::cout << " d in [" << d << ", " << 10 * d << ") |";
  std::cout << "\n|---|";
  for (std::size_t k = 0; k < decades.size(); ++k) std::cout << "---|";
  std::cout << "\n";
  for (std::size_t m = 0; m < mappings.size(); ++m) {
    std::cout << "| " << mappings[m].name << " |";
    for (double e : worst[m]) {
      char cell[32];
      std::snprintf(cell, sizeof cell, " %.1e |", e);
      std::cout << (std::isinf(e) ? std::string(" depth 1: infinity |") : std::string(cell));
    }
    std::cout << "\n";
  }

  const double step = std::ldexp(1.0, -24);
  for (std::size_t k = 0; k < decades.size(); ++k) {
    const double top = 10.0 * decades[k];
    // Reversed float with clip control: a few float steps of d, whatever d is.
    EXPECT_LT(worst[3][k], 8.0 * step) << "reversed float, decade " << decades[k];
    // The other three: up to half a 2^-24 step of 1 - n/d, d/n * 2^-25 of d (and a float ulp or
    // two of vertex arithmetic), so at least 1000 times worse than the reversed float by d = 1.
    for (std::size_t m = 0; m < 3; ++m) {
      if (std::isinf(worst[m][k])) continue;  // beyond d = n 2^24 everything reads as infinity
      EXPECT_LT(worst[m][k], 2.0 * top / n * step + 8.0 * step)
          << mappings[m].name << ", decade " << decades[k];
      if (decades[k] >= 1.0) {
        EXPECT_GT(worst[m][k], 1000.0 * worst[3][k]) << mappings[m].name << ", " << decades[k];
      }
    }
  }
}
