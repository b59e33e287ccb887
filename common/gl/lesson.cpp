#include "gl/lesson.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <regex>
#include <sstream>

#include "gl/debug.h"
#include "gl/errors.h"
#include "gl/golden.h"
#include "gl/session.h"
#include "gl/shader.h"
#include "gl/stencil_view.h"

namespace stencil {

// ---- lesson model -------------------------------------------------------------------

const char* featureName(Feature f) {
  switch (f) {
    case Feature::DepthBoundsTest: return "EXT_depth_bounds_test";
    case Feature::PipelineStatistics: return "ARB_pipeline_statistics_query";
    case Feature::ClipControl: return "ARB_clip_control";
    case Feature::DepthClamp: return "ARB_depth_clamp";
    case Feature::KhrDebug: return "KHR_debug";
    case Feature::StencilExport: return "ARB_shader_stencil_export";
  }
  return "?";
}

bool hasFeature(const GlFeatures& g, Feature f) {
  switch (f) {
    case Feature::DepthBoundsTest: return g.depthBoundsTest;
    case Feature::PipelineStatistics: return g.pipelineStatistics;
    case Feature::ClipControl: return g.clipControl;
    case Feature::DepthClamp: return g.depthClamp;
    case Feature::KhrDebug: return g.khrDebug;
    case Feature::StencilExport: return g.stencilExport;
  }
  return false;
}

glm::vec3 OrbitCamera::eye() const {
  const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return target +
         distance * glm::vec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
}
glm::mat4 OrbitCamera::view() const {
  const glm::mat4 lookAt = glm::lookAt(eye(), target, glm::vec3(0, 1, 0));
  return mirrored ? glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) * lookAt : lookAt;
}
glm::mat4 OrbitCamera::projection(float aspect) const {
  if (orthographic) {
    const float h = 0.5f * orthoHeight, w = h * aspect;
    return glm::ortho(-w, w, -h, h, nearPlane, farPlane);
  }
  if (std::isinf(farPlane)) return glm::infinitePerspective(glm::radians(fovyDeg), aspect, nearPlane);
  return glm::perspective(glm::radians(fovyDeg), aspect, nearPlane, farPlane);
}

OrbitCamera orbitCameraOf(const SceneCamera& c) {
  if (glm::length(c.up) == 0.0f || glm::length(glm::normalize(c.up) - glm::vec3(0, 1, 0)) > 1e-6f)
    throw std::invalid_argument("the camera's up must be +y (0 1 0)");
  const glm::vec3 offset = c.eye - c.target;
  const float distance = glm::length(offset);
  if (!(distance > 0.0f)) throw std::invalid_argument("the camera's eye is on its target");
  const glm::vec3 d = offset / distance;
  if (glm::length(glm::vec2(d.x, d.z)) < 1e-6f)
    throw std::invalid_argument("the camera looks straight up or down, where +y cannot be its up");
  OrbitCamera o;
  o.target = c.target;
  o.distance = distance;
  o.azimuthDeg = glm::degrees(std::atan2(d.x, d.z));  // eye() puts the eye at (sin az, ., cos az)
  o.elevationDeg = glm::degrees(std::asin(glm::clamp(d.y, -1.0f, 1.0f)));
  o.fovyDeg = c.fovyDeg;
  o.nearPlane = c.nearPlane;
  o.farPlane = c.farPlane;
  o.orthographic = c.orthographic;
  o.orthoHeight = c.orthoHeight;
  o.mirrored = c.mirrored;
  return o;
}

Frame::Frame(double t, glm::ivec2 s, const OrbitCamera& camera, const std::vector<Option>& options,
             PassRecorder& recorder, const GlFeatures& f, bool reversed, unsigned framebuffer)
    : time(t),
      size(s),
      view(camera.view()),
      projection(camera.projection(static_cast<float>(s.x) / static_cast<float>(s.y))),
      eye(camera.eye()),
      features(f),
      reversedDepth(reversed),
      options_(options),
      recorder_(recorder),
      framebuffer_(framebuffer) {}

int Frame::option(std::string_view name) const {
  for (const Option& o : options_)
    if (o.name == name) return o.value;
  throw std::logic_error("the lesson reads option '" + std::string(name) + "', which it does not declare");
}

void Frame::pass(std::string_view name, std::string_view detail) {
  recorder_.pass(name, detail);
}

void Frame::ownOcclusionQueries(const std::function<void()>& draw) {
  recorder_.pauseSamples();
  draw();
  recorder_.resumeSamples();
}

void Frame::count(std::string_view name, std::uint64_t amount) {
  recorder_.count(name, amount);
}

void Frame::checkFailed(std::string what) {
  recorder_.checkFailed(std::move(what));
}

