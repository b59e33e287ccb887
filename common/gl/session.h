// Everything one run of a lesson holds, shared by the headless and the window paths.
#pragma once
#include <filesystem>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "gl/context.h"
#include "gl/framebuffer.h"
#include "gl/image.h"
#include "gl/lesson.h"
#include "gl/options.h"
#include "gl/recorder.h"

namespace stencil {

// How far long work in the current frame has come (Frame::progress), and the "still rendering"
// lines a headless run prints while a frame takes long: the first after 5 s, then every 10 s, so
// that no long run is silent ("frame 1 of 1 at 640x480: still rendering, 15 s; 122880 of 307200
// pixels ray cast (40%)"). Thread-safe.
class WorkProgress {
 public:
  void set(std::string_view what, std::size_t done, std::size_t total);
  std::string line() const;  // "; DONE of TOTAL WHAT (P%)" or empty
  void clear();

 private:
  mutable std::mutex mutex_;
  std::string what_;
  std::size_t done_ = 0, total_ = 0;
};

// While it lives, a thread prints WHAT's "still rendering" lines on stderr (unless quiet).
class SlowWorkReporter {
 public:
  SlowWorkReporter(std::string what, const WorkProgress&, bool quiet);
  ~SlowWorkReporter();
  SlowWorkReporter(const SlowWorkReporter&) = delete;
  SlowWorkReporter& operator=(const SlowWorkReporter&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

class Session {
 public:
  // Makes the context, checks the lesson's needs, builds and verifies the framebuffer,
  // then constructs the lesson.
  Session(const LessonInfo&, const LessonFactory&, const CommandLine&, Backend);

  // Resets the options to the variant's, then applies `settings` (--set) on top.
  void setVariant(const std::string& name, const std::vector<std::pair<std::string, int>>& settings = {});
  void resize(int width, int height);  // a new framebuffer (the window was resized)
  // Renders one frame at `time` into the framebuffer; the recorder holds its passes. Throws
  // UsageError, drawing nothing, where LessonInfo::refuseOptions refuses the variant and options as
  // they are now (the window's keys and the page's controls change them after the command line's
  // check).
  void renderFrame(double time, FrameRequest);

  const LessonInfo& info;
  const CommandLine& commandLine;
  std::unique_ptr<Context> context;
  std::unique_ptr<Framebuffer> framebuffer;
  std::unique_ptr<PassRecorder> recorder;
  std::unique_ptr<Lesson> lesson;
  std::string variant;
  std::vector<Option> options;
  OrbitCamera camera;
  std::optional<ShadowCheck> shadowCheck;  // the last frame's, when --oracle asks for it
  glm::mat4 viewProjection{1.0f};          // the last frame's
  glm::mat4 projection{1.0f};              // the last frame's Frame::projection (the depth view)
  bool saveShadowMasks = false;            // Frame::shadowMask stages under --mask-out (the last frame)
  // The process's CPU time per headless frame, every thread's (llvmpipe's too), milliseconds: a
  // benchmark's measure that other work on the machine hardly changes (--stats-frames).
  std::vector<double> frameCpuMs;
  OutputSet outputs;                       // the run's files, written as one when it ends (finishRun)
  WorkProgress progress;                   // Frame::progress of the frame being rendered
  Frame::ShadowMaskWriter shadowMaskHook;  // when set, Frame::shadowMask calls it instead (--shadow-hours)
  bool reversedDepth = false;              // the variant's reversed float depth, where the driver allows it
  std::optional<glm::vec2> pointer;        // Frame::pointer for the next frame (the window sets it)
  const Scene* scene = nullptr;            // --scene's (nullptr without one), for LessonInfo::refuseOptions
  float uiScale = 1.0f;                    // Frame::uiScale (the window sets it)
  // The lesson program the window asked to go to (the course's next or previous lesson): once this
  // session has closed its window, the program replaces this one (execv), in a window of its own.
  std::optional<std::filesystem::path> nextLesson;
  // The window flags it opens with (--size, --position, --ui-scale, --view, --panel): this window's.
  std::vector<std::string> nextLessonFlags;

 private:
  void checkNeeds(const std::vector<Feature>&, const std::string& who) const;
  void makeFramebuffer(int width, int height);
  DepthFormat depthFormat() const;  // the framebuffer's for reversedDepth
  void refuseChosenOptions();
  bool toldNoClipControl_ = false;
  // The variant and options refuseChosenOptions last let through: checked again only when changed.
  std::optional<std::pair<std::string, std::vector<Option>>> accepted_;
};

// The window's panel: a strip this many screen pixels wide at the window's left, beside the
// picture, never over it. A window run opens this much wider than --size, so the picture is the
// size asked for (with --frames, a test run, the panel starts hidden and the window is --size).
constexpr int kWindowPanelWidth = 300;
// The smallest picture a window opens with (--size); headless runs take any size.
constexpr int kMinWindowWidth = 160, kMinWindowHeight = 120;

// The course: the lesson programs beside this one (files named NN-name in the folder of
// /proc/self/exe), in order. Empty where the folder cannot be read.
std::vector<std::filesystem::path> courseLessons();

// The interactive loop (window_ui.cpp). Returns the exit code.
int runWindow(Session&);

// Writes what the command line asked for from the last frame (--out, --stencil-out,
// --passes, --stats, --oracle, --golden), with the shadow masks staged while rendering, as one
// OutputSet: all of them or none. A failed golden's artifacts follow as a set of their own.
// Returns the exit code.
int finishRun(Session&, const Image& colour, const Image& stencil, const std::vector<double>& frameMs);

}  // namespace stencil
