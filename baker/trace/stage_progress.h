// How a long bake reports where it is and learns that it should stop.
//
// A bake runs numbered stages (StagePlan names them up front, so "stage 4 of 8" is known from
// the start). Each stage counts its work items (rows of texels, light paths) in a StageProgress
// that worker threads advance; the observer hears of it a few times a second and once when the
// stage ends, and may answer false to cancel. Cancelling is cooperative: each stage checks
// between work items (a row of texels, a batch of paths), stops handing out work, and throws
// BakeCancelled, so nothing of the cancelled bake is written. GL-free.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace bounce {

struct BakeProgress {
  int stage = 0;   // 1-based
  int stages = 0;  // in the plan
  std::string name;
  uint64_t done = 0, total = 0;  // work items of this stage
  double seconds = 0.0;          // spent in this stage
  double etaSeconds = 0.0;       // left in this stage at its rate so far (0 once finished)
  double samplesPerSecond = 0.0;
  bool finished = false;
};

class BakeObserver {
 public:
  virtual ~BakeObserver() = default;
  // Called by one thread at a time (any of the bake's), at most every 100 ms per stage and once
  // when a stage finishes. Returns false to cancel the bake.
  virtual bool onProgress(const BakeProgress& progress) = 0;
};

struct BakeCancelled : std::runtime_error {
  BakeCancelled() : std::runtime_error("the bake was cancelled") {}
};

class StageProgress {
 public:
  // `observer` may be null (nothing reported, never cancelled).
  StageProgress(BakeObserver* observer, int stage, int stages, std::string name, uint64_t total);
  // Reports the stage finished, unless it was cancelled or is unwinding from an exception.
  ~StageProgress();
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  // Any thread: `items` more work items done, `samples` more samples taken (for the rate).
  void advance(uint64_t items, uint64_t samples = 0);
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // Throws BakeCancelled when the observer asked to stop.
  void throwIfCancelled() const;
  double elapsedSeconds() const;

 private:
  BakeProgress snapshot(bool finished) const;
  void report(bool finished);

  BakeObserver* observer_;
  int stage_, stages_;
  std::string name_;
  uint64_t total_;
  std::atomic<uint64_t> done_{0}, samples_{0};
  std::atomic<bool> cancelled_{false};
  std::chrono::steady_clock::time_point start_, lastReport_;
  std::mutex reporting_;
  int exceptionsAtStart_;
};

// The stages of one bake, in order; begin() numbers a stage by its place in the plan. The
// stage lasts as long as the returned object.
class StagePlan {
 public:
  StagePlan(BakeObserver* observer, std::vector<std::string> names)
      : observer_(observer), names_(std::move(names)) {}
  // Throws std::logic_error for a name not in the plan (a bug).
  std::unique_ptr<StageProgress> begin(const std::string& name, uint64_t total) const;
  bool has(const std::string& name) const;
  int size() const { return static_cast<int>(names_.size()); }

 private:
  BakeObserver* observer_;
  std::vector<std::string> names_;
};

}  // namespace bounce
