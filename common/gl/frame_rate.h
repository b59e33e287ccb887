// The window's frame rate: how many frames ended in the last second and how long they took.
#pragma once
#include <cstddef>
#include <deque>

namespace stencil {

// Feed it the time (seconds, any monotonic clock) at which each frame ends. It keeps the frames
// that ended in the last kSpan seconds, and the one before them, so that at any rate it reports
// whole frame intervals: fps() = intervals / their total time, msPerFrame() = 1000 / fps(). At a
// rate below 1/kSpan it reports the last interval alone. Before two frames have ended both are 0.
// No smoothing over time: the figure is right one second after the rate changes.
class FrameRate {
 public:
  static constexpr double kSpan = 1.0;

  void frameEnded(double now) {
    ends_.push_back(now);
    ++frames_;
    // Keep one end at or before now - kSpan: the start of the first interval inside the span.
    while (ends_.size() > 2 && ends_[1] <= now - kSpan) ends_.pop_front();
  }
  // Frame intervals that ended in the last kSpan seconds (at least 1 once two frames have ended).
  std::size_t intervals() const {
    return ends_.size() < 2 ? 0 : ends_.size() - 1;
  }
  double fps() const {
    if (ends_.size() < 2) return 0.0;
    const double span = ends_.back() - ends_.front();
    return span > 0.0 ? static_cast<double>(ends_.size() - 1) / span : 0.0;
  }
  double msPerFrame() const {
    const double f = fps();
    return f > 0.0 ? 1000.0 / f : 0.0;
  }
  // Every frame fed so far.
  long long frames() const {
    return frames_;
  }

 private:
  std::deque<double> ends_;
  long long frames_ = 0;
};

}  // namespace stencil
