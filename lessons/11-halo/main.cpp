// Lesson 11: the magic halo (Kilgard, "Improving Shadows and Reflections via the Stencil Buffer",
// section 7 and figures 16-17; the GLUT 3.7 demo halomagic.c).
//
// A halo is the object drawn a second time, a little larger, in a glow colour, blended, but only
// where the object itself is not: a ring that never covers the object. The stencil says where:
//   1 clear   the halo's bit to 1 everywhere (the frame's clear value);
//   2 tag     the object drawn once more into the stencil only: its visible pixels get 0;
//   3 halo    the grown object where the bit is still 1 (EQUAL), blended, and INVERT as it blends,
//             so a pixel that two layers of the grown object cover is blended once.
// One bit is enough, so the halo shares the stencil with the floor's reflection (lesson 02) and the
// planar shadow (lesson 04), as in Kilgard's figure 17: each effect writes only its own bit (the
// write mask) and tests only the bits it reads (the read mask):
//   bit 0  reflection  the visible floor; the reflection is drawn there (and the halo reads it)
//   bit 1  shadow      the visible floor not yet darkened; the shadow clears it as it darkens
//   bit 2  halo        the figure's: 1 where its halo may still blend
//   bit 3  halo        the ball's, when a second haloed object stands beside the figure
//
// How the object grows is the method: the whole object scaled about its centre (the paper), each
// convex piece grown about its own centre (the paper's fix for a concave object), the surface pushed
// along its normals (what engines do in object space), or the object's outline moved a few pixels
// in every direction (what engines do in screen space). The lesson measures each: the ring's width
// along the outline, the halo over the object, pixels blended twice, and the fragments it costs.

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/halo.h"
#include "geometry/planar.h"
#include "geometry/shapes.h"
#include "gl/gpu_mesh.h"
#include "gl/lesson.h"
#include "gl/shader.h"

using namespace stencil;

namespace {

constexpr int kWhole = 0, kPieces = 1, kExtrude = 2, kScreen = 3;  // the "method" option

// ---- the stencil's bits, one owner each -----------------------------------------------------------
constexpr GLuint kReflectBit = 0x01;  // visible floor: the reflection's tag
constexpr GLuint kShadowBit = 0x02;   // visible floor not yet darkened: the shadow's tag
constexpr GLuint kFloorBits = kReflectBit | kShadowBit;
constexpr GLuint kHaloBit[2] = {0x04, 0x08};  // the figure's and the ball's: 1 where a halo may blend

// ---- sizes ------------------------------------------------------------------------------------------
constexpr float kScale = 1.12f;        // the paper's recipe: the whole object scaled by this about its centre
constexpr float kGrow = 0.075f;        // the other object-space methods: this many world units on every side
constexpr float kScreenPixels = 5.0f;  // screen space: the outline moved this far at 240 pixels high

// What each pixel means in the blend-count picture (show = 1).
// One blend adds 127 (dark red), two add 254 (bright red), three or more saturate at 255.
constexpr float kCountStep = 127.0f / 255.0f;
constexpr glm::vec4 kFigureId{0.0f, 0.0f, 1.0f, 1.0f}, kBallId{0.0f, 0.0f, 170.0f / 255.0f, 1.0f},
    kRailId{0.0f, 0.0f, 85.0f / 255.0f, 1.0f}, kBlack{0.0f, 0.0f, 0.0f, 1.0f};

constexpr glm::vec4 kSky{0.55f, 0.62f, 0.75f, 1.0f};
constexpr glm::vec3 kFloorColour{0.78f, 0.76f, 0.72f};
constexpr float kFloorOpacity = 0.7f;  // the polished floor over its reflection
constexpr float kShadowAlpha = 0.5f;

// A convex piece of a haloed object, in the object's space: its mesh, and the frame it grows in.
struct Piece {
  Mesh mesh;           // the shape in place (transformed: normals right under its scale)
  glm::mat4 frame;     // its centre and axes: the piece's own space to the object's
  glm::vec3 halfSize;  // along its axes
  glm::vec3 colour;
};

// The figure's pieces and the ball's, made after the lesson.
Piece piece(const Mesh& unit, const glm::mat4& frame, glm::vec3 halfSize, glm::vec3 colour);
std::vector<Piece> figurePieces();

// A haloed object on the GPU: its pieces, once as they are and once with smoothed normals (extrusion).
struct HaloObject {
  std::vector<Piece> pieces;
  std::vector<std::unique_ptr<GpuMesh>> meshes, smooth;
  glm::vec3 centre{0.0f};  // of its bounding box, in its own space: where the whole object is scaled about

