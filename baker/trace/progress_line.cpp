#include "trace/progress_line.h"

#include <cstdio>

#include <unistd.h>

namespace bounce {

bool stderrIsTerminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressLine::ProgressLine(std::string label, uint64_t totalItems, bool enabled)
    : label_(std::move(label)),
      total_(totalItems),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_) {}

ProgressLine::~ProgressLine() {
  if (enabled_) {
    print(true);
    std::fputc('\n', stderr);
  }
}

double ProgressLine::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressLine::advance(uint64_t items, uint64_t samples) {
  done_ += items;
  samples_ += samples;
  if (!enabled_) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastPrint_ < std::chrono::milliseconds(250)) return;
  lastPrint_ = now;
  print(false);
}

void ProgressLine::print(bool final) {
  const double seconds = elapsedSeconds();
  const uint64_t done = done_.load();
  const double fraction =
      total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const double rate = seconds > 0.0 ? static_cast<double>(samples_.load()) / seconds * 1e-6 : 0.0;
  const double eta = fraction > 0.0 ? seconds * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s %5.1f%%  %.2f Msamples/s  %s %.0f s   ", label_.c_str(),
               100.0 * fraction, rate, final ? "elapsed" : "ETA", final ? seconds : eta);
  std::fflush(stderr);
}

}  // namespace bounce
