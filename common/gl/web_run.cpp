// The browser's runLesson (the Emscripten build): the lesson page's script (common/web/lesson.js)
// turns the page's URL into the lesson's command line (--variant, --time, --size, --set), and this
// file makes the session on the page's canvas, shows each frame there, and answers the page's
// calls: play, pause, a frame at a time, a variant, an option, a view (colour, the stencil as the
// window's ramp, in grey or as bit planes, the depth as the window shows it), a pass to stop after
// (the pass stepper), the orbit camera, a scene file (the scene lessons), and the snapshot the
// tests read.
// What the URL asks for and the lesson refuses is one line on the page, as on the command line, and
// the lesson is drawn without it; a scene file that cannot be read is one line on the page, and the
// lesson keeps its last good scene.
#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
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
EM_JS(void, stencil_page_refused, (const char* message), { StencilPage.refused(UTF8ToString(message)); });
EM_JS(void, stencil_page_image, (const char* id, const unsigned char* png, int size),
      { StencilPage.image(UTF8ToString(id), HEAPU8.slice(png, png + size)); });
EM_JS(void, stencil_page_ready, (const char* lesson), { StencilPage.ready(JSON.parse(UTF8ToString(lesson))); });
EM_JS(void, stencil_page_frame, (double time, const char* passes),
      { StencilPage.frame(time, JSON.parse(UTF8ToString(passes))); });
EM_JS(void, stencil_page_legend, (const char* legend),
      { StencilPage.legend(JSON.parse(UTF8ToString(legend))); });
EM_JS(double, stencil_page_now, (), { return performance.now(); });

