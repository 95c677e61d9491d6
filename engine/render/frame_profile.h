// Where a frame's time goes, over many frames: each pass's GPU time (gl/gpu_pass_timers.h), the
// CPU time of building and submitting the frame (ForwardRenderer::render, without waiting for
// the GPU), the wait for the GPU and the readback, as mean and 95th percentile in milliseconds.
// GL-free: the renderer feeds it numbers; each series keeps its newest 4096 samples.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace bounce {

struct TimeSummary {
  std::string name;
  std::size_t frames = 0;  // samples
  double mean = 0.0;       // ms
  double p95 = 0.0;        // ms: the smallest sample at or above 95% of the samples
};

// The 95th percentile of `samples` (nearest rank: sorted[ceil(0.95·n) − 1]); 0 for none.
double percentile95(std::vector<double> samples);

class FrameProfile {
 public:
  // GPU times of one frame's passes (several spans of one name in a frame add up).
  void addGpuFrame(const std::vector<std::pair<std::string, double>>& passes);
  void addCpu(const std::string& what, double milliseconds);
  // Σ of the newest GPU frame's passes, ms (none before the first arrives).
  std::optional<double> lastGpuFrame() const { return lastGpuFrame_; }
  // Per pass in first-seen order: GPU time per frame (frames where the pass did not run count
  // as nothing, not as 0 ms).
  std::vector<TimeSummary> gpuPasses() const;
  // CPU spans in first-seen order ("frame", "gpu wait", "readback").
  std::vector<TimeSummary> cpu() const;
  void clear();

 private:
  static std::vector<TimeSummary> summarise(const std::vector<std::string>& order,
                                            const std::map<std::string, std::vector<double>>& s);
  std::vector<std::string> gpuOrder_, cpuOrder_;
  std::map<std::string, std::vector<double>> gpu_, cpu_;
  std::optional<double> lastGpuFrame_;
};

}  // namespace bounce
