// GPU time of the commands between begin() and end(), from GL_TIME_ELAPSED queries (core since
// GL 3.3). Results are read a few frames late, only once the driver has them, so timing never
// stalls the pipeline; lastMilliseconds() is the most recent finished span.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

namespace bounce::gl {

class GpuTimer {
 public:
  GpuTimer();
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin();
  void end();
  std::optional<double> lastMilliseconds() const { return last_; }

 private:
  static constexpr int kInFlight = 4;  // spans queued before the oldest must be read
  std::array<uint32_t, kInFlight> queries_{};
  std::array<bool, kInFlight> pending_{};
  int next_ = 0;
  std::optional<double> last_;
};

}  // namespace bounce::gl