namespace stencil {
namespace {

struct WebRun {
  LessonInfo declared;  // the lesson's own declarations
  SceneLessonFactory make;
  bool readsScenes = false;
  CommandLine commandLine;  // the page's, with the scene file the session was made with
  // The session's scene (nullptr: the lesson's own) and the declarations it was made with (a
  // scene's camera and lights change them): both outlive the session, which refers to them.
  std::unique_ptr<Scene> scene;
  std::unique_ptr<LessonInfo> info;
  std::unique_ptr<Session> session;
  bool playing = false;
  double time = 0;           // the frame's time, seconds
  double playedFrom = 0;     // performance.now() when play began, ms
  double playedFromTime = 0;  // the frame's time then
  int view = 0;               // colour, stencil, grey, bits, depth (lesson.js's views)
  std::optional<std::size_t> pass;  // show the frame as it was after this pass; none: the whole frame
  GLuint pictureTexture = 0, pictureFbo = 0;
  bool urlRefused = false;  // the URL's settings were refused: the lesson started as it starts
};

std::unique_ptr<WebRun> run;

void fail(const std::string& message) {
  std::cerr << run->declared.id << ": " << message << "\n";
  stencil_page_error(message.c_str());
}

// The scene files a scene lesson offers (embedded at /scenes by common/web/web.cmake), relative to
// it, sorted.
std::vector<std::string> sceneFiles() {
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::recursive_directory_iterator("/scenes", error))
    if (entry.path().extension() == ".scene") files.push_back(entry.path().lexically_relative("/scenes").string());
  std::sort(files.begin(), files.end());
  return files;
}

// What the page's controls are made from: the lesson's own declarations.
std::string lessonJson(const WebRun& r) {
  const LessonInfo& info = *r.info;
  // Each option with the value its variant gives it (the URL's set= names only those away from it).
  const std::vector<Option> ofVariant = optionsFor(info, r.session->variant, {});
  nlohmann::ordered_json options = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.session->options.size(); ++i) {
    const Option& o = r.session->options[i];
    options.push_back({{"name", o.name}, {"help", o.help}, {"value", o.value}, {"variantValue", ofVariant[i].value},
                       {"min", o.min}, {"max", o.max}});
  }
  nlohmann::ordered_json variants = nlohmann::ordered_json::array();
  for (const Variant& v : info.variants) variants.push_back({{"name", v.name}, {"help", v.help}});
  // The options away from the variant's values, as the URL's set= gives them ("name:value").
  std::vector<std::string> changed;
  for (std::size_t i = 0; i < r.session->options.size(); ++i)
    if (r.session->options[i].value != ofVariant[i].value)
      changed.push_back(r.session->options[i].name + ":" + std::to_string(r.session->options[i].value));
  const GlFeatures& f = r.session->context->features();
  return nlohmann::ordered_json{
      {"id", info.id},
      {"title", info.title},
      {"summary", info.summary},
      {"variant", r.session->variant},
      {"variants", variants},
      {"options", options},
      {"passes", info.passes},
      {"time", r.time},
      {"size", {r.session->framebuffer->width(), r.session->framebuffer->height()}},
      {"renderer", f.renderer},
      {"features", f.summary()},
      {"readsScenes", r.readsScenes},
      {"urlRefused", r.urlRefused},
      {"changed", changed},
      {"scene", r.commandLine.scene ? r.commandLine.scene->string() : ""},
      {"scenes", r.readsScenes ? sceneFiles() : std::vector<std::string>{}},
      {"orbit", {r.session->camera.azimuthDeg, r.session->camera.elevationDeg, r.session->camera.distance}}}
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

// The depth as the window's depth view shows it (read by drawing it, framebuffer.cpp), the frame's
// rows only: the page writes the legend's line below the canvas.
Image depthViewPicture(const std::vector<float>& depth, nlohmann::ordered_json& legend) {
  const Session& s = *run->session;
  const int w = s.framebuffer->width(), h = s.framebuffer->height();
  DepthRange range;
  Image picture = depthPicture(depth, w, h, s.projection, s.reversedDepth, &range);
  picture.pixels.resize(static_cast<std::size_t>(4 * w * h));
  picture.height = h;
  legend = {{"rule", depthLegendLine(range)}};
  return picture;
}

// A stencil view (1 the ramp, 2 grey, 3 the bit planes) and its legend for the page: the ramp's and
// grey's values present, each [value, pixels, "#rrggbb"], grey's rule first; the bit planes' layout.
Image stencilViewPicture(const Image& stencil, int view, nlohmann::ordered_json& legend) {
  if (view == 3) {
    legend = {
        {"rule", "the eight bit planes: bit 0 top left to bit 7 bottom right, white where the bit is set"}};
    return stencilBitPlanes(stencil);
  }
  const StencilLegend values = stencilLegend(stencil, view == 2);
  nlohmann::ordered_json entries = nlohmann::ordered_json::array();
  for (int v = 0; v < 256; ++v) {
    const auto i = static_cast<std::size_t>(v);
    if (values.histogram[i] == 0) continue;
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", values.colours[i][0], values.colours[i][1],
                  values.colours[i][2]);
    entries.push_back({v, values.histogram[i], colour});
  }
  legend = {{"rule", view == 2 ? "grey: " + values.greyRule : "stencil values"}, {"entries", entries}};
  return stencilRamp(stencil, StencilRampStyle{.legend = false, .grey = view == 2});
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
  nlohmann::ordered_json legend = nlohmann::ordered_json::object();
  if (run->view == 4)
    showPicture(depthViewPicture(snapshot ? snapshot->depth : s.framebuffer->readDepth(), legend), w, h);
  else if (run->view != 0)
    showPicture(
        stencilViewPicture(snapshot ? snapshot->stencil : s.framebuffer->readStencil(), run->view, legend), w,
        h);
  else if (snapshot)
    showPicture(snapshot->colour, w, h);
  else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, s.framebuffer->id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  stencil_page_legend(legend.dump().c_str());
  nlohmann::ordered_json passes = nlohmann::ordered_json::array();
  for (const PassStats& p : s.recorder->passStats()) passes.push_back(p.label);
  stencil_page_frame(time, passes.dump().c_str());
}

