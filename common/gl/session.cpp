// Session (session.h): one run of a lesson, shared by the headless and the window paths; and
// the course's lesson programs.
#include "gl/session.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "gl/debug.h"
#include "gl/errors.h"
#include "gl/gl.h"

namespace stencil {

Session::Session(const LessonInfo& lessonInfo, const LessonFactory& factory, const CommandLine& cl,
                 Backend backend)
    : info(lessonInfo), commandLine(cl), camera(lessonInfo.camera) {
  // The panel beside the picture, at --ui-scale (the window fits it to the monitor's scale after).
  const int panel = backend == Backend::Window && !cl.frames && !cl.panelHidden
                        ? static_cast<int>(std::lround(kWindowPanelWidth * cl.uiScale.value_or(1.0f)))
                        : 0;
  context = createContext(backend, cl.width + panel, cl.height, info.id + ": " + info.title);
  enableDebugOutput(context->features());
  checkNeeds(info.needs, "lesson " + info.id);
  setVariant(cl.variant.empty() ? info.variants.front().name : cl.variant, cl.settings);
  makeFramebuffer(cl.width, cl.height);
  lesson = factory();
  checkGlErrors("while the lesson set up");
}

void Session::checkNeeds(const std::vector<Feature>& needs, const std::string& who) const {
  for (Feature f : needs)
    if (!hasFeature(context->features(), f))
      throw UsageError(who + " needs " + featureName(f) + ", which " + context->features().renderer +
                       " does not offer");
}

void Session::setVariant(const std::string& name, const std::vector<std::pair<std::string, int>>& settings) {
  checkNeeds(findVariant(info, name).needs, "variant '" + name + "'");
  options = optionsFor(info, name, settings);
  variant = name;
  camera = findVariant(info, name).camera.value_or(info.camera);
  const bool wanted = findVariant(info, name).reversedDepth.value_or(info.reversedDepth);
  const bool canClip = hasFeature(context->features(), Feature::ClipControl);
  if (wanted && !canClip && !commandLine.quiet && !toldNoClipControl_) {
    std::cerr << info.id << ": " << context->features().renderer
              << " has no ARB_clip_control: reversed float depth is off, the 24-bit depth buffer with "
                 "GL's mapping instead\n";
    toldNoClipControl_ = true;
  }
  reversedDepth = wanted && canClip;
  // A variant with another depth format gets a framebuffer of that format (the window switches).
  if (framebuffer && framebuffer->depthFormat() != depthFormat())
    makeFramebuffer(framebuffer->width(), framebuffer->height());
}

DepthFormat Session::depthFormat() const {
  return reversedDepth ? DepthFormat::Float32 : DepthFormat::Fixed24;
}

void Session::makeFramebuffer(int width, int height) {
  recorder.reset();
  framebuffer = std::make_unique<Framebuffer>(width, height, commandLine.stencilBits, depthFormat());
  if (framebuffer->stencilBits() < info.stencilBits)
    throw UsageError("the framebuffer has " + std::to_string(framebuffer->stencilBits()) + " stencil bits; " +
                     info.id + " needs " + std::to_string(info.stencilBits));
  recorder = std::make_unique<PassRecorder>(info.passes, *framebuffer, context->features());
}

void Session::resize(int width, int height) {
  makeFramebuffer(width, height);
}

// LessonInfo::refuseOptions as the command line applies it, with the options away from the
// variant's values as the settings given: a change the window or the page makes that the command
// line would refuse (lesson 14's own scenes picked while a scene file is drawn) is refused too.
void Session::refuseChosenOptions() {
  if (!info.refuseOptions || (accepted_ && accepted_->first == variant && accepted_->second == options)) return;
  const auto settings = settingsAwayFromVariant(info, variant, options);
  if (const std::string why = info.refuseOptions({options, settings, scene}); !why.empty()) throw UsageError(why);
  accepted_.emplace(variant, options);
}

void Session::renderFrame(double time, FrameRequest request) {
  refuseChosenOptions();
  const glm::ivec2 size{framebuffer->width(), framebuffer->height()};
  resetFrameState(framebuffer->id(), size, context->features());
  recorder->beginFrame(request);
  Frame frame(time, size, camera, options, *recorder, context->features(), reversedDepth, framebuffer->id());
  if (shadowMaskHook)
    frame.setShadowMaskWriter(shadowMaskHook);
  else if (commandLine.maskOut && saveShadowMasks)
    frame.setShadowMaskWriter([this](std::string_view name) {
      const Image stencil = framebuffer->readStencil();
      Image mask(stencil.width, stencil.height, 1);
      for (std::size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = stencil.pixels[i] == 0 ? 255 : 0;
      outputs.addPng(*commandLine.maskOut / (std::string(name) + ".png"), mask);
    });
  progress.clear();
  frame.setProgressSink(
      [this](std::string_view what, std::size_t done, std::size_t total) { progress.set(what, done, total); });
  frame.pointer = pointer;
  frame.uiScale = uiScale;
  lesson->render(frame);
  recorder->endFrame();
  viewProjection = frame.projection * frame.view;
  projection = frame.projection;
  if (commandLine.oracle) shadowCheck = lesson->shadowCheck(frame);
}

void WorkProgress::set(std::string_view what, std::size_t done, std::size_t total) {
  const std::lock_guard lock(mutex_);
  what_ = what;
  done_ = done;
  total_ = total;
}

std::string WorkProgress::line() const {
  const std::lock_guard lock(mutex_);
  if (what_.empty() || total_ == 0) return {};
  return "; " + std::to_string(done_) + " of " + std::to_string(total_) + " " + what_ + " (" +
         std::to_string(done_ * 100 / total_) + "%)";
}

void WorkProgress::clear() {
  const std::lock_guard lock(mutex_);
  what_.clear();
  done_ = total_ = 0;
}

SlowWorkReporter::SlowWorkReporter(std::string what, const WorkProgress& progress, bool quiet) {
  if (quiet) return;
  thread_ = std::thread([this, what = std::move(what), &progress] {
    const auto start = std::chrono::steady_clock::now();
    auto next = start + std::chrono::seconds(5);
    std::unique_lock lock(mutex_);
    while (!stop_.wait_until(lock, next, [this] { return stopping_; })) {
      const auto seconds =
          std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start).count();
      std::cerr << what << ": still rendering, " << seconds << " s" << progress.line() << "\n";
      next += std::chrono::seconds(10);
    }
  });
}

SlowWorkReporter::~SlowWorkReporter() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_one();
  thread_.join();
}

std::vector<std::filesystem::path> courseLessons() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  static const std::regex kLessonName("[0-9][0-9]-[a-z0-9-]+");
  std::vector<std::filesystem::path> lessons;
  for (const auto& entry : std::filesystem::directory_iterator(self.parent_path(), ec))
    if (entry.is_regular_file(ec) && std::regex_match(entry.path().filename().string(), kLessonName) &&
        access(entry.path().c_str(), X_OK) == 0)
      lessons.push_back(entry.path());
  std::sort(lessons.begin(), lessons.end());
  return lessons;
}

}  // namespace stencil
