#include "trace/stage_progress.h"

#include <algorithm>
#include <exception>

namespace bounce {

StageProgress::StageProgress(BakeObserver* observer, int stage, int stages, std::string name,
                             uint64_t total)
    : observer_(observer),
      stage_(stage),
      stages_(stages),
      name_(std::move(name)),
      total_(total),
      start_(std::chrono::steady_clock::now()),
      lastReport_(start_),
      exceptionsAtStart_(std::uncaught_exceptions()) {
  report(false);
}

StageProgress::~StageProgress() {
  if (cancelled() || std::uncaught_exceptions() > exceptionsAtStart_) return;
  try {
    report(true);
  } catch (...) {  // an observer that throws at the end changes nothing: the stage is done
  }
}

double StageProgress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void StageProgress::throwIfCancelled() const {
  if (cancelled()) throw BakeCancelled();
}

BakeProgress StageProgress::snapshot(bool finished) const {
  BakeProgress p;
  p.stage = stage_;
  p.stages = stages_;
  p.name = name_;
  p.total = total_;
  p.done = finished ? total_ : std::min(done_.load(), total_);
  p.seconds = elapsedSeconds();
  p.samplesPerSecond = p.seconds > 0.0 ? static_cast<double>(samples_.load()) / p.seconds : 0.0;
  const double fraction =
      total_ > 0 ? static_cast<double>(p.done) / static_cast<double>(total_) : 1.0;
  p.etaSeconds = !finished && fraction > 0.0 ? p.seconds * (1.0 - fraction) / fraction : 0.0;
  p.finished = finished;
  return p;
}

void StageProgress::report(bool finished) {
  if (!observer_) return;
  std::unique_lock lock(reporting_, std::defer_lock);
  if (finished) {
    lock.lock();
  } else if (!lock.try_lock()) {
    return;  // another thread is reporting
  }
  if (!observer_->onProgress(snapshot(finished))) cancelled_ = true;
}

void StageProgress::advance(uint64_t items, uint64_t samples) {
  done_ += items;
  samples_ += samples;
  if (!observer_) return;
  const auto now = std::chrono::steady_clock::now();
  {
    std::unique_lock lock(reporting_, std::try_to_lock);
    if (!lock.owns_lock() || now - lastReport_ < std::chrono::milliseconds(100)) return;
    lastReport_ = now;
  }
  report(false);
}

std::unique_ptr<StageProgress> StagePlan::begin(const std::string& name, uint64_t total) const {
  const auto at = std::find(names_.begin(), names_.end(), name);
  if (at == names_.end()) throw std::logic_error("bake stage '" + name + "' is not in the plan");
  return std::make_unique<StageProgress>(observer_, static_cast<int>(at - names_.begin()) + 1,
                                         size(), name, total);
}

bool StagePlan::has(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

}  // namespace bounce