int OptionsChosen::value(std::string_view name) const {
  for (const Option& o : options)
    if (o.name == name) return o.value;
  throw std::logic_error("no option '" + std::string(name) + "'");
}

bool OptionsChosen::set(std::string_view name) const {
  return std::any_of(settings.begin(), settings.end(), [&](const auto& s) { return s.first == name; });
}

void Frame::progress(std::string_view what, std::size_t done, std::size_t total) const {
  if (progressSink_) progressSink_(what, done, total);
}

void Frame::shadowMask(std::string_view name) {
  if (name.empty() || name.find_first_of("/\\") != std::string_view::npos || name.front() == '.')
    throw std::logic_error("shadow mask name '" + std::string(name) + "' is not a plain file name");
  if (!shadowMaskWriter_) return;
  // The writer reads the framework's stencil; the lesson's read binding and pack alignment stay.
  GLint read = 0, packAlignment = 4;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
  shadowMaskWriter_(name);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
  glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
}

// ---- the frame's starting state --------------------------------------------------------

void resetFrameState(unsigned framebuffer, glm::ivec2 size, const GlFeatures& features) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glStencilMask(0xFF);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthFunc(GL_LESS);
  glClearDepth(1.0);
  if (hasFeature(features, Feature::ClipControl))
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);  // GL's default clip-space depth
}

Scene readScene(const CommandLine& cl, LessonInfo& info) {
  Scene scene;
  try {
    scene = loadScene(*cl.scene, cl.shadowHours.has_value());  // a profile may start or end at night
  } catch (const SceneError& e) {
    throw UsageError(e.what());
  }
  try {
    info.camera = orbitCameraOf(scene.camera);
  } catch (const std::invalid_argument& e) {
    throw UsageError(cl.scene->string() + ": " + e.what());
  }
  for (Variant& v : info.variants) v.camera.reset();
  if (!info.sceneLightOption.empty()) {
    for (Option& o : info.options)
      if (o.name == info.sceneLightOption) {
        o.min = 0;
        o.max = static_cast<int>(scene.lights.size()) - 1;
        o.value = std::min(o.value, o.max);
      }
    try {
      optionsFor(info, cl.variant, cl.settings);
    } catch (const UsageError& e) {
      throw UsageError(std::string(e.what()) + " (" + cl.scene->string() + " has " +
                       std::to_string(scene.lights.size()) +
                       (scene.lights.size() == 1 ? " light)" : " lights)"));
    }
  }
  return scene;
}

// What preparing the scene's casters did and found (welded seams, dropped triangles), a line each.
void sayWhatTheCastersNeeded(const CommandLine& cl, const Scene& scene) {
  if (cl.quiet) return;
  for (const SceneObject& o : scene.objects)
    for (const std::string& m : o.caster.report.messages)
      std::cerr << cl.scene->string() << ": object '" << o.name << "': " << m << "\n";
}

// ---- headless run -----------------------------------------------------------------------
// The browser runs a lesson its own way (web_run.cpp): a page, not a command line's files.
#ifndef __EMSCRIPTEN__