  explicit HaloObject(std::vector<Piece> p);  // uploads the pieces, finds the centre
};

class Halo final : public Lesson {
 public:
  // noteCost: say so on stderr when a frame of the screen-space method would take thousands of draws.
  explicit Halo(bool noteCost)
      : noteCost_(noteCost),
        lit_("common/light.vert", "common/light.frag"),
        litFlat_("common/light.vert", "common/flat.frag"),
        clipped_("common/light_clipped.vert", "common/light.frag"),
        clippedFlat_("common/light_clipped.vert", "common/flat.frag"),
        shadow_("common/projected_shadow.vert", "common/flat.frag"),
        flat_("common/flat.vert", "common/flat.frag"),
        shell_("11-halo/shell.vert", "common/flat.frag"),
        floorMesh_(makePlane(3.2f, 1)),
        railMesh_(makeCube(1.0f)),
        floor_(floorMesh_),
        rail_(railMesh_),
        figure_(figurePieces()),
        ball_({piece(makeSphere(1.0f, 32, 16), glm::mat4(1), glm::vec3(0.3f), {0.35f, 0.75f, 0.4f})}) {}

  void render(Frame& f) override {
    const bool counting = f.option("show") == 1;
    const glm::vec4 light = lightAt(f);
    const glm::vec4 floorPlane = planeFrom({0, 0, 0}, {0, 1, 0});
    const glm::vec4 sky = counting ? kBlack : kSky;

    // ---- scene: the objects, then the floor tagged where it is visible --------------------------------
    glClearColor(sky.r, sky.g, sky.b, sky.a);
    glStencilMask(0xFF);
    glClearStencil(static_cast<GLint>(kHaloBit[0] | kHaloBit[1]));  // 1 clear: the halo bits 1, the floor's 0
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);     // nearer surfaces hide farther ones
    glDepthFunc(GL_LESS);        // the nearest surface wins
    glEnable(GL_CULL_FACE);      // closed objects: their back faces never show
    glDisable(GL_STENCIL_TEST);  // the objects tag nothing
    drawObjects(f, glm::mat4(1), light, counting, nullptr);
    glEnable(GL_STENCIL_TEST);                   // the floor tags as it is drawn
    glStencilMask(kFloorBits);                   // the floor writes its two bits and no other
    glStencilFunc(GL_ALWAYS, kFloorBits, 0xFF);  // wherever the floor is drawn...
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);   // ...and seen: tagged for the reflection and the shadow
    drawSurface(f, floor_, glm::mat4(1), kFloorColour, kBlack, light, counting, nullptr);
    f.pass("scene");

