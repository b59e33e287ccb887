// The window's frame rate (gl/frame_rate.h): right within 1% one second into any steady rate,
// 3 fps and 100 fps included, and one second after the rate changes.
#include "gl/frame_rate.h"

#include <gtest/gtest.h>

namespace stencil {
namespace {

// Frames `dt` seconds apart from `start` for `seconds`; returns the last frame's end.
double run(FrameRate& rate, double start, double dt, double seconds) {
  double t = start;
  for (int i = 1; i * dt <= seconds + 1e-9; ++i) rate.frameEnded(t = start + i * dt);
  return t;
}

TEST(FrameRate, NothingBeforeTwoFrames) {
  FrameRate rate;
  EXPECT_EQ(rate.fps(), 0.0);
  rate.frameEnded(1.0);
  EXPECT_EQ(rate.fps(), 0.0);
  EXPECT_EQ(rate.msPerFrame(), 0.0);
  rate.frameEnded(1.5);
  EXPECT_DOUBLE_EQ(rate.fps(), 2.0);
  EXPECT_DOUBLE_EQ(rate.msPerFrame(), 500.0);
}

TEST(FrameRate, SteadyRatesOneSecondIn) {
  for (const double fps : {3.0, 2.7, 30.0, 100.0, 144.0, 1000.0}) {
    FrameRate rate;
    rate.frameEnded(0.0);
    run(rate, 0.0, 1.0 / fps, 1.0);
    EXPECT_NEAR(rate.fps(), fps, 0.01 * fps) << fps;
    EXPECT_NEAR(rate.msPerFrame(), 1000.0 / fps, 10.0 / fps) << fps;
  }
}

TEST(FrameRate, SlowerThanTheSpanReportsTheLastInterval) {
  FrameRate rate;
  rate.frameEnded(0.0);
  rate.frameEnded(2.5);
  rate.frameEnded(5.5);  // 3 s a frame
  EXPECT_DOUBLE_EQ(rate.msPerFrame(), 3000.0);
  EXPECT_EQ(rate.intervals(), 1u);
}

// A fast start (the first frames before the lesson's work grows) leaves no trace one second later:
// the rate that was shown in the window as 110 and 194 fps for a lesson running at 3.
TEST(FrameRate, ForgetsAFastStartWithinASecond) {
  FrameRate rate;
  double t = run(rate, 0.0, 0.005, 0.5);  // 200 fps for half a second
  t = run(rate, t, 0.375, 1.2);           // then 375 ms a frame
  EXPECT_NEAR(rate.fps(), 1.0 / 0.375, 0.01 / 0.375);
  EXPECT_NEAR(rate.msPerFrame(), 375.0, 3.75);
  EXPECT_EQ(rate.frames(), 100 + 3);
}

}  // namespace
}  // namespace stencil