namespace {

// A time in milliseconds, kept to 4 decimals (llvmpipe's timings are noisier than that).
nlohmann::ordered_json milliseconds(const std::optional<double>& v) {
  if (!v) return nullptr;
  return std::round(*v * 1e4) / 1e4;
}
template <typename T>
nlohmann::ordered_json orNull(const std::optional<T>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json passJson(const PassStats& p) {
  nlohmann::ordered_json j = {{"name", p.name},
                              {"label", p.label},  // as the pass stepper names it: "shadows (light 2)"
                              {"draw_calls", p.drawCalls},
                              {"triangles", p.triangles},
                              {"samples_passed", orNull(p.samplesPassed)},
                              {"primitives_submitted", orNull(p.primitivesSubmitted)},
                              {"gpu_ms", milliseconds(p.gpuMs)}};
  if (!p.gpuMs && !p.gpuMsNullReason.empty()) j["gpu_ms_null_reason"] = p.gpuMsNullReason;
  j["cpu_ms"] = milliseconds(p.cpuMs);
  return j;
}

// The --stats document (README, "Every lesson takes the same flags"), keys in this order.
std::string statsJson(const Session& s, const std::vector<double>& frameMs) {
  const auto& passes = s.recorder->passStats();
  const GlFeatures& f = s.context->features();
  nlohmann::ordered_json out = {{"lesson", s.info.id},
                                {"variant", s.variant},
                                {"backend", backendName(s.context->backend())},
                                {"renderer", f.renderer},
                                {"size", {s.framebuffer->width(), s.framebuffer->height()}},
                                {"time", s.commandLine.time},
                                {"frames", frameMs.size()},
                                {"depth", depthFormatName(s.framebuffer->depthFormat()) +
                                              std::string(s.reversedDepth ? "-reversed" : "")},
                                {"features",
                                 {{"depth_bounds_test", f.depthBoundsTest},
                                  {"pipeline_statistics", f.pipelineStatistics},
                                  {"clip_control", f.clipControl},
                                  {"khr_debug", f.khrDebug},
                                  {"depth_clamp", f.depthClamp},
                                  {"stencil_export", f.stencilExport}}}};
  PassStats total;
  bool haveSamples = true, havePrims = true, haveGpu = true;
  nlohmann::ordered_json passList = nlohmann::ordered_json::array();
  for (const PassStats& p : passes) {
    passList.push_back(passJson(p));
    total.drawCalls += p.drawCalls;
    total.triangles += p.triangles;
    haveSamples &= p.samplesPassed.has_value();
    havePrims &= p.primitivesSubmitted.has_value();
    haveGpu &= p.gpuMs.has_value();
    total.samplesPassed = p.samplesPassed.value_or(0) + total.samplesPassed.value_or(0);
    total.primitivesSubmitted = p.primitivesSubmitted.value_or(0) + total.primitivesSubmitted.value_or(0);
    total.gpuMs = p.gpuMs.value_or(0) + total.gpuMs.value_or(0);
    total.cpuMs += p.cpuMs;
  }
  if (!haveSamples) total.samplesPassed.reset();
  if (!havePrims) total.primitivesSubmitted.reset();
  if (!haveGpu) {
    total.gpuMs.reset();
    total.gpuMsNullReason = "a pass's gpu_ms is null";
  }
  out["passes"] = passList;
  nlohmann::ordered_json totalJson = {{"passes", passes.size()}};
  const nlohmann::ordered_json totalFields = passJson(total);
  for (const auto& field : totalFields.items())
    if (field.key() != "name" && field.key() != "label") totalJson[field.key()] = field.value();
  out["total"] = totalJson;
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  for (const auto& [name, value] : s.recorder->counts()) counts[name] = value;
  out["counts"] = counts;
  // The first frame pays for shader compilation (llvmpipe compiles at first draw), so the
  // steady-state figures leave it out when there are more frames.
  const auto steadyBegin = frameMs.size() > 1 ? frameMs.begin() + 1 : frameMs.begin();
  const double mean =
      std::accumulate(steadyBegin, frameMs.end(), 0.0) / static_cast<double>(frameMs.end() - steadyBegin);
  std::vector<double> steady(steadyBegin, frameMs.end());
  std::sort(steady.begin(), steady.end());
  const std::size_t half = steady.size() / 2;
  const double median = steady.size() % 2 ? steady[half] : 0.5 * (steady[half - 1] + steady[half]);
  out["frame_ms"] = {{"first", milliseconds(frameMs.front())},
                     {"mean", milliseconds(mean)},
                     {"median", milliseconds(median)},
                     {"min", milliseconds(*std::min_element(steadyBegin, frameMs.end()))},
                     {"max", milliseconds(*std::max_element(steadyBegin, frameMs.end()))}};
  if (s.commandLine.statsFrames) {  // every frame, the first too, for a caller's own warm-up rule
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (double ms : frameMs) all.push_back(milliseconds(ms));
    out["frame_ms"]["all"] = all;
    nlohmann::ordered_json cpu = nlohmann::ordered_json::array();
    for (double ms : s.frameCpuMs) cpu.push_back(milliseconds(ms));
    out["frame_cpu_ms"] = {{"all", cpu}};
  }
  return out.dump(2) + "\n";
}

std::filesystem::path rawPathBeside(const std::filesystem::path& picture) {
  std::filesystem::path raw = picture;
  raw.replace_extension(".raw.png");
  return raw;
}

// --oracle's edges beside its picture: FILE.edges.png.
std::filesystem::path edgesPathBeside(const std::filesystem::path& picture) {
  std::filesystem::path edges = picture;
  edges.replace_extension(".edges.png");
  return edges;
}

// --oracle: the stencil's lit receivers against a CPU ray cast of the scene the lesson drew.
bool checkShadows(Session& s, const Image& stencil) {
  if (!s.shadowCheck)
    throw UsageError(s.info.id + " makes no shadow claim in variant '" + s.variant +
                     "' to check with --oracle");
  const ShadowCheck& check = *s.shadowCheck;
  const glm::ivec2 size{stencil.width, stencil.height};
  std::vector<int> surfaces;
  std::vector<bool> ties;
  const std::vector<PixelClass> oracle =
      classifyPixels(check.objects, check.light, s.viewProjection, size, check.lightRadius, &surfaces, &ties);
  std::vector<bool> lit(stencil.pixels.size());
  for (std::size_t i = 0; i < lit.size(); ++i) {
    const bool receiver = oracle[i] == PixelClass::Lit || oracle[i] == PixelClass::Shadowed;
    lit[i] = check.judgeReceiversOnly && !receiver ? false : check.litInStencil(stencil.pixels[i]);
  }
  const OracleReport r = compareWithOracle(oracle, lit, size, &surfaces, &ties);
  Image picture(size.x, size.y, 4);
  picture.pixels = oraclePicture(oracle, lit, size, &surfaces, &ties);
  s.outputs.addPng(*s.commandLine.oracle, picture);
  Image classes(size.x, size.y, 1);  // the oracle's classes as raw bytes (PixelClass), for tools
  for (std::size_t i = 0; i < oracle.size(); ++i) classes.pixels[i] = static_cast<std::uint8_t>(oracle[i]);
  s.outputs.addPng(rawPathBeside(*s.commandLine.oracle), classes);
  // Its edges, 255 where a disagreement is forgiven, for tools that judge another picture of the
  // same frame (tests/web/web_check.py: the browser's).
  Image edges(size.x, size.y, 1);
  const std::vector<bool> onEdges = oracleEdges(oracle, size, &surfaces, &ties);
  for (std::size_t i = 0; i < onEdges.size(); ++i) edges.pixels[i] = onEdges[i] ? 255 : 0;
  s.outputs.addPng(edgesPathBeside(*s.commandLine.oracle), edges);
  std::cerr << (r.passed() ? "oracle ok: " : "oracle FAILED: ") << r.receiverPixels << " receiver pixels, "
            << r.shadowedPixels << " shadowed; " << r.disagreements << " disagree, " << r.onEdges
            << " of them on edges (picture: " << s.commandLine.oracle->string() << ")\n";
  return r.passed();
}

// A picture flag's file: a PNG name that can be written, and its raw sibling when it has one.
void checkPictureOutput(const std::filesystem::path& path, const std::string& flag, bool rawBeside) {
  checkOutputFile(path, flag);
  if (path.extension() != ".png")
    throw OutputError(flag + " " + path.string() +
                      ": the file is written as PNG, so its name must end in .png");
  if (rawBeside) checkOutputFile(rawPathBeside(path), flag + " (raw values beside it)");
}

// The folder a failed golden comparison leaves its images in without --artifacts: in the current
// folder, per lesson, then per variant and backend (only the first part is known before a context).
std::filesystem::path defaultArtifactsRoot(const LessonInfo& info) {
  return std::filesystem::path("golden-artifacts") / info.id;
}

// One output file as a flag names it: the flag, and what is written (a picture or its raw sibling).
struct OutputFile {
  std::string flag;
  std::filesystem::path path;
};

// The file a path names, for telling whether two paths name one file: absolute, with the links
// of the part that exists resolved, lexically normal.
std::filesystem::path sameFileKey(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec).lexically_normal();
  if (ec) return path.lexically_normal();
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, ec);
  return ec ? absolute : canonical.lexically_normal();
}