    // ---- reflection (lesson 02 on the floor): far, reflect, restore, all where bit 0 is set -----------
    if (f.on("reflect")) {
      glStencilMask(0x00);                                // the reflection writes no bit
      glStencilFunc(GL_EQUAL, kReflectBit, kReflectBit);  // and reads only its own
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);             // (nothing is written anyway)
      glDepthFunc(GL_ALWAYS);  // far: the visible floor's depth pushed to the far plane,
      glDepthRange(1.0, 1.0);  // so the reflected objects can be drawn "under" it
      flat_.set("transform", f.projection * f.view);
      flat_.set("colour", sky);
      floor_.draw();
      glDepthRange(0.0, 1.0);               // the whole range again
      glDepthFunc(GL_LESS);                 // the reflected objects hide each other as the real ones do
      const glm::vec4 below = -floorPlane;  // keep what the mirror image puts below the floor
      glFrontFace(GL_CW);                   // the reflection turns windings over
      glEnable(GL_CLIP_DISTANCE0);          // light_clipped.vert writes the distance to the floor
      drawObjects(f, reflectionMatrix(floorPlane), light, counting, &below);
      glDisable(GL_CLIP_DISTANCE0);  // only the reflection is clipped
      glFrontFace(GL_CCW);           // the real world's winding again
      glDepthFunc(GL_ALWAYS);        // restore: the floor's depth back over the reflection's,
      glEnable(GL_BLEND);            // and the polished floor blended over it
      glBlendColor(0.0f, 0.0f, 0.0f, kFloorOpacity);
      glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
      drawSurface(f, floor_, glm::mat4(1), kFloorColour, kBlack, light, counting, nullptr);
      glDisable(GL_BLEND);   // opaque again
      glDepthFunc(GL_LESS);  // the nearest surface wins again
    }
    f.pass("reflection");

    // ---- shadow (lesson 04): the objects flattened onto the floor, once per pixel of bit 1 --------------
    if (f.on("shadow")) {
      glStencilMask(kShadowBit);                          // the shadow writes its own bit only:
      glStencilFunc(GL_EQUAL, kShadowBit, kShadowBit);    // where it is still set...
      glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);             // ...darken, and clear it: once per pixel
      glDisable(GL_DEPTH_TEST);                           // the bit says where the floor is visible
      glEnable(GL_BLEND);                                 // translucent black:
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // the floor keeps half its light
      glEnable(GL_CLIP_DISTANCE0);                        // only what stands above the floor
      glEnable(GL_CLIP_DISTANCE1);                        // and below the light casts
      shadow_.set("shadowMatrix", planarShadowMatrix(floorPlane, light));
      shadow_.set("viewProjection", f.projection * f.view);
      shadow_.set("receiver", floorPlane);
      shadow_.set("light", light);
      shadow_.set("colour", glm::vec4(0.0f, 0.0f, 0.0f, kShadowAlpha));
      forEachSolid(f, [&](const GpuMesh& mesh, const glm::mat4& model, glm::vec3, glm::vec4) {
        shadow_.set("model", model);
        mesh.draw();
      });
      glDisable(GL_CLIP_DISTANCE0);  // nothing else is clipped
      glDisable(GL_CLIP_DISTANCE1);
      glDisable(GL_BLEND);      // opaque again
      glEnable(GL_DEPTH_TEST);  // the tag and the halo are depth tested
    }
    f.pass("shadow");

    // ---- 2 tag: each haloed object's visible pixels get 0 in its halo bit ------------------------------
    const int haloed = f.on("ball") ? 2 : 1;
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // tagging draws no colour
    glDepthMask(GL_FALSE);                                // and keeps the depth
    glDepthFunc(GL_LEQUAL);             // the object is in the depth buffer already: its visible pixels pass
    glStencilFunc(GL_ALWAYS, 0, 0xFF);  // whatever the bit holds:
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // 0 where the object is seen
    for (int o = 0; o < haloed; ++o) {
      glStencilMask(haloBit(f, o));  // into its halo bit alone
      drawHaloed(f, o, light, counting);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // the halo has colour
    glDepthFunc(GL_LESS);                             // in front of the scene passes
    f.pass("tag");

    // ---- 3 halo: the grown object where its bit is 1, blended, the bit inverted as it blends -------------
    if (f.on("halo")) {
      noteScreenCost(f, haloed);
      for (int o = 0; o < haloed; ++o) drawHalo(f, o, counting);
    }
    glDepthMask(GL_TRUE);  // GL's defaults again, for the next frame and the window's overlay
    glDisable(GL_BLEND);
    glStencilMask(0xFF);
    glDisable(GL_STENCIL_TEST);  // the stencil stays as the halo left it, for --stencil-out
    glEnable(GL_DEPTH_TEST);
    f.pass("halo");

    // ---- what the blend counts say (show = 1) ------------------------------------------------------
    if (counting) measure(f, haloed);
    glDisable(GL_CULL_FACE);  // GL's default again
    f.pass("measure");
  }

 private:
  // ---- the halo ------------------------------------------------------------------------------------------

  // The halo bit of haloed object o: its own, or the figure's when the halos share one.
  static GLuint haloBit(const Frame& f, int o) { return f.on("shared-bit") ? kHaloBit[0] : kHaloBit[o]; }

  void drawHalo(Frame& f, int o, bool counting) {
    const GLuint bit = haloBit(f, o);
    glEnable(GL_BLEND);
    if (counting) {
      glBlendFunc(GL_ONE, GL_ONE);  // each blend adds one step: the picture counts them
    } else {
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // the glow over what is there
    }
    glDepthMask(GL_FALSE);   // a glow is not a surface
    glEnable(GL_CULL_FACE);  // the shell's front faces: one layer per convex piece
    const glm::vec4 glow =
        counting ? (o == 0 ? glm::vec4(kCountStep, 0, 0, 0) : glm::vec4(0, kCountStep, 0, 0))
                 : (o == 0 ? glm::vec4(1.0f, 0.85f, 0.2f, 0.55f) : glm::vec4(0.3f, 0.9f, 1.0f, 0.55f));
    shell_.set("colour", glow);
    shell_.set("objectDepth", f.option("depth"));
    if (!f.on("stencil")) {
      glDisable(GL_STENCIL_TEST);  // Kilgard's "covered in yellow": nothing keeps the halo off the object
      glEnable(GL_DEPTH_TEST);     // but the depth test, and the shell is in front of the object
      drawShell(f, o);
      glEnable(GL_STENCIL_TEST);  // the next halo may have it
      return;
    }
    glStencilMask(bit);                                                   // the halo writes its bit alone
    glStencilOp(GL_KEEP, GL_KEEP, f.on("invert") ? GL_INVERT : GL_KEEP);  // 1 -> 0 as it blends: once
    if (f.on("floor")) {
      // Over the visible floor (the reflection's bit, read through the read mask) the shell is drawn
      // without the depth test, so the part of it below the floor still glows there.
      glStencilFunc(GL_EQUAL, static_cast<GLint>(bit | kReflectBit), bit | kReflectBit);
      glDisable(GL_DEPTH_TEST);  // the floor would hide the shell's part below it
      drawShell(f, o);
      glStencilFunc(GL_EQUAL, static_cast<GLint>(bit), bit | kReflectBit);  // elsewhere, depth tested
    } else {
      glStencilFunc(GL_EQUAL, static_cast<GLint>(bit), bit);  // wherever the bit is still 1
    }
    glEnable(GL_DEPTH_TEST);  // hidden where something nearer stands
    drawShell(f, o);
  }

  // The object's shell, grown by the chosen method: draw calls through shell.vert.
  void drawShell(Frame& f, int o) {
    const HaloObject& h = object(o);
    const glm::mat4 model = modelOf(f, o);
    const int method = f.option("method");
    shell_.set("model", model);
    shell_.set("viewProjection", f.projection * f.view);
    shell_.set("extrude", method == kExtrude ? kGrow : 0.0f);
    const glm::vec2 viewport(f.size);
    shell_.set("shift", glm::vec4(0.0f, 0.0f, viewport));
    const auto pieces = [&](bool smooth) {
      for (std::size_t i = 0; i < h.pieces.size(); ++i) {
        shell_.set("grow", growth(h, i, method));
        (smooth ? h.smooth : h.meshes)[i]->draw();
      }
    };
    if (method != kScreen) {
      pieces(method == kExtrude);
      return;
    }
    // Screen space: the object's outline dilated by a disc of k pixels, as the object drawn once per
    // whole-pixel offset inside the disc.
    const int k = screenRadius(f);
    for (int dy = -k; dy <= k; ++dy)
      for (int dx = -k; dx <= k; ++dx) {
        if (dx * dx + dy * dy > k * k) continue;
        shell_.set("shift", glm::vec4(static_cast<float>(dx), static_cast<float>(dy), viewport));
        pieces(false);
      }
  }

  // The screen method draws every piece once per offset in a disc of k pixels, k in proportion to the
  // height: its draws grow with the square of the height (1134 at 320x240, 4438 at 640x480). Above
  // kScreenDrawsNoted draws a frame, a headless run says once why it is slow; it is not an error.
  static constexpr long kScreenDrawsNoted = 10000;
  void noteScreenCost(const Frame& f, int haloed) {
    if (!noteCost_ || f.option("method") != kScreen) return;
    const int k = screenRadius(f);
    long offsets = 0;
    for (int dy = -k; dy <= k; ++dy)
      for (int dx = -k; dx <= k; ++dx) offsets += dx * dx + dy * dy <= k * k ? 1 : 0;
    long pieces = 0;
    for (int o = 0; o < haloed; ++o) pieces += static_cast<long>(object(o).pieces.size());
    const long draws = offsets * pieces * (f.on("floor") && f.on("stencil") ? 2 : 1);
    if (draws <= kScreenDrawsNoted) return;
    noteCost_ = false;  // once per run
    std::cerr << "note: method 3 (screen) draws " << draws << " shells a frame here (k = " << k << " pixels, "
              << offsets << " offsets): the cost grows with the square of the height\n";
  }

  static int screenRadius(const Frame& f) {
    return std::max(1, static_cast<int>(std::lround(kScreenPixels * static_cast<float>(f.size.y) / 240.0f)));
  }

  // The grow matrix of piece i, in the object's space.
  static glm::mat4 growth(const HaloObject& h, std::size_t i, int method) {
    if (method == kWhole) {  // the whole object about its centre
      return glm::translate(glm::mat4(1), h.centre) * glm::scale(glm::mat4(1), glm::vec3(kScale)) *
             glm::translate(glm::mat4(1), -h.centre);
    }
    if (method == kPieces) {  // each piece about its own centre, kGrow further on every side
      const Piece& p = h.pieces[i];
      return p.frame * glm::scale(glm::mat4(1), (p.halfSize + kGrow) / p.halfSize) * glm::inverse(p.frame);
    }
    return glm::mat4(1);
  }

  // ---- measuring (show = 1) --------------------------------------------------------------------------

  // Reads the blend-count picture back, measures each halo (geometry/halo.h), and counts the fragments
  // the shells rasterize with every test off: what each method costs before the stencil rejects any.
  void measure(Frame& f, int haloed) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(f.size.x) * static_cast<std::size_t>(f.size.y) *
                                   4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows packed tight
    glReadPixels(0, 0, f.size.x, f.size.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);  // GL's default again
    const std::size_t n = rgba.size() / 4;
    for (int o = 0; o < haloed; ++o) {
      std::vector<std::uint8_t> object(n), blends(n), blocked(n);
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t id = rgba[4 * i + 2];
        object[i] = id == idByte(o == 0 ? kFigureId : kBallId);
        blocked[i] = id != 0 && !object[i];
        blends[i] = blendCount(rgba[4 * i + static_cast<std::size_t>(o)]);
      }
      const HaloMeasure m = measureHalo(object, blends, blocked, f.size);
      const std::string name = o == 0 ? "figure." : "ball.";
      f.count(name + "object_pixels", m.objectPixels);
      f.count(name + "halo_pixels", m.haloPixels);
      f.count(name + "covered_pixels", m.coveredPixels);
      f.count(name + "multi_blended_pixels", m.multiPixels);
      f.count(name + "blends", m.blends);
      f.count(name + "outline_pixels", m.outlinePixels);
      f.count(name + "filled_pixels", m.filledPixels);
      f.count(name + "width_mean_x100", static_cast<std::uint64_t>(std::lround(100.0 * m.widthMean)));
      f.count(name + "width_min_x100", static_cast<std::uint64_t>(std::lround(100.0 * m.widthMin)));
      f.count(name + "width_max_x100", static_cast<std::uint64_t>(std::lround(100.0 * m.widthMax)));
    }
    // Every fragment the shells rasterize: the same draws with every test and every write off.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // nothing written:
    glDepthMask(GL_FALSE);                                // the frame stays as it is
    glDisable(GL_DEPTH_TEST);                             // nothing rejected:
    glDisable(GL_STENCIL_TEST);                           // every fragment counts
    glEnable(GL_CULL_FACE);                               // as the halo pass draws them: front faces
    shell_.set("colour", glm::vec4(0.0f));
    shell_.set("objectDepth", 0);
    for (int o = 0; o < haloed; ++o) {
      GLuint64 rasterized = 0;
      f.ownOcclusionQueries([&] {
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_SAMPLES_PASSED, query);
        drawShell(f, o);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &rasterized);
        glDeleteQueries(1, &query);
      });
      f.count(std::string(o == 0 ? "figure." : "ball.") + "shell_fragments", rasterized);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);  // GL's defaults again
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
  }

  static std::uint8_t idByte(const glm::vec4& id) {
    return static_cast<std::uint8_t>(std::lround(id.b * 255.0f));
  }
  // 127 per blend, saturating at 255: 0, 1, 2 (254), and 3 for three or more (255).
  static std::uint8_t blendCount(std::uint8_t v) {
    return static_cast<std::uint8_t>(v == 255 ? 3 : (v + 63) / 127);
  }

  // ---- the scene -------------------------------------------------------------------------------------

  const HaloObject& object(int o) const { return o == 0 ? figure_ : ball_; }

  static glm::mat4 figureModel(const Frame& f) {
    const float turn =
        30.0f + 12.0f * std::sin(0.6f * static_cast<float>(f.time));  // faces the camera, swaying
    return glm::rotate(glm::mat4(1), glm::radians(turn), {0, 1, 0});
  }
  static glm::mat4 modelOf(const Frame& f, int o) {
    if (o == 0) return figureModel(f);
    // The ball floats in front of the figure's raised right arm, nearer the eye: it hides part of the arm.
    const float bob = 0.08f * std::sin(1.3f * static_cast<float>(f.time));
    return figureModel(f) * glm::translate(glm::mat4(1), {0.62f, 1.45f + bob, 0.45f});
  }
  // The rail: a bar across the figure's chest, 3 cm thick, its back face on the body and its front face
  // 3 cm in front of it (nearer than the grown shell's 7.5 cm).
  static glm::mat4 railModel(const Frame& f) {
    return figureModel(f) * glm::translate(glm::mat4(1), {0.0f, 1.0f, 0.355f}) *
           glm::scale(glm::mat4(1), {0.95f, 0.06f, 0.015f});
  }

  glm::vec4 lightAt(const Frame& f) const {
    const float a = 0.8f + 0.25f * static_cast<float>(f.time);
    return {2.2f * std::cos(a), 5.0f, 2.2f * std::sin(a), 1.0f};
  }

  // Every solid the scene has: the figure's pieces, the ball and the rail when on.
  template <typename Draw>
  void forEachSolid(const Frame& f, Draw&& draw) const {
    const glm::vec4 ids[2] = {kFigureId, kBallId};
    for (int o = 0; o < (f.on("ball") ? 2 : 1); ++o) {
      const HaloObject& h = object(o);
      for (std::size_t i = 0; i < h.pieces.size(); ++i)
        draw(*h.meshes[i], modelOf(f, o), h.pieces[i].colour, ids[o]);
    }
    if (f.on("occluder")) draw(rail_, railModel(f), glm::vec3(0.25f, 0.5f, 0.3f), kRailId);
  }

  // The objects through `reflect` (the identity for the real scene). Reflected, every one is black in
  // the count picture: only the real objects are measured.
  void drawObjects(const Frame& f, const glm::mat4& reflect, glm::vec4 light, bool counting,
                   const glm::vec4* clip) {
    forEachSolid(f, [&](const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, glm::vec4 id) {
      drawSurface(f, mesh, reflect * model, colour, clip ? kBlack : id, light, counting, clip, reflect);
    });
  }

  // The tag pass draws a haloed object as the scene pass drew it (same program, same depths).
  void drawHaloed(const Frame& f, int o, glm::vec4 light, bool counting) {
    const HaloObject& h = object(o);
    for (std::size_t i = 0; i < h.pieces.size(); ++i)
      drawSurface(f, *h.meshes[i], modelOf(f, o), h.pieces[i].colour, kBlack, light, counting, nullptr);
  }

  // One lit surface; in the count picture a flat colour (the object's id, or black) with the same
  // vertex shader, so both pictures have the same depths and stencil.
  void drawSurface(const Frame& f, const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour,
                   glm::vec4 id, glm::vec4 light, bool counting, const glm::vec4* clip,
                   const glm::mat4& reflect = glm::mat4(1)) const {
    const Program& p = clip ? (counting ? clippedFlat_ : clipped_) : (counting ? litFlat_ : lit_);
    p.set("model", model);
    p.set("viewProjection", f.projection * f.view);
    if (clip) p.set("clipPlane", *clip);
    if (counting) {
      p.set("colour", id);
    } else {
      p.set("colour", colour);
      p.set("light", reflect * light);  // lit as in the real world, then mirrored with the scene
      p.set("lightColour", glm::vec3(1.0f));
      p.set("ambient", glm::vec3(0.3f));
      p.set("eye", f.eye);
      p.set("shininess", 32.0f);
    }
    mesh.draw();
  }

  bool noteCost_;
  Program lit_, litFlat_, clipped_, clippedFlat_, shadow_, flat_, shell_;
  Mesh floorMesh_, railMesh_;
  GpuMesh floor_, rail_;
  HaloObject figure_, ball_;
};

