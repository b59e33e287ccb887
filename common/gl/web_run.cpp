// The browser's runLesson (the Emscripten build): the lesson page's script (common/web/lesson.js)
// turns the page's URL into the lesson's command line (--variant, --time, --size, --set), and this
// file makes the session on the page's canvas, shows each frame there, and answers the page's
// calls: play, pause, a frame at a time, a variant, an option, a view (colour, the stencil as the
// window's ramp, in grey or as bit planes, the depth as the window shows it), a pass to stop after
// (the pass stepper), and the snapshot the tests read.
// A bad setting is one line on the page, as on the command line, and nothing is drawn.
#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "gl/debug.h"
#include "gl/errors.h"
#include "gl/gl.h"
#include "gl/lesson.h"
#include "gl/options.h"
#include "gl/session.h"
#include "gl/stencil_view.h"

// The page's side (common/web/lesson.js): StencilPage.
EM_JS(void, stencil_page_error, (const char* message), { StencilPage.error(UTF8ToString(message)); });
EM_JS(void, stencil_page_image, (const char* id, const unsigned char* png, int size),
      { StencilPage.image(UTF8ToString(id), HEAPU8.slice(png, png + size)); });
EM_JS(void, stencil_page_ready, (const char* lesson), { StencilPage.ready(JSON.parse(UTF8ToString(lesson))); });
EM_JS(void, stencil_page_frame, (double time, const char* passes),
      { StencilPage.frame(time, JSON.parse(UTF8ToString(passes))); });
EM_JS(double, stencil_page_now, (), { return performance.now(); });