// Refuses two outputs that would write one file: the later would replace the earlier.
void checkDistinctOutputs(const std::vector<OutputFile>& files) {
  std::vector<std::filesystem::path> keys;
  for (const OutputFile& f : files) keys.push_back(sameFileKey(f.path));
  for (std::size_t i = 0; i < files.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (keys[i] == keys[j])
        throw OutputError(files[j].flag + " " + files[j].path.string() + " and " + files[i].flag + " " +
                          files[i].path.string() + " are the same file");
}

// Every output the command line names, checked before a context is made or anything rendered:
// each can be written, and no two name one file. In compare mode --golden must be an existing
// folder, and the folder a failed comparison writes to (--artifacts, or the default one) must be
// one that can be made. Throws UsageError (OutputError for an output) for the first that fails.
void checkOutputs(const CommandLine& cl, const LessonInfo& info) {
  std::vector<OutputFile> files;
  if (cl.out) {
    checkPictureOutput(*cl.out, "--out", false);
    files.push_back({"--out", *cl.out});
  }
  if (cl.stencilOut) {
    checkPictureOutput(*cl.stencilOut, "--stencil-out", true);
    files.push_back({"--stencil-out", *cl.stencilOut});
    files.push_back({"--stencil-out's raw values", rawPathBeside(*cl.stencilOut)});
  }
  if (cl.depthOut) {
    checkPictureOutput(*cl.depthOut, "--depth-out", false);
    files.push_back({"--depth-out", *cl.depthOut});
  }
  if (cl.shadowHours) {
    checkPictureOutput(*cl.shadowHours, "--shadow-hours", true);
    files.push_back({"--shadow-hours", *cl.shadowHours});
    files.push_back({"--shadow-hours' raw counts", rawPathBeside(*cl.shadowHours)});
  }
  if (cl.oracle) {
    checkPictureOutput(*cl.oracle, "--oracle", true);
    checkOutputFile(edgesPathBeside(*cl.oracle), "--oracle (its edges beside it)");
    files.push_back({"--oracle", *cl.oracle});
    files.push_back({"--oracle's raw classes", rawPathBeside(*cl.oracle)});
    files.push_back({"--oracle's edges", edgesPathBeside(*cl.oracle)});
  }
  checkDistinctOutputs(files);
  // The output folders' own names: --passes NN-pass.png (and .stencil.png, .stencil.raw.png),
  // --mask-out light-<i>.png and step-HHMM.png. A file output that is such a folder, or would be
  // one of its files, is refused: one would replace the other.
  static const std::regex passNames("[0-9][0-9]-.*\\.png"), maskNames("(light-[0-9]+|step-[0-9]{4})\\.png");
  const auto checkFolder = [&](const std::optional<std::filesystem::path>& folder, const std::string& flag,
                               const std::regex& names) {
    if (!folder) return;
    const std::filesystem::path key = sameFileKey(*folder);
    for (const OutputFile& f : files) {
      const std::filesystem::path file = sameFileKey(f.path);
      if (file == key || (file.parent_path() == key && std::regex_match(file.filename().string(), names)))
        throw OutputError(f.flag + " " + f.path.string() + (file == key ? " is the " : " is a file of the ") +
                          flag + " folder " + folder->string());
    }
  };
  checkFolder(cl.passesDir, "--passes", passNames);
  checkFolder(cl.maskOut, "--mask-out", maskNames);
  if (cl.passesDir) checkOutputFolder(*cl.passesDir, "--passes");
  if (cl.maskOut) checkOutputFolder(*cl.maskOut, "--mask-out");
  if (cl.golden && cl.updateGolden) checkOutputFolder(*cl.golden, "--golden");
  if (cl.golden && !cl.updateGolden) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(*cl.golden, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_directory(status))
      throw UsageError("--golden " + cl.golden->string() + ": is a file; --golden takes the goldens' folder");
    if (!std::filesystem::is_directory(status))
      throw UsageError("--golden " + cl.golden->string() +
                       ": no such folder; --update-golden writes the goldens first");
    if (cl.artifacts)
      checkOutputFolder(*cl.artifacts, "--artifacts");
    else
      checkOutputFolder(defaultArtifactsRoot(info), "--golden's artifacts folder (no --artifacts)");
  } else if (cl.artifacts) {
    checkOutputFolder(*cl.artifacts, "--artifacts");
  }
}

