#include "background_bake.h"

#include <cstdio>

#include "pipeline/scene_bake.h"

namespace bounce {

SceneBakeSettings BackgroundBake::previewSettings(int threads) {
  SceneBakeSettings s;
  s.targetError = 0.3f;  // three times looser than the final bake's 10 %
  s.maxSpp = 256;
  s.vpls = s.vpls > 0 ? 1024 : 0;
  s.threads = threads;
  return s;
}

SceneBakeSettings BackgroundBake::finalSettings(int threads) {
  SceneBakeSettings s;  // bounce-bake's defaults
  s.threads = threads;
  return s;
}

BackgroundBake::BackgroundBake(Scene scene, std::filesystem::path folder, int threads)
    : scene_(std::move(scene)),
      folder_(std::move(folder)),
      threads_(threads),
      thread_([this] { run(); }) {}

BackgroundBake::~BackgroundBake() {
  cancel();
  thread_.join();
}

void BackgroundBake::cancel() {
  std::lock_guard lock(mutex_);
  cancel_ = true;
}

bool BackgroundBake::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

std::string BackgroundBake::status() const {
  std::lock_guard lock(mutex_);
  if (!running_) return stopped_.empty() ? "done" : stopped_;
  char line[200];
  const double percent = progress_.total > 0 ? 100.0 * static_cast<double>(progress_.done) /
                                                   static_cast<double>(progress_.total)
                                             : 0.0;
  std::snprintf(line, sizeof line, "%s: [%d/%d] %s %.0f%%, ETA %.0f s", pass_.c_str(),
                progress_.stage, progress_.stages, progress_.name.c_str(), percent,
                progress_.etaSeconds);
  return line;
}

double BackgroundBake::fraction() const {
  std::lock_guard lock(mutex_);
  if (progress_.stages == 0) return 0.0;
  const double within = progress_.total > 0 ? static_cast<double>(progress_.done) /
                                                  static_cast<double>(progress_.total)
                                            : 0.0;
  return (progress_.stage - 1 + within) / progress_.stages;
}

std::optional<BakePass> BackgroundBake::takeFinished() {
  std::lock_guard lock(mutex_);
  std::optional<BakePass> pass = std::move(finished_);
  finished_.reset();
  return pass;
}

bool BackgroundBake::hasFinished() const {
  std::lock_guard lock(mutex_);
  return finished_.has_value();
}

std::string BackgroundBake::stopped() const {
  std::lock_guard lock(mutex_);
  return stopped_;
}

bool BackgroundBake::onProgress(const BakeProgress& progress) {
  std::lock_guard lock(mutex_);
  progress_ = progress;
  return !cancel_;
}

void BackgroundBake::run() {
  const auto stop = [&](const std::string& why) {
    std::lock_guard lock(mutex_);
    stopped_ = why;
    running_ = false;
  };
  try {
    for (const bool preview : {true, false}) {
      {
        std::lock_guard lock(mutex_);
        pass_ = preview ? "preview" : "final";
      }
      SceneBake baked =
          bakeScene(scene_, preview ? previewSettings(threads_) : finalSettings(threads_), this);
      BakePass pass{preview ? "preview" : "final", std::move(baked.folder), {}};
      if (!preview && !folder_.empty()) {
        writeBake(folder_, pass.bake);
        pass.writtenTo = folder_;
      }
      std::lock_guard lock(mutex_);
      finished_ = std::move(pass);  // a preview not yet taken is simply replaced
    }
    stop("");
  } catch (const BakeCancelled&) {
    stop("cancelled");
  } catch (const std::exception& e) {
    stop(std::string("failed: ") + e.what());
  }
}

}  // namespace bounce
