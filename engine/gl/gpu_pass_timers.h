// GPU time of each pass of a frame, from GL timestamp queries (glQueryCounter(GL_TIMESTAMP), core
// since GL 3.3: ARB_timer_query) at the pass's start and end, read without stalling: a frame's
// queries stay in flight in a ring of kFramesInFlight frames and are read at the start of a later
// frame once the driver says they are available (on any real driver the frame before last is);
// only when the ring is full is the oldest frame waited for. Timestamps rather than
// GL_TIME_ELAPSED: spans may nest, and llvmpipe (Mesa 22.3) reports a GL_TIME_ELAPSED span that
// crosses one of its scene flushes (a shadow map rendered, then sampled) from a start of 0, i.e.
// the machine's uptime (driver_quirks.h). Times are milliseconds.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

namespace bounce::gl {

// One finished frame: each pass's GPU time, ms, in the order the passes ran (a pass timed twice
// in a frame appears twice).
struct GpuFrameTimes {
  struct Pass {
    const char* name;  // a string literal (the caller's pass name)
    double milliseconds;
  };
  std::vector<Pass> passes;
};

class GpuPassTimers {
 public:
  static constexpr std::size_t kFramesInFlight = 3;

  GpuPassTimers() = default;
  ~GpuPassTimers();
  GpuPassTimers(const GpuPassTimers&) = delete;
  GpuPassTimers& operator=(const GpuPassTimers&) = delete;

  // Starts a frame: collects the frames in flight whose queries are all available (waiting only
  // for the oldest when kFramesInFlight are in flight).
  void beginFrame();
  // Times the GPU commands until end() as pass `name` (a string literal) of the current frame.
  void begin(const char* name);
  void end();
  // Waits for every frame in flight and collects it (after a benchmark's last frame).
  void finish();
  // Frames collected since the last call, oldest first.
  std::vector<GpuFrameTimes> takeFinished();

  // Times one pass for the life of the scope; a null `timers` times nothing.
  class Scope {
   public:
    Scope(GpuPassTimers* timers, const char* name) : timers_(timers) {
      if (timers_) timers_->begin(name);
    }
    ~Scope() {
      if (timers_) timers_->end();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    GpuPassTimers* timers_;
  };

 private:
  struct Query {
    const char* name;
    uint32_t start, end;  // timestamp queries
  };
  using Frame = std::vector<Query>;
  // Reads the oldest frame in flight (waiting when `wait`); false when not yet available.
  bool collectOldest(bool wait);
  uint32_t newQuery();

  std::deque<Frame> inFlight_;   // oldest first; the back is the current frame
  std::vector<uint32_t> spare_;  // query objects whose results were read
  std::vector<GpuFrameTimes> finished_;
  std::vector<std::size_t> open_;  // passes of the current frame begun and not ended
};

}  // namespace bounce::gl