// ---- the haloed objects ---------------------------------------------------------------------------

HaloObject::HaloObject(std::vector<Piece> p) : pieces(std::move(p)) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Piece& q : pieces) {
    meshes.push_back(std::make_unique<GpuMesh>(q.mesh));
    smooth.push_back(std::make_unique<GpuMesh>(smoothNormals(q.mesh)));
    for (const glm::vec3& v : q.mesh.positions) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
  centre = 0.5f * (lo + hi);
}

// A unit shape (radius 1, height 2) scaled to halfSize along the frame's axes and put in place.
Piece piece(const Mesh& unit, const glm::mat4& frame, glm::vec3 halfSize, glm::vec3 colour) {
  return {transformed(unit, frame * glm::scale(glm::mat4(1), halfSize)), frame, halfSize, colour};
}

// The figure, feet on the floor at the origin, facing +z: a body, a head with a hat, two legs and
// two raised arms, each a convex piece; together concave.
std::vector<Piece> figurePieces() {
  using glm::translate;
  const glm::mat4 id(1.0f);
  const glm::vec3 skin{0.95f, 0.55f, 0.3f}, cloth{0.3f, 0.45f, 0.85f}, hat{0.75f, 0.2f, 0.3f};
  const Mesh ball = makeSphere(1.0f, 32, 16), limb = makeCylinder(1.0f, 2.0f, 24),
             cone = makeCone(1.0f, 2.0f, 24);
  std::vector<Piece> p;
  p.push_back(piece(ball, translate(id, {0.0f, 0.95f, 0.0f}), {0.42f, 0.55f, 0.34f}, cloth));
  p.push_back(piece(ball, translate(id, {0.0f, 1.74f, 0.0f}), glm::vec3(0.26f), skin));
  p.push_back(piece(cone, translate(id, {0.0f, 2.12f, 0.0f}), {0.2f, 0.17f, 0.2f}, hat));
  for (const float side : {-1.0f, 1.0f}) {
    p.push_back(piece(limb, translate(id, {0.19f * side, 0.28f, 0.0f}), {0.11f, 0.28f, 0.11f}, cloth));
    const glm::mat4 arm =
        glm::rotate(translate(id, {0.6f * side, 1.2f, 0.0f}), glm::radians(-55.0f * side), {0, 0, 1});
    p.push_back(piece(limb, arm, {0.085f, 0.36f, 0.085f}, skin));
  }
  return p;
}

