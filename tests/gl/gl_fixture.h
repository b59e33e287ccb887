// The fixture of the GL glue's tests: one context for a whole suite (OSMesa where built in, else
// EGL), 64x64, with debug output on where the driver has it. Without any context a suite's tests
// are skipped, not passed, and say why. A suite derives from it: class MySuite : public GlFixture {}.
#pragma once
#include <gtest/gtest.h>

#include <exception>
#include <memory>
#include <string>

#include "gl/context.h"
#include "gl/debug.h"

namespace stencil {

class GlFixture : public ::testing::Test {
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

}  // namespace stencil
