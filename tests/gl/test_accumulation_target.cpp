// A lesson's accumulation target against a real context: its half-float colour adds many small
// terms without rounding each to 1/255 (RGBA8 does), and the copy into the framework's
// framebuffer brings colour (clamped), depth and stencil across. Skipped where no context can be
// made.
#include <gtest/gtest.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "gl/accumulation_target.h"
#include "gl/context.h"
#include "gl/framebuffer.h"
#include "gl/gpu_mesh.h"
#include "gl/shader.h"
#include "gl_fixture.h"

using namespace stencil;

namespace {

class AccumulationTargetTest : public GlFixture {};

// The red level, 0..255, that `terms` passes of `value` each leave once added up in a target of
// `format` by additive blending (a rectangle over the whole target per pass) and copied into an
// RGBA8 framebuffer, as lesson 16 adds its lights.
int summedLevel(ColourFormat format, float value, int terms) {
  const glm::ivec2 size(4, 4);
  AccumulationTarget target(size, format, DepthFormat::Fixed24);
  Framebuffer shown(size.x, size.y);
  Program flat("common/flat.vert", "common/flat.frag");
  GpuTriangles rectangle;
  rectangle.upload(
      {{-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}});
  target.bind();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  flat.set("transform", glm::mat4(1.0f));
  flat.set("colour", glm::vec4(value, value, value, 0.0f));
  for (int i = 0; i < terms; ++i) rectangle.draw();
  glDisable(GL_BLEND);
  target.copyTo(shown.id());
  return shown.readColour().pixels[0];
}

}  // namespace

// Thirty-two terms of 0.4/255: in half floats they add up to 12.8/255, shown as level 13; in RGBA8
// each term is rounded to level 0 as it is added, and the sum stays 0.
TEST_F(AccumulationTargetTest, HalfFloatColourAddsTermsThatEightBitsRoundAway) {
  EXPECT_EQ(summedLevel(ColourFormat::RGBA16F, 0.4f / 255.0f, 32), 13);
  EXPECT_EQ(summedLevel(ColourFormat::RGBA8, 0.4f / 255.0f, 32), 0);
}

// A sum past 1 is held by the target and clamped to 255 by the copy into RGBA8.
TEST_F(AccumulationTargetTest, TheCopyClampsWhatPassesOne) {
  EXPECT_EQ(summedLevel(ColourFormat::RGBA16F, 0.75f, 2), 255);
}

TEST_F(AccumulationTargetTest, TheCopyBringsDepthAndStencilAcross) {
  for (DepthFormat depth : {DepthFormat::Fixed24, DepthFormat::Float32}) {
    AccumulationTarget target({5, 3}, ColourFormat::RGBA16F, depth);
    Framebuffer shown(5, 3, 8, depth);
    target.bind();
    glClearDepth(0.25);
    glClearStencil(7);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glClearDepth(1.0);
    glClearStencil(0);
    target.copyTo(shown.id());
    EXPECT_EQ(shown.readStencil().pixels, std::vector<std::uint8_t>(15, 7)) << depthFormatName(depth);
    for (float d : shown.readDepth()) EXPECT_NEAR(d, 0.25f, 1e-6f) << depthFormatName(depth);
  }
}

TEST_F(AccumulationTargetTest, FitsOnlyItsOwnSizeAndFormats) {
  const AccumulationTarget target({8, 6}, ColourFormat::RGBA16F, DepthFormat::Float32);
  EXPECT_TRUE(target.fits({8, 6}, ColourFormat::RGBA16F, DepthFormat::Float32));
  EXPECT_FALSE(target.fits({8, 7}, ColourFormat::RGBA16F, DepthFormat::Float32));
  EXPECT_FALSE(target.fits({8, 6}, ColourFormat::RGBA8, DepthFormat::Float32));
  EXPECT_FALSE(target.fits({8, 6}, ColourFormat::RGBA16F, DepthFormat::Fixed24));
}