namespace stencil {
namespace {

struct WebRun {
  LessonInfo info;
  LessonFactory make;
  CommandLine commandLine;
  std::unique_ptr<Session> session;
  bool playing = false;
  double time = 0;           // the frame's time, seconds
  double playedFrom = 0;     // performance.now() when play began, ms
  double playedFromTime = 0;  // the frame's time then
  int view = 0;               // colour, stencil, grey, bits, depth (lesson.js's views)
  std::optional<std::size_t> pass;  // show the frame as it was after this pass; none: the whole frame
  GLuint pictureTexture = 0, pictureFbo = 0;
};

std::unique_ptr<WebRun> run;

void fail(const std::string& message) {
  std::cerr << run->info.id << ": " << message << "\n";
  stencil_page_error(message.c_str());
}

// What the page's controls are made from: the lesson's own declarations.
std::string lessonJson(const WebRun& r) {
  const LessonInfo& info = r.info;
  nlohmann::ordered_json options = nlohmann::ordered_json::array();
  for (const Option& o : r.session->options)
    options.push_back({{"name", o.name}, {"help", o.help}, {"value", o.value}, {"min", o.min}, {"max", o.max}});
  nlohmann::ordered_json variants = nlohmann::ordered_json::array();
  for (const Variant& v : info.variants) variants.push_back({{"name", v.name}, {"help", v.help}});
  const GlFeatures& f = r.session->context->features();
  return nlohmann::ordered_json{{"id", info.id},
                                {"title", info.title},
                                {"summary", info.summary},
                                {"variant", r.session->variant},
                                {"variants", variants},
                                {"options", options},
                                {"passes", info.passes},
                                {"time", r.time},
                                {"size", {r.session->framebuffer->width(), r.session->framebuffer->height()}},
                                {"renderer", f.renderer},
                                {"features", f.summary()}}
      .dump();
}

// Shows a picture (top row first, RGBA) on the canvas, scaled to it.
void showPicture(const Image& picture, int canvasWidth, int canvasHeight) {
  WebRun& r = *run;
  if (!r.pictureTexture) {
    glGenTextures(1, &r.pictureTexture);
    glGenFramebuffers(1, &r.pictureFbo);
  }
  glBindTexture(GL_TEXTURE_2D, r.pictureTexture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, picture.width, picture.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               picture.pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, r.pictureFbo);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r.pictureTexture, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  // The picture's first row is its top: the blit turns it over onto the canvas.
  glBlitFramebuffer(0, picture.height, picture.width, 0, 0, 0, canvasWidth, canvasHeight, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
}

// The depth as the window's depth view shows it (read by drawing it, framebuffer.cpp).
Image depthViewPicture(const std::vector<float>& depth) {
  const Session& s = *run->session;
  return depthPicture(depth, s.framebuffer->width(), s.framebuffer->height(), s.projection, s.reversedDepth);
}

// The stencil as the view shows it.
Image stencilViewPicture(const Image& stencil, int view) {
  if (view == 3) return stencilBitPlanes(stencil);
  if (view == 2) {
    Image grey(stencil.width, stencil.height, 4);
    for (std::size_t i = 0; i < stencil.pixels.size(); ++i) {
      std::uint8_t* p = &grey.pixels[4 * i];
      p[0] = p[1] = p[2] = stencil.pixels[i];
      p[3] = 255;
    }
    return grey;
  }
  return stencilRamp(stencil, StencilRampStyle{.legend = false});
}

// Renders the frame at `time` and shows it on the canvas: in the view asked for, whole or as it was
// after the pass asked for.
void renderAndShow(double time) {
  Session& s = *run->session;
  run->time = time;
  FrameRequest request;
  request.captureOnly = run->pass;
  s.renderFrame(time, request);
  const int w = s.framebuffer->width(), h = s.framebuffer->height();
  const Snapshot* snapshot = run->pass && !s.recorder->snapshots().empty() ? &s.recorder->snapshots().front() : nullptr;
  if (snapshot)
    showPicture(run->view == 0   ? snapshot->colour
                : run->view == 4 ? depthViewPicture(snapshot->depth)
                                 : stencilViewPicture(snapshot->stencil, run->view),
                w, h);
  else if (run->view == 4)
    showPicture(depthViewPicture(s.framebuffer->readDepth()), w, h);
  else if (run->view != 0)
    showPicture(stencilViewPicture(s.framebuffer->readStencil(), run->view), w, h);
  else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.framebuffer->id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  nlohmann::ordered_json passes = nlohmann::ordered_json::array();
  for (const PassStats& p : s.recorder->passStats()) passes.push_back(p.label);
  stencil_page_frame(time, passes.dump().c_str());
}

// Runs `work`; an error stops playing and is said on the page. Returns whether it succeeded.
template <typename Work>
bool guarded(Work work) {
  try {
    work();
    return true;
  } catch (const std::exception& e) {
    run->playing = false;
    emscripten_cancel_main_loop();
    fail(e.what());
    return false;
  }
}

void tick() {
  if (!run->playing) return;
  guarded([] { renderAndShow(run->playedFromTime + (stencil_page_now() - run->playedFrom) / 1000.0); });
}

// What the browser cannot do of what the lesson does on the desktop, said in the page's log.
void sayWhatIsMissing(bool sceneLesson) {
  const std::string id = run->info.id;
  std::cerr << id << ": not in the browser: --stats and its counts (WebGL 2's occlusion queries only say"
            << " whether any sample passed), --depth-out\n";
  if (sceneLesson)
    std::cerr << id << ": not in the browser yet: scene files (--scene); the lesson draws its built-in scene\n";
}

int runWeb(const LessonInfo& info, const LessonFactory& make, int argc, char** argv, bool sceneLesson) {
  run = std::make_unique<WebRun>();
  run->info = info;
  run->make = make;
  const bool ok = guarded([&] {
    run->commandLine = parseCommandLine(run->info, argc, argv);
    run->session = std::make_unique<Session>(run->info, run->make, run->commandLine, Backend::Web);
    const GlFeatures& f = run->session->context->features();
    std::cerr << run->info.id << ": " << f.renderer << ", " << f.version << "; " << f.summary() << "\n";
    sayWhatIsMissing(sceneLesson);
    renderAndShow(run->commandLine.time);
    stencil_page_ready(lessonJson(*run).c_str());
  });
  return ok ? 0 : 2;
}

}  // namespace

int runLesson(const LessonInfo& info, const LessonFactory& factory, int argc, char** argv) {
  return runWeb(info, factory, argc, argv, false);
}

// Scene files in the browser are not read yet: the lesson draws its built-in scene.
int runSceneLesson(const LessonInfo& info, const SceneLessonFactory& factory, int argc, char** argv) {
  return runWeb(info, [factory] { return factory(nullptr); }, argc, argv, true);
}

}  // namespace stencil

using stencil::run;

extern "C" {

// The snapshot contract: the frame at the URL's time, its colour (RGBA) and stencil (one grey byte
// a pixel, as --stencil-out's .raw.png) as PNG files handed to the page. Returns 0, or 1 after
// saying why on the page.
EMSCRIPTEN_KEEPALIVE int stencil_web_snapshot() {
  if (!run || !run->session) return 1;
  const bool ok = stencil::guarded([] {
    run->playing = false;
    stencil::renderAndShow(run->commandLine.time);
    stencil::Session& s = *run->session;
    const std::string colour = stencil::encodePng(s.framebuffer->readColour());
    const std::string stencil = stencil::encodePng(s.framebuffer->readStencil());
    stencil::checkGlErrors("while reading the snapshot");
    stencil_page_image("snapshot-colour", reinterpret_cast<const unsigned char*>(colour.data()),
                       static_cast<int>(colour.size()));
    stencil_page_image("snapshot-stencil", reinterpret_cast<const unsigned char*>(stencil.data()),
                       static_cast<int>(stencil.size()));
  });
  return ok ? 0 : 1;
}

// Plays from the current frame's time (1) or holds it (0).
EMSCRIPTEN_KEEPALIVE void stencil_web_play(int play) {
  if (!run || !run->session) return;
  run->playing = play != 0;
  emscripten_cancel_main_loop();
  if (!run->playing) return;
  run->playedFrom = stencil_page_now();
  run->playedFromTime = run->time;
  emscripten_set_main_loop(stencil::tick, 0, 0);
}

// Shows the frame at `time`, seconds.
EMSCRIPTEN_KEEPALIVE void stencil_web_time(double time) {
  if (!run || !run->session) return;
  run->playedFrom = stencil_page_now();
  run->playedFromTime = time;
  stencil::guarded([time] { stencil::renderAndShow(time); });
}

// The view (0 colour, 1 stencil, 2 grey, 3 bits, 4 depth), then the current frame again.
EMSCRIPTEN_KEEPALIVE int stencil_web_view(int view) {
  if (!run || !run->session) return 1;
  return stencil::guarded([view] {
           if (view < 0 || view > 4)
             throw stencil::UsageError("view " + std::to_string(view) +
                                       ": the browser has colour, stencil, grey, bits and depth");
           run->view = view;
           stencil::renderAndShow(run->time);
         })
             ? 0
             : 1;
}

// The frame as it was after pass `index` (0 the first that ran), or the whole frame (-1).
EMSCRIPTEN_KEEPALIVE int stencil_web_pass(int index) {
  if (!run || !run->session) return 1;
  return stencil::guarded([index] {
           run->pass = index < 0 ? std::nullopt : std::optional<std::size_t>(static_cast<std::size_t>(index));
           stencil::renderAndShow(run->time);
         })
             ? 0
             : 1;
}

// A variant by name, then the current frame again. Returns 0, or 1 after saying why on the page.
EMSCRIPTEN_KEEPALIVE int stencil_web_variant(const char* name) {
  if (!run || !run->session) return 1;
  return stencil::guarded([name] {
           run->session->setVariant(name);
           stencil::renderAndShow(run->time);
         })
             ? 0
             : 1;
}

// An option's value (checked against its declared range), then the current frame again.
EMSCRIPTEN_KEEPALIVE int stencil_web_option(const char* name, int value) {
  if (!run || !run->session) return 1;
  return stencil::guarded([name, value] {
           stencil::Session& s = *run->session;
           std::vector<std::pair<std::string, int>> settings;
           for (const stencil::Option& o : s.options)
             settings.emplace_back(o.name, o.name == name ? value : o.value);
           s.options = stencil::optionsFor(run->info, s.variant, settings);
           stencil::renderAndShow(run->time);
         })
             ? 0
             : 1;
}
}
#endif
