// A live "done/total, rate, ETA" line on stderr, rewritten in place with '\r'. Safe to call
// from any thread; prints at most a few times per second.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace bounce {

class ProgressLine {
 public:
  // Progress is counted in items (e.g. tiles); the rate in samples (Msamples/s).
  ProgressLine(std::string label, uint64_t totalItems, bool enabled);
  ~ProgressLine();
  void advance(uint64_t items, uint64_t samples);
  double elapsedSeconds() const;

 private:
  void print(bool final);

  std::string label_;
  uint64_t total_;
  bool enabled_;
  std::atomic<uint64_t> done_{0};
  std::atomic<uint64_t> samples_{0};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastPrint_;
  std::mutex mutex_;
};

// True when stderr is a terminal (live progress is then worth drawing).
bool stderrIsTerminal();

}  // namespace bounce