Image stencilPicture(const CommandLine& cl, const Image& stencil) {
  return cl.stencilBitPlanes ? stencilBitPlanes(stencil) : stencilRamp(stencil);
}

int runHeadless(Session& s) {
  const CommandLine& cl = s.commandLine;
  const int frames = cl.frames.value_or(1);
  std::vector<double> frameMs;
  for (int i = 0; i < frames; ++i) {
    const bool last = i + 1 == frames;
    FrameRequest request{
        .measure = cl.stats && !cl.statsFrames, .captureAll = last && cl.passesDir.has_value(), .captureOnly = {}};
    s.saveShadowMasks = last;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    {
      const SlowWorkReporter reporter("frame " + std::to_string(i + 1) + " of " + std::to_string(frames) + " at " +
                                          std::to_string(cl.width) + "x" + std::to_string(cl.height),
                                      s.progress, cl.quiet);
      s.renderFrame(cl.time + i / 60.0, request);
      glFinish();
    }
    frameMs.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    s.frameCpuMs.push_back(1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
    if (frames > 1 && !cl.quiet && (i + 1) % 60 == 0) std::cerr << "frame " << i + 1 << "/" << frames << "\n";
  }
  return finishRun(s, s.framebuffer->readColour(), s.framebuffer->readStencil(), frameMs);
}

// --shadow-hours: the scene's (first) sun light moved through the span, the lesson made anew with
// the sun where it stands at each step and one frame rendered; the sun's shadow mask (the stencil
// once its shadow is in it: Frame::shadowMask("light-<i>")) counted per pixel. A step with the sun
// at or below the horizon is night: the sun casts no shadow then, and night is not shadow, so it
// adds to no pixel's count (its --mask-out mask is all lit) and is counted apart, on stderr; the
// legend's ramp runs over the daylight steps. Wallner's shadow profile, section 8.
int runShadowHours(Session& s, Scene& scene, const LessonFactory& make) {
  const CommandLine& cl = s.commandLine;
  std::size_t sunIndex = scene.lights.size();
  for (std::size_t i = 0; i < scene.lights.size() && sunIndex == scene.lights.size(); ++i)
    if (scene.lights[i].sun) sunIndex = i;
  const SunLight sun = *scene.lights[sunIndex].sun;
  const std::string maskName = "light-" + std::to_string(sunIndex);
  const int width = s.framebuffer->width(), height = s.framebuffer->height();
  std::vector<std::uint16_t> counts(static_cast<std::size_t>(width) * height, 0);
  const auto at = [&](int minutes) {
    CivilTime time = sun.time;
    time.hour = minutes / 60;
    time.minute = minutes % 60;
    time.second = 0.0;
    return time;
  };
  bool daylight = false;  // a profile with no daylight step is refused before anything is written
  for (int minutes = cl.shadowFrom; minutes <= cl.shadowTo && !daylight; minutes += cl.shadowStep)
    daylight = sunPosition(sun.place, at(minutes)).elevationDeg > 0.0;
  if (!daylight) {
    char span[64];
    std::snprintf(span, sizeof span, "%02d:%02d-%02d:%02d", cl.shadowFrom / 60, cl.shadowFrom % 60,
                  cl.shadowTo / 60, cl.shadowTo % 60);
    throw UsageError("--shadow-hours: the sun is down at every step of " + std::string(span) +
                     " on the scene's date: no sun shadow to profile");
  }
  int steps = 0, nightSteps = 0;
  double totalMs = 0.0;
  for (int minutes = cl.shadowFrom; minutes <= cl.shadowTo; minutes += cl.shadowStep, ++steps) {
    const CivilTime time = at(minutes);
    char clock[24];
    std::snprintf(clock, sizeof clock, "%02d%02d", time.hour, time.minute);
    const SunPosition p = sunPosition(sun.place, time);
    Image mask(width, height, 1);  // 255 lit, 0 in shadow, as --mask-out writes them
    std::fill(mask.pixels.begin(), mask.pixels.end(), std::uint8_t{255});  // night: no sun shadow
    double ms = 0.0;
    const bool night = p.elevationDeg <= 0.0;
    nightSteps += night ? 1 : 0;
    if (!night) {
      scene.lights[sunIndex].position = glm::vec4(sunDirection(p.elevationDeg, p.azimuthDeg), 0.0f);
      s.lesson = make();
      bool seen = false;
      s.shadowMaskHook = [&](std::string_view name) {
        if (name != maskName) return;
        const Image stencil = s.framebuffer->readStencil();
        for (std::size_t i = 0; i < mask.pixels.size(); ++i)
          mask.pixels[i] = stencil.pixels[i] == 0 ? 255 : 0;
        seen = true;
      };
      const auto start = std::chrono::steady_clock::now();
      s.renderFrame(cl.time, FrameRequest{});
      glFinish();
      ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      s.shadowMaskHook = nullptr;
      if (!seen) throw std::runtime_error(s.info.id + " drew no shadow mask for the sun (" + maskName + ")");
    }
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
      if (mask.pixels[i] == 0) {
        ++counts[i];
        ++shadowed;
      }
    if (cl.maskOut) s.outputs.addPng(*cl.maskOut / ("step-" + std::string(clock) + ".png"), mask);
    totalMs += ms;
    if (!cl.quiet) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "shadow-hours %02d:%02d: sun elevation %.2f, azimuth %.2f degrees; %zu of %zu pixels in "
                    "shadow; frame %.1f ms%s\n",
                    time.hour, time.minute, p.elevationDeg, p.azimuthDeg, shadowed, counts.size(), ms,
                    night ? " (night: the sun is down, no sun shadow; not counted as shadow)" : "");
      std::cerr << line;
    }
  }
  s.outputs.addPng(*cl.shadowHours, shadowHoursPicture(counts, width, height, steps - nightSteps, cl.shadowStep));
  Image raw(width, height, 1);
  for (std::size_t i = 0; i < counts.size(); ++i) raw.pixels[i] = static_cast<std::uint8_t>(counts[i]);
  s.outputs.addPng(rawPathBeside(*cl.shadowHours), raw);
  s.outputs.commit();
  if (!cl.quiet)
    std::cerr << "shadow-hours: " << steps << (steps == 1 ? " step of " : " steps of ") << cl.shadowStep
              << " min, " << nightSteps << " of them at night (the sun down: no sun shadow, not counted), "
              << (steps > nightSteps ? totalMs / (steps - nightSteps) : 0.0)
              << " ms a daylight frame on average; " << cl.shadowHours->string()
              << " and its raw counts written\n";
  return 0;
}

}  // namespace