// Runs `work`; an error stops playing and is said on the page, and a change the lesson refuses
// (UsageError: an option out of range) is said and leaves the lesson as it was. Returns whether
// it succeeded.
template <typename Work>
bool guarded(Work work) {
  try {
    work();
    return true;
  } catch (const UsageError& e) {
    std::cerr << run->declared.id << ": " << e.what() << "\n";
    stencil_page_refused(e.what());
    return false;
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
void sayWhatIsMissing() {
  std::cerr << run->declared.id << ": not in the browser: --stats and its counts (WebGL 2's occlusion queries"
            << " only say whether any sample passed), --depth-out\n";
}

// The session for the scene file `path` (empty: the lesson's own scene), keeping the variant and
// options the page has. The file is read and the options checked before the running session goes,
// so that a bad file leaves it as it was (UsageError, the one line the command line gives).
void startSession(const std::optional<std::filesystem::path>& path) {
  WebRun& r = *run;
  CommandLine cl = r.commandLine;
  cl.scene = path;
  if (r.session) {  // the variant, and the options the page set away from its values
    cl.variant = r.session->variant;
    cl.settings = settingsAwayFromVariant(r.declared, cl.variant, r.session->options);
  }
  addSceneSettings(r.declared, cl);
  auto info = std::make_unique<LessonInfo>(r.declared);
  std::unique_ptr<Scene> scene;
  if (path) scene = std::make_unique<Scene>(readScene(cl, *info));
  if (info->refuseOptions) {
    const std::vector<Option> options = optionsFor(*info, cl.variant, cl.settings);
    const std::string why = info->refuseOptions({options, cl.settings, scene.get()});
    if (!why.empty()) throw UsageError(why);
  }
  if (scene) sayWhatTheCastersNeeded(cl, *scene);
  if (r.pictureTexture) {  // the canvas's objects go with the context
    glDeleteTextures(1, &r.pictureTexture);
    glDeleteFramebuffers(1, &r.pictureFbo);
    r.pictureTexture = r.pictureFbo = 0;
  }
  r.session.reset();
  r.commandLine = cl;
  r.info = std::move(info);
  r.scene = std::move(scene);
  const Scene* fromFile = r.scene.get();
  r.session = std::make_unique<Session>(*r.info, [make = r.make, fromFile] { return make(fromFile); },
                                        r.commandLine, Backend::Web);
  r.session->scene = fromFile;
}

int runWeb(const LessonInfo& info, const SceneLessonFactory& make, int argc, char** argv, bool readsScenes) {
  run = std::make_unique<WebRun>();
  run->declared = info;
  run->make = make;
  run->readsScenes = readsScenes;
  const bool ok = guarded([&] {
    // What the URL asks for and the lesson refuses (a variant it lacks, an option out of range, a
    // scene file it cannot read) is said on the page, and the lesson drawn without it, so that its
    // controls are there to choose again. A refusal is said, then the first of the URL's settings
    // (a flag and its value: lesson.js gives only pairs) whose leaving out lets the lesson start or
    // changes what is refused is left out, and so on: every refused setting is said, and the lesson
    // starts with the others (else as it starts).
    const auto attempt = [&](std::vector<char*> args) {
      try {
        const CommandLine cl = parseCommandLine(run->declared, static_cast<int>(args.size()), args.data());
        if (cl.scene && !readsScenes)
          throw UsageError("--scene: " + info.id + " draws only its own scene; the scene lessons read scene files");
        run->commandLine = cl;
        startSession(cl.scene);
        return std::string();
      } catch (const UsageError& e) {
        return std::string(e.what());
      }
    };
    std::vector<char*> args{argv, argv + argc};
    std::string why = attempt(args);
    while (!why.empty()) {
      if (args.size() == 1) throw UsageError(why);
      std::cerr << info.id << ": " << why << "\n";
      stencil_page_refused(why.c_str());
      run->urlRefused = true;
      std::string next = why;
      for (std::size_t k = 1; k + 1 < args.size() && next == why; k += 2) {
        std::vector<char*> less = args;
        less.erase(less.begin() + static_cast<std::ptrdiff_t>(k), less.begin() + static_cast<std::ptrdiff_t>(k) + 2);
        next = attempt(less);
        if (next != why) args = less;
      }
      if (next == why) {  // no one setting: the lesson as it starts
        args.resize(1);
        next = attempt(args);
      }
      why = next;
    }
    const GlFeatures& f = run->session->context->features();
    std::cerr << run->declared.id << ": " << f.renderer << ", " << f.version << "; " << f.summary() << "\n";
    sayWhatIsMissing();
    renderAndShow(run->commandLine.time);
    stencil_page_ready(lessonJson(*run).c_str());
  });
  return ok ? 0 : 2;
}

}  // namespace

int runLesson(const LessonInfo& info, const LessonFactory& factory, int argc, char** argv) {
  return runWeb(info, [factory](const Scene*) { return factory(); }, argc, argv, false);
}

int runSceneLesson(const LessonInfo& info, const SceneLessonFactory& factory, int argc, char** argv) {
  return runWeb(info, factory, argc, argv, true);
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

// The orbit camera turned by `azimuth` and `elevation` degrees (the elevation held within 89 degrees
// of level) and its distance multiplied by `zoom` (held within 0.5-80 world units), as the window's
// drag and wheel do, then the current frame again.
EMSCRIPTEN_KEEPALIVE void stencil_web_orbit(double azimuth, double elevation, double zoom) {
  if (!run || !run->session || !std::isfinite(azimuth) || !std::isfinite(elevation) || !std::isfinite(zoom) ||
      zoom <= 0)
    return;
  stencil::OrbitCamera& c = run->session->camera;
  const stencil::OrbitCamera before = c;
  c.azimuthDeg = static_cast<float>(std::remainder(c.azimuthDeg + azimuth, 360.0));
  c.elevationDeg = std::clamp(static_cast<float>(c.elevationDeg + elevation), -89.0f, 89.0f);
  c.distance = std::clamp(static_cast<float>(c.distance * zoom), 0.5f, 80.0f);
  if (stencil::guarded([] { stencil::renderAndShow(run->time); })) return;
  // A view the lesson refuses (lesson 14: the near plane inside the solid) is said and not kept.
  run->session->camera = before;
  stencil::guarded([] { stencil::renderAndShow(run->time); });
}

// The orbit camera where it stands now: azimuth and elevation in degrees, distance in world units.
EMSCRIPTEN_KEEPALIVE double stencil_web_orbit_value(int which) {
  if (!run || !run->session) return 0;
  const stencil::OrbitCamera& c = run->session->camera;
  return which == 0 ? c.azimuthDeg : which == 1 ? c.elevationDeg : c.distance;
}

// A scene file (a path in the program's files: /scenes/..., or one the page wrote from a file the
// reader dropped; empty: the lesson's own scene) in place of the current one. Returns 0, or 1 after
// saying why on the page, the lesson keeping its last good scene.
EMSCRIPTEN_KEEPALIVE int stencil_web_scene(const char* path) {
  if (!run || !run->session) return 1;
  if (!run->readsScenes) {
    stencil_page_refused((run->declared.id + " draws only its own scene; the scene lessons read scene files").c_str());
    return 1;
  }
  const std::optional<std::filesystem::path> previous = run->commandLine.scene;
  try {
    stencil::startSession(*path ? std::optional<std::filesystem::path>(path) : std::nullopt);
    stencil::renderAndShow(run->time);
    stencil_page_ready(stencil::lessonJson(*run).c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << run->declared.id << ": " << e.what() << "\n";
    stencil_page_refused(e.what());
  }
  if (!run->session)  // the new session failed after the old one went: the last good scene again
    stencil::guarded([&previous] {
      stencil::startSession(previous);
      stencil::renderAndShow(run->time);
    });
  return 1;
}

// An option's value (checked against its declared range), then the current frame again. Returns
// 0, or 1 after saying why on the page, the options drawn before kept (lesson 14's method 0 with a
// scene file, say).
EMSCRIPTEN_KEEPALIVE int stencil_web_option(const char* name, int value) {
  if (!run || !run->session) return 1;
  stencil::Session& s = *run->session;
  const std::vector<stencil::Option> options = s.options;
  if (stencil::guarded([&s, name, value] {
        std::vector<std::pair<std::string, int>> settings;
        for (const stencil::Option& o : s.options) settings.emplace_back(o.name, o.name == name ? value : o.value);
        s.options = stencil::optionsFor(*run->info, s.variant, settings);
        stencil::renderAndShow(run->time);
      }))
    return 0;
  if (s.options == options) return 1;
  s.options = options;
  stencil::guarded([] { stencil::renderAndShow(run->time); });
  return 1;
}
}
#endif
