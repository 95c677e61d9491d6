// bounce-view's re-bake: the scene bake (pipeline/scene_bake.h) on a thread of its own, in two
// passes: a quick preview (a loose error target, few samples and VPLs) and then the bake with
// bounce-bake's defaults, which is also written to the scene's bake folder (<scene>.bake, as
// bounce-bake SCENE would). The viewer polls it once a frame: the latest progress for the panel,
// and each finished pass to draw with. cancel() stops the running pass within a row of texels;
// a cancelled bake writes nothing and the viewer keeps what it had.
#pragma once

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "bake_folder/bake_folder.h"
#include "pipeline/scene_bake_settings.h"
#include "scene/scene.h"
#include "trace/stage_progress.h"

namespace bounce {

struct BakePass {
  std::string name;  // "preview" or "final"
  Bake bake;
  std::filesystem::path writtenTo;  // the folder the final pass was written to; empty: none
};

class BackgroundBake final : private BakeObserver {
 public:
  // Starts at once. `threads`: the bake's worker threads (leave the renderer a core). An empty
  // `folder`: the final bake is kept in memory only.
  BackgroundBake(Scene scene, std::filesystem::path folder, int threads);
  ~BackgroundBake();  // cancels and waits
  BackgroundBake(const BackgroundBake&) = delete;
  BackgroundBake& operator=(const BackgroundBake&) = delete;

  void cancel();
  bool running() const;
  // The latest report, prefixed with its pass ("preview: [5/8] irradiance 41%, ETA 3 s").
  std::string status() const;
  double fraction() const;  // of the running pass's stages, 0..1
  // A pass that finished since the last call.
  std::optional<BakePass> takeFinished();
  bool hasFinished() const;  // one is waiting to be taken
  // Why the bake stopped early: "cancelled", or the error; empty otherwise.
  std::string stopped() const;

  static SceneBakeSettings previewSettings(int threads);
  static SceneBakeSettings finalSettings(int threads);

 private:
  bool onProgress(const BakeProgress& progress) override;
  void run();

  Scene scene_;
  std::filesystem::path folder_;
  int threads_;
  mutable std::mutex mutex_;
  std::string pass_;
  BakeProgress progress_;
  std::optional<BakePass> finished_;
  std::string stopped_;
  bool running_ = true;
  bool cancel_ = false;
  std::thread thread_;  // last: starts once everything above is built
};

}  // namespace bounce