int finishRun(Session& s, const Image& colour, const Image& stencil, const std::vector<double>& frameMs) {
  const CommandLine& cl = s.commandLine;
  if (cl.out) s.outputs.addPng(*cl.out, colour);
  if (cl.stencilOut) {
    s.outputs.addPng(*cl.stencilOut, stencilPicture(cl, stencil));
    s.outputs.addPng(rawPathBeside(*cl.stencilOut), stencil);
  }
  if (cl.depthOut) {
    DepthRange range;
    s.outputs.addPng(*cl.depthOut, depthPicture(s.framebuffer->readDepth(), s.framebuffer->width(),
                                                s.framebuffer->height(), s.projection, s.reversedDepth, &range));
    if (!cl.quiet) std::cerr << depthLegendLine(range) << "\n";
  }
  if (cl.passesDir) {
    int index = 1;
    for (const Snapshot& snap : s.recorder->snapshots()) {
      char prefix[16];
      std::snprintf(prefix, sizeof prefix, "%02d-", index++);
      s.outputs.addPng(*cl.passesDir / (prefix + snap.pass + ".png"), snap.colour);
      s.outputs.addPng(*cl.passesDir / (prefix + snap.pass + ".stencil.png"), stencilPicture(cl, snap.stencil));
    }
  }
  // The oracle's pictures belong to the set: a check that throws leaves nothing written.
  const bool shadowsRight = !cl.oracle || checkShadows(s, stencil);
  bool goldenCompared = false;
  if (cl.golden) {
    const std::string& renderer = s.context->features().renderer;
    if (!isGoldenRenderer(renderer)) {
      const std::string why =
          "the goldens are Mesa llvmpipe's pictures and this context is " + renderer +
          " (LIBGL_ALWAYS_SOFTWARE=1 picks llvmpipe; ctest -L oracle checks this renderer)";
      if (cl.updateGolden) throw UsageError("--update-golden: " + why);
      s.outputs.commit();
      std::cerr << "golden skipped: " << why << "\n";
      return 77;  // ctest's SKIP_RETURN_CODE for the golden tests
    }
    if (cl.updateGolden) writeGolden(colour, stencil, *cl.golden, s.variant, s.outputs);
    goldenCompared = !cl.updateGolden;
  }
  s.outputs.commit();
  if (cl.stats && !frameMs.empty()) std::cout << statsJson(s, frameMs);
  if (cl.golden && cl.updateGolden)
    std::cerr << "wrote " << goldenColourPath(*cl.golden, s.variant).string() << " and "
              << goldenStencilPath(*cl.golden, s.variant).string() << "\n";
  if (!shadowsRight) return 1;
  for (const std::string& what : s.recorder->failedChecks()) std::cerr << what << "\n";
  if (!s.recorder->failedChecks().empty()) return 1;
  if (!goldenCompared) return 0;
  // A failed comparison's artifacts are a set of their own: the test has failed (exit 1) whether
  // or not they can be written, and the line says which.
  const auto artifacts = cl.artifacts.value_or(defaultArtifactsRoot(s.info) /
                                               (s.variant + "-" + backendName(s.context->backend())));
  OutputSet artifactFiles;
  const GoldenResult result = checkGolden(colour, stencil, *cl.golden, s.variant, artifacts, artifactFiles);
  std::string unwritten;
  try {
    artifactFiles.commit();
  } catch (const OutputError& e) {
    unwritten = std::string(" (its images were not written: ") + e.what() + ")";
  }
  std::cerr << (result.passed ? "golden ok: " : "golden FAILED: ") << result.message << unwritten << "\n";
  return result.passed ? 0 : 1;
}