// ---- the lesson: options, variants, camera -------------------------------------------------------

LessonInfo lessonInfo() {
  LessonInfo info;
  info.id = "11-halo";
  info.title = "The magic halo";
  info.summary =
      "A glow around an object that never covers it: the object grown and blended where its stencil tag is\n"
      "absent, INVERT so each pixel blends once; one bit beside a reflection's and a shadow's on one floor.";
  info.options = {
      {"method", 'M',
       "how the object grows: 0 the whole object scaled about its\n"
       "      centre (the paper), 1 each convex piece grown about its own\n"
       "      centre (the paper's fix), 2 pushed along its normals, 3 its\n"
       "      outline moved k pixels every way (screen space: a draw per\n"
       "      offset, the cost grows with the square of the height)",
       kPieces, 3},
      {"stencil", 'T', "tag the object and draw the halo only where the tag is absent", 1},
      {"invert", 'I', "INVERT the halo's bit as each pixel blends, so no pixel blends twice", 1},
      {"depth", 'Z', "the halo at the object's own depth (0: at the grown shell's, nearer)", 1},
      {"floor", 'F', "over the visible floor (the reflection's bit) the halo skips the depth test", 1},
      {"occluder", 'O', "a rail just in front of the figure", 0},
      {"ball", 'B', "a second haloed object, its own bit: a ball in front of the figure's arm", 0},
      {"shared-bit", 'H', "the ball's halo in the figure's bit (one bit for two halos)", 0},
      {"reflect", 'E', "the floor's reflection", 1},
      {"shadow", 'D', "the planar shadow on the floor", 1},
      {"halo", 'G', "draw the halo at all (off: the tests' reference)", 1},
      {"show", 'X',
       "0 the shaded frame; 1 the blend counts: the same passes in flat\n"
       "      colours, the figure blue, each blend of the figure's halo adding\n"
       "      127 to red (twice 254), the ball's to green (--stats: measures)",
       0},
  };
  info.variants = {
      {"recipe",
       "figure 17: the halo (a piece at a time), the reflection and the shadow share the stencil",
       {}},
      {"no-stencil",
       "the halo without the stencil: the figure covered in yellow",
       {{"stencil", 0}, {"depth", 0}}},
      {"no-invert",
       "the stencil tag but KEEP: where the pieces' shells overlap, pixels blend twice",
       {{"invert", 0}}},
      {"whole-object",
       "the paper's recipe on a concave figure: scaled about its centre, an uneven ring",
       {{"method", kWhole}}},
      {"occluder",
       "a rail just in front: the grown shell is nearer than the rail and paints over it",
       {{"occluder", 1}, {"depth", 0}}},
      {"occluder-fixed", "the shell at the figure's own depth: the rail hides the halo", {{"occluder", 1}}},
      {"floor-cut",
       "the shell below the floor fails the depth test: the ring is cut at the feet",
       {{"floor", 0}}},
      {"two-halos",
       "a ball in front of the figure, one bit each: both halos blend once, also over each other",
       {{"ball", 1}}},
      {"two-halos-one-bit",
       "both halos in one bit: the first halo's INVERT and tag cut the second",
       {{"ball", 1}, {"shared-bit", 1}}},
      {"extrude",
       "engines: the surface pushed along its smoothed normals, an even width in world units",
       {{"method", kExtrude}}},
      {"screen",
       "engines: the outline dilated by k pixels, the figure drawn shifted every way",
       {{"method", kScreen}}},
      {"counts", "the recipe's blend counts: every halo pixel blended once", {{"show", 1}}},
      {"counts-no-invert",
       "the blend counts without INVERT: the overlaps blended twice",
       {{"show", 1}, {"invert", 0}}},
      {"counts-two-halos",
       "the blend counts of two halos, a bit each: the ball's ring whole, over the figure too",
       {{"show", 1}, {"ball", 1}}},
      {"counts-two-halos-one-bit",
       "the blend counts with one bit for both: the ball's ring cut where the figure's is",
       {{"show", 1}, {"ball", 1}, {"shared-bit", 1}}},
  };
  info.passes = {"scene", "reflection", "shadow", "tag", "halo", "measure"};
  info.camera.target = {0.0f, 0.8f, 0.0f};
  info.camera.distance = 4.9f;
  info.camera.azimuthDeg = 30.0f;
  info.camera.elevationDeg = 15.0f;
  return info;
}

}  // namespace

int main(int argc, char** argv) {
  const auto given = [&](std::string_view flag) {
    return std::find(argv + 1, argv + argc, flag) != argv + argc;
  };
  const bool noteCost = given("--headless") && !given("--quiet");
  return runLesson(
      lessonInfo(), [noteCost] { return std::make_unique<Halo>(noteCost); }, argc, argv);
}
