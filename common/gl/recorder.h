// The pass recorder: a lesson marks the end of each named pass; the recorder counts draw
// calls and triangles, runs occlusion/timer/statistics queries around each pass for
// --stats, checks for GL errors, and captures colour, depth and stencil after the passes
// asked for, from the framebuffer the pass drew into. Tests, docs figures and the window's
// pass stepping all use this one mechanism. It never changes a binding the lesson made.
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gl/context.h"
#include "gl/framebuffer.h"
#include "gl/image.h"

namespace stencil {

struct PassStats {
  std::string name;  // as declared (LessonInfo::passes)
  // The pass as it ran: the name with the detail the lesson gave (Frame::pass), "shadows (light 2)";
  // a name the frame repeats without details is numbered, "reflection #2"; else the name alone.
  std::string label;
  std::string detail;
  std::uint64_t drawCalls = 0;
  std::uint64_t triangles = 0;                       // counted on the CPU at each draw
  std::optional<std::uint64_t> samplesPassed;        // occlusion query: fragments that passed
  std::optional<std::uint64_t> primitivesSubmitted;  // ARB_pipeline_statistics_query, if present
  std::optional<double> gpuMs;                       // timer query; empty when it cannot be right
  std::string gpuMsNullReason;                       // why gpuMs is empty, when it was measured
  double cpuMs = 0;
};

struct Snapshot {
  std::string pass;     // the declared name
  std::string label;    // PassStats::label
  std::size_t index{};  // the pass's index in the frame
  // The framebuffer it was read from (a GL name): the one bound for drawing when the pass ended,
  // or the framework's where that one could not be read (PassRecorder::pass).
  unsigned framebuffer = 0;
  Image colour, stencil;
  std::vector<float> depth;  // window depths, top row first (Framebuffer::readDepth)
};

struct FrameRequest {
  bool measure = false;                    // run queries (costs a little)
  bool captureAll = false;                 // a snapshot after every pass
  std::optional<std::size_t> captureOnly;  // a snapshot after the pass with this index only
};

class PassRecorder {
 public:
  PassRecorder(std::vector<std::string> declaredPasses, const Framebuffer&, const GlFeatures&);
  ~PassRecorder();

  void beginFrame(FrameRequest);
  // The end of a named pass; detail (optional) says which of its repeats it was ("light 2").
  // A snapshot, when the frame asks for one, is read from the framebuffer bound for drawing now
  // if it can be read whole (complete, a read buffer with a colour attachment, a depth and a
  // stencil attachment), at the framework framebuffer's size; otherwise from the framework's.
  // The draw and read framebuffer bindings, the viewport and GL_PACK_ALIGNMENT are left as they
  // were found.
  void pass(std::string_view name, std::string_view detail = {});
  void count(std::string_view name, std::uint64_t amount);  // a lesson's own count (Frame::count)
  void checkFailed(std::string what) { failedChecks_.push_back(std::move(what)); }  // Frame::checkFailed
  // Ends the current pass's occlusion query early, keeping what it counted so far, and begins it
  // again: between the two the lesson may run its own (Frame::ownOcclusionQueries). No-ops
  // unless the frame is measured.
  void pauseSamples();
  void resumeSamples();
  void endFrame();  // labels the passes that ran and reads the queries back

  const std::vector<std::string>& declaredPasses() const { return declared_; }
  const std::vector<PassStats>& passStats() const { return stats_; }  // last frame
  const std::vector<Snapshot>& snapshots() const { return snapshots_; }
  // The lesson's own counts in the last frame, in the order first counted.
  const std::vector<std::pair<std::string, std::uint64_t>>& counts() const { return counts_; }
  // The lesson's own checks that failed in the last frame (Frame::checkFailed), a line each.
  const std::vector<std::string>& failedChecks() const { return failedChecks_; }

 private:
  void beginPass();
  void labelPasses();
  struct Queries {
    unsigned samples = 0, time = 0, primitives = 0;
  };

  std::vector<std::string> declared_;
  const Framebuffer& framebuffer_;
  bool pipelineStatistics_;
  bool timerCounts_ = false;  // the driver's timer query has counter bits: it can time
  FrameRequest request_;
  std::vector<PassStats> stats_;
  std::vector<Queries> queries_;              // one set per pass of the frame, reused across frames
  std::vector<std::uint64_t> pausedSamples_;  // per pass: counted before its query was paused
  std::uint64_t currentPaused_ = 0;
  std::vector<Snapshot> snapshots_;
  std::vector<std::pair<std::string, std::uint64_t>> counts_;
  std::vector<std::string> failedChecks_;
  PassStats current_;
  std::chrono::steady_clock::time_point passStart_;
};

// Called by every counted draw (GpuMesh::draw).
void countDraw(std::uint64_t triangles);

}  // namespace stencil
