#include "render/frame_profile.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bounce {
namespace {

// The newest samples kept per series (a viewer runs for hours).
constexpr std::size_t kMaxSamples = 4096;

void push(std::vector<double>& samples, double value) {
  if (samples.size() == kMaxSamples) samples.erase(samples.begin());
  samples.push_back(value);
}

}  // namespace

double percentile95(std::vector<double> samples) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(samples.size())));
  return samples[std::max<std::size_t>(rank, 1) - 1];
}

void FrameProfile::addGpuFrame(const std::vector<std::pair<std::string, double>>& passes) {
  std::map<std::string, double> frame;
  for (const auto& [name, ms] : passes) {
    if (!gpu_.contains(name) && !frame.contains(name)) gpuOrder_.push_back(name);
    frame[name] += ms;
  }
  double total = 0.0;
  for (const auto& [name, ms] : frame) {
    push(gpu_[name], ms);
    total += ms;
  }
  lastGpuFrame_ = total;
}

void FrameProfile::addCpu(const std::string& what, double milliseconds) {
  if (!cpu_.contains(what)) cpuOrder_.push_back(what);
  push(cpu_[what], milliseconds);
}

std::vector<TimeSummary> FrameProfile::summarise(
    const std::vector<std::string>& order, const std::map<std::string, std::vector<double>>& s) {
  std::vector<TimeSummary> rows;
  for (const std::string& name : order) {
    const std::vector<double>& samples = s.at(name);
    TimeSummary row;
    row.name = name;
    row.frames = samples.size();
    row.mean = std::accumulate(samples.begin(), samples.end(), 0.0) /
               static_cast<double>(std::max<std::size_t>(samples.size(), 1));
    row.p95 = percentile95(samples);
    rows.push_back(row);
  }
  return rows;
}

std::vector<TimeSummary> FrameProfile::gpuPasses() const {
  return summarise(gpuOrder_, gpu_);
}

std::vector<TimeSummary> FrameProfile::cpu() const {
  return summarise(cpuOrder_, cpu_);
}

void FrameProfile::clear() {
  *this = FrameProfile{};
}

}  // namespace bounce
