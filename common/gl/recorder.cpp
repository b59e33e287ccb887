#include "gl/recorder.h"

#include <algorithm>
#include <stdexcept>

#include "gl/debug.h"
#include "gl/gl.h"

namespace stencil {
namespace {

PassStats* counting = nullptr;  // the pass draws are counted into

std::uint64_t queryResult(unsigned query) {
  GLuint64 value = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &value);
  return value;
}

// Whether a snapshot can read colour, depth and stencil from `framebuffer` (a GL name; 0, the
// window's, never: the lesson draws off screen). Binds it for reading; the caller restores.
bool readableWhole(GLuint framebuffer) {
  if (framebuffer == 0) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  if (glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return false;
  GLint readBuffer = GL_NONE;
  glGetIntegerv(GL_READ_BUFFER, &readBuffer);
  if (readBuffer == GL_NONE) return false;
  const auto attached = [](GLenum attachment) {
    GLint type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    return type != GL_NONE;
  };
  return attached(static_cast<GLenum>(readBuffer)) && attached(GL_DEPTH_ATTACHMENT) &&
         attached(GL_STENCIL_ATTACHMENT);
}

}  // namespace

void countDraw(std::uint64_t triangles) {
  if (!counting) return;
  counting->drawCalls += 1;
  counting->triangles += triangles;
}

PassRecorder::PassRecorder(std::vector<std::string> declaredPasses, const Framebuffer& framebuffer,
                           const GlFeatures& features)
    : declared_(std::move(declaredPasses)),
      framebuffer_(framebuffer),
      pipelineStatistics_(features.pipelineStatistics) {
  GLint bits = 0;
  if (features.timerQuery) glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  timerCounts_ = bits > 0;
  // Mesa binds a framebuffer in the driver only at the first clear or draw into it. A timer query
  // begun before the driver has any framebuffer is binned into no tile, so it never records its
  // start, and llvmpipe then reports the end timestamp alone: the time since boot. Clearing the
  // new framebuffer once binds it before any query begins.
  framebuffer_.bind();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

PassRecorder::~PassRecorder() {
  for (auto& q : queries_) {
    glDeleteQueries(1, &q.samples);
    glDeleteQueries(1, &q.time);
    if (q.primitives) glDeleteQueries(1, &q.primitives);
  }
  counting = nullptr;
}

void PassRecorder::beginFrame(FrameRequest request) {
  request_ = request;
  stats_.clear();
  snapshots_.clear();
  counts_.clear();
  failedChecks_.clear();
  pausedSamples_.clear();
  checkGlErrors("before the frame");
  beginPass();
}

void PassRecorder::beginPass() {
  current_ = PassStats{};
  currentPaused_ = 0;
  counting = &current_;
  if (request_.measure) {
    if (queries_.size() <= stats_.size()) {
      Queries q;
      glGenQueries(1, &q.samples);
      glGenQueries(1, &q.time);
      if (pipelineStatistics_) glGenQueries(1, &q.primitives);
      queries_.push_back(q);
    }
    const Queries& q = queries_[stats_.size()];
    glBeginQuery(GL_SAMPLES_PASSED, q.samples);
    glBeginQuery(GL_TIME_ELAPSED, q.time);
    if (q.primitives) glBeginQuery(GL_PRIMITIVES_SUBMITTED_ARB, q.primitives);
  }
  passStart_ = std::chrono::steady_clock::now();
}

void PassRecorder::pass(std::string_view name, std::string_view detail) {
  if (std::find(declared_.begin(), declared_.end(), name) == declared_.end())
    throw std::logic_error("pass '" + std::string(name) + "' is not declared by the lesson");
  current_.name = name;
  current_.detail = detail;
  current_.label = current_.name;  // endFrame numbers the repeats
  if (request_.measure) {
    const Queries& q = queries_[stats_.size()];
    glEndQuery(GL_SAMPLES_PASSED);
    glEndQuery(GL_TIME_ELAPSED);
    if (q.primitives) glEndQuery(GL_PRIMITIVES_SUBMITTED_ARB);
    glFinish();  // so the CPU time includes the GPU work it issued
  }
  current_.cpuMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - passStart_).count();
  checkGlErrors("in pass '" + current_.name + "'");
  const std::size_t index = stats_.size();
  stats_.push_back(current_);
  pausedSamples_.push_back(currentPaused_);
  if (request_.captureAll || request_.captureOnly == index) {
    // What the lesson has bound is put back afterwards: reading binds the read framebuffer and
    // sets the pack alignment, and nothing here touches the draw binding or the viewport.
    GLint draw = 0, read = 0, packAlignment = 4;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
    const GLuint source =
        readableWhole(static_cast<GLuint>(draw)) ? static_cast<GLuint>(draw) : framebuffer_.id();
    const int w = framebuffer_.width(), h = framebuffer_.height();
    snapshots_.push_back({.pass = current_.name,
                          .label = current_.label,
                          .index = index,
                          .framebuffer = source,
                          .colour = readColourPixels(source, w, h),
                          .stencil = readStencilPixels(source, w, h),
                          .depth = readDepthPixels(source, w, h)});
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
    checkGlErrors("while reading the snapshot of pass '" + current_.name + "'");
  }
  beginPass();
}

void PassRecorder::labelPasses() {
  for (PassStats& p : stats_) {
    if (!p.detail.empty()) {
      p.label = p.name + " (" + p.detail + ")";
      continue;
    }
    const auto sameName = [&](const PassStats& q) { return q.name == p.name && q.detail.empty(); };
    if (std::count_if(stats_.begin(), stats_.end(), sameName) < 2) continue;
    const auto before = std::count_if(stats_.data(), &p, sameName);
    p.label = p.name + " #" + std::to_string(before + 1);
  }
  for (Snapshot& s : snapshots_) s.label = stats_[s.index].label;
}

void PassRecorder::pauseSamples() {
  if (!request_.measure) return;
  const unsigned query = queries_[stats_.size()].samples;
  glEndQuery(GL_SAMPLES_PASSED);
  currentPaused_ += queryResult(query);
}

void PassRecorder::resumeSamples() {
  if (!request_.measure) return;
  glBeginQuery(GL_SAMPLES_PASSED, queries_[stats_.size()].samples);
}

void PassRecorder::count(std::string_view name, std::uint64_t amount) {
  for (auto& [n, value] : counts_)
    if (n == name) {
      value += amount;
      return;
    }
  counts_.emplace_back(name, amount);
}

void PassRecorder::endFrame() {
  if (request_.measure) {
    glEndQuery(GL_SAMPLES_PASSED);
    glEndQuery(GL_TIME_ELAPSED);
    if (pipelineStatistics_) glEndQuery(GL_PRIMITIVES_SUBMITTED_ARB);
  }
  counting = nullptr;
  if (current_.drawCalls > 0)
    throw std::logic_error("draw calls after the last named pass: mark it with frame.pass()");
  checkGlErrors("at the end of the frame");
  labelPasses();
  if (!request_.measure) return;
  for (std::size_t i = 0; i < stats_.size(); ++i) {
    stats_[i].samplesPassed = queryResult(queries_[i].samples) + pausedSamples_[i];
    const double gpuMs = static_cast<double>(queryResult(queries_[i].time)) / 1e6;
    // The pass's CPU time runs from before its query began to after glFinish: no GPU time fits
    // in it that is longer.
    if (!timerCounts_)
      stats_[i].gpuMsNullReason = "the driver's timer query has no counter bits (GL_QUERY_COUNTER_BITS is 0)";
    else if (gpuMs > stats_[i].cpuMs)
      stats_[i].gpuMsNullReason =
          "the timer query measured " + std::to_string(gpuMs) + " ms, longer than the pass's CPU wall time";
    else
      stats_[i].gpuMs = gpuMs;
    if (queries_[i].primitives) stats_[i].primitivesSubmitted = queryResult(queries_[i].primitives);
  }
}

}  // namespace stencil
