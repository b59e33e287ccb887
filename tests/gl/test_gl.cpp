// The GL glue against a real context (OSMesa where built in, else EGL): the framebuffer's
// verified stencil, the recorder's counts and snapshots, GL errors failing a pass, and the
// depth precision a far plane at infinity costs.
// Without any context the tests are skipped, not passed.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <limits>

#include "geometry/shapes.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "gl/errors.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/recorder.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

class Gl : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      context = createContext(osmesaAvailable() ? Backend::Osmesa : Backend::Egl, 64, 64, "test");
      enableDebugOutput(context->features());
    } catch (const std::exception& e) {
      reason = e.what();
    }
  }
  static void TearDownTestSuite() { context.reset(); }
  void SetUp() override {
    if (!context) GTEST_SKIP() << "no GL context: " << reason;
  }

  static inline std::unique_ptr<Context> context;
  static inline std::string reason;
};

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
