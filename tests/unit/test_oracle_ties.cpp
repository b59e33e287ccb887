// The oracle's ties (geometry/shadow_oracle.h): pixels where a side of a shadow volume and the
// surface the pixel sees lie closer in depth than a rasterizer's vertex snapping (1/16 pixel) can
// move them, whose count a conforming rasterizer may take either way.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/shadow_oracle.h"
#include "geometry/shapes.h"

namespace {

using namespace stencil;

// A ground (y = 0) seen from straight above, 40x40 pixels over [-1, 1] in x and z (x to the right,
// -z up the picture), and a small open square standing on it in the plane x = 0, facing +x: its
// bottom border runs along the ground from z = -0.25 to 0.25.
struct WallOnGround {
  Mesh ground = makePlane(1.0f);
  Mesh square = makePlane(0.25f);
  glm::mat4 standing = glm::rotate(glm::translate(glm::mat4(1), {0, 0.25f, 0}), glm::radians(-90.0f), {0, 0, 1});
  glm::mat4 topDown = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 20.0f) *
                      glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  glm::ivec2 size{40, 40};
  std::vector<bool> ties(const glm::vec4& light) const {
    std::vector<int> surfaces;
    std::vector<bool> found;
    classifyPixels({{&ground, glm::mat4(1), false, true}, {&square, standing, true, false}}, light, topDown, size,
                   std::numeric_limits<float>::infinity(), &surfaces, &found);
    return found;
  }
  // Pixel (px, py)'s centre on the ground (top row first).
  glm::vec2 centre(int px, int py) const {
    return {-1.0f + (static_cast<float>(px) + 0.5f) / 20.0f, -1.0f + (static_cast<float>(py) + 0.5f) / 20.0f};
  }
};

// A light along the ground from +x: the square's bottom border extrudes, away from the light, into
// the ground's own plane. Over the half-strip x < 0, |z| < 0.25 that side lies in the surface: no
// snapping can tell them apart, every pixel there is a tie; a pixel away from the strip is not.
TEST(OracleTies, ASideInTheSurfacesPlaneTiesOverItsWholeStrip) {
  const WallOnGround scene;
  const std::vector<bool> ties = scene.ties(glm::vec4(1, 0, 0, 0));
  int inside = 0;
  for (int py = 0; py < scene.size.y; ++py)
    for (int px = 0; px < scene.size.x; ++px) {
      const glm::vec2 c = scene.centre(px, py);  // (x, z)
      const bool tie = ties[static_cast<std::size_t>(py * scene.size.x + px)];
      // A pixel's width (0.05) from the strip's borders either way, where the sides of the square's
      // upright borders cross the ground steeply.
      if (c.x < -0.05f && std::abs(c.y) < 0.2f) {
        EXPECT_TRUE(tie) << "in the strip, at " << c.x << ", " << c.y;
        ++inside;
      } else if (c.x > 0.05f || std::abs(c.y) > 0.3f) {
        EXPECT_FALSE(tie) << "off the strip, at " << c.x << ", " << c.y;
      }
    }
  EXPECT_EQ(inside, 19 * 8) << "19 columns left of x = -0.05, 8 rows within |z| < 0.2";
}

// A light from above at 45 degrees: the sides cross the ground steeply, and seen from straight
// above a side and the ground are apart by more than 1/16 pixel's snapping a pixel's width from
// where they cross: ties lie only within a pixel of the shadow's outline (x = -0.5 and x = 0 for
// |z| <= 0.25, |z| = 0.25 between them).
TEST(OracleTies, SidesCrossingTheSurfaceSteeplyTieOnlyAtTheOutline) {
  const WallOnGround scene;
  const std::vector<bool> ties = scene.ties(glm::vec4(1, 1, 0, 0));
  for (int py = 0; py < scene.size.y; ++py)
    for (int px = 0; px < scene.size.x; ++px) {
      const glm::vec2 c = scene.centre(px, py);
      const float fromOutline =
          std::abs(c.y) <= 0.25f ? std::min(std::abs(c.x + 0.5f), std::abs(c.x))
          : c.x >= -0.5f && c.x <= 0.0f ? std::abs(std::abs(c.y) - 0.25f)
                                        : 1.0f;
      if (fromOutline > 0.05f) {
        EXPECT_FALSE(ties[static_cast<std::size_t>(py * scene.size.x + px)]) << "at " << c.x << ", " << c.y;
      }
    }
}

// compareWithOracle counts a disagreement on a tie as on an edge, and one elsewhere as wrong.
TEST(OracleTies, ADisagreementOnATieIsForgivenAndNowhereElse) {
  const glm::ivec2 size{5, 5};
  const std::vector<PixelClass> oracle(25, PixelClass::Lit);
  std::vector<bool> lit(25, true);
  lit[12] = false;  // the centre pixel says shadowed
  std::vector<bool> ties(25, false);
  EXPECT_FALSE(compareWithOracle(oracle, lit, size, nullptr, &ties).passed());
  ties[7] = true;  // a tie next to it forgives nothing there
  EXPECT_FALSE(compareWithOracle(oracle, lit, size, nullptr, &ties).passed());
  ties[12] = true;
  const OracleReport r = compareWithOracle(oracle, lit, size, nullptr, &ties);
  EXPECT_EQ(r.disagreements, 1u);
  EXPECT_EQ(r.onEdges, 1u);
  EXPECT_TRUE(r.passed());
  EXPECT_EQ(oracleEdges(oracle, size, nullptr, &ties), ties) << "the edges a tool reads are the ties here";
}

}  // namespace