namespace {

int runProgram(const LessonInfo& lessonInfo, const SceneLessonFactory& factory, bool readsScenes, int argc,
               char** argv) {
  const std::string program = std::filesystem::path(argv[0]).filename().string();
  keepFreedHeap();
  try {
    const CommandLine cl = parseCommandLine(lessonInfo, argc, argv);
    if (!readsScenes && (cl.scene || cl.maskOut))
      throw UsageError(std::string(cl.scene ? "--scene" : "--mask-out") + ": " + lessonInfo.id +
                       " draws only its own scene; the scene lessons read scene files");
    if (cl.shadowHours && (!readsScenes || !lessonInfo.shadows))
      throw UsageError("--shadow-hours: " + lessonInfo.id + " does not draw scene files' shadows");
    if (cl.shadowHours && !cl.scene)
      throw UsageError("--shadow-hours needs --scene FILE with a sun light (light sun ...)");
    if (cl.shadowHours && cl.oracle)
      throw UsageError("--shadow-hours and --oracle: check the steps with --mask-out");
    if (!lessonInfo.shadows && (cl.oracle || cl.maskOut))
      throw UsageError(std::string(cl.oracle ? "--oracle" : "--mask-out") + ": " + lessonInfo.id +
                       " makes no shadow claim to check or save");
    if (cl.help) {
      std::cout << helpText(lessonInfo, program, readsScenes);
      return 0;
    }
    if (cl.listVariants) {
      std::cout << variantList(lessonInfo);
      return 0;
    }
    checkOutputs(cl, lessonInfo);
    LessonInfo info = lessonInfo;
    std::optional<Scene> scene;
    if (cl.scene) scene = readScene(cl, info);
    if (cl.shadowHours && std::none_of(scene->lights.begin(), scene->lights.end(),
                                       [](const SceneLight& l) { return l.sun.has_value(); }))
      throw UsageError("--shadow-hours: " + cl.scene->string() +
                       " has no sun light (light sun LAT LON DATE TIME ZONE)");
    if (info.refuseOptions) {
      const std::vector<Option> options = optionsFor(info, cl.variant, cl.settings);
      const std::string why = info.refuseOptions({options, cl.settings, scene ? &*scene : nullptr});
      if (!why.empty()) throw UsageError(why);
    }
    if (scene) sayWhatTheCastersNeeded(cl, *scene);
    const LessonFactory make = [&] { return factory(scene ? &*scene : nullptr); };
    setShaderDirFlag(cl.shaderDir);
    BackendChoice choice = chooseBackend(cl.backend, cl.headless || cl.shadowHours.has_value());
    // A window's picture smaller than this cannot be looked at, nor the panel laid out beside it; a
    // --frames run (a golden test: the picture alone) and a headless one take any --size.
    if (choice.backend == Backend::Window && !cl.frames && (cl.width < kMinWindowWidth || cl.height < kMinWindowHeight))
      throw UsageError("--size " + std::to_string(cl.width) + "x" + std::to_string(cl.height) +
                       " is too small for the window: its picture needs at least " + std::to_string(kMinWindowWidth) +
                       "x" + std::to_string(kMinWindowHeight));
    std::unique_ptr<Session> session;
    while (!session) {
      try {
        session = std::make_unique<Session>(info, make, cl, choice.backend);
        session->scene = scene ? &*scene : nullptr;
      } catch (const NoContextError& e) {
        // The automatic choice falls back from a display with no window to headless, and from
        // OSMesa to EGL; a backend given with --backend has no fallback.
        if (cl.backend || choice.backend == Backend::Egl) throw;
        choice = choice.backend == Backend::Window
                     ? headlessBackend(std::string("no window on the display (") + e.what() + ")")
                     : BackendChoice{Backend::Egl, std::string("OSMesa failed (") + e.what() + ")"};
      }
    }
    if (!cl.quiet) {
      const GlFeatures& f = session->context->features();
      std::cerr << "backend: " << backendName(choice.backend) << " (" << choice.reason << "); " << f.renderer
                << ", GL " << f.major << "." << f.minor << "; " << f.summary() << "\n";
    }
    if (cl.shadowHours) return runShadowHours(*session, *scene, make);
    if (choice.backend != Backend::Window) return runHeadless(*session);
    const int code = runWindow(*session);
    const std::optional<std::filesystem::path> next = session->nextLesson;
    const std::vector<std::string> windowFlags = session->nextLessonFlags;
    session.reset();  // the window closes before the next lesson opens its own
    if (next) {
      // The next lesson in the window as this one left it (size, place, UI scale, view, panel);
      // --quiet carries over.
      const std::string exe = next->string();
      std::vector<std::string> args = {exe, "--backend", "window"};
      args.insert(args.end(), windowFlags.begin(), windowFlags.end());
      if (cl.quiet) args.push_back("--quiet");
      std::vector<char*> argvNext;
      for (std::string& a : args) argvNext.push_back(a.data());
      argvNext.push_back(nullptr);
      execv(exe.c_str(), argvNext.data());
      throw std::runtime_error("cannot start " + exe + ": " + std::strerror(errno));
    }
    return code;
  } catch (const UsageError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 2;
  } catch (const NoContextError& e) {
    std::cerr << program << ": no OpenGL context: " << e.what() << "\n";
    return 77;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

int runLesson(const LessonInfo& info, const LessonFactory& factory, int argc, char** argv) {
  return runProgram(
      info, [&](const Scene*) { return factory(); }, false, argc, argv);
}

int runSceneLesson(const LessonInfo& info, const SceneLessonFactory& factory, int argc, char** argv) {
  return runProgram(info, factory, true, argc, argv);
}

#endif  // __EMSCRIPTEN__

}  // namespace stencil
