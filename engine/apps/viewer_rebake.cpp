#include "viewer_rebake.h"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "background_bake.h"
#include "bake_folder/bake_facts.h"

namespace bounce {

ViewerRebake::ViewerRebake() = default;
ViewerRebake::~ViewerRebake() = default;

void ViewerRebake::start(const Scene& scene, const std::filesystem::path& sceneFile, bool edited) {
  if (bake_ && bake_->running()) return;
  bake_.reset();
  // The bake's threads leave the renderer a core.
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  std::filesystem::path folder;
  if (!edited) folder = std::filesystem::path(sceneFile).replace_extension(".bake");
  bake_ = std::make_unique<BackgroundBake>(scene, folder, std::max(cores - 1, 1));
  std::fprintf(stderr, "bounce-view: re-baking %s (preview first)\n",
               folder.empty() ? "in memory: the scene has edits the file has not"
                              : ("into " + folder.string()).c_str());
}

void ViewerRebake::cancel() {
  if (bake_) bake_->cancel();
}

bool ViewerRebake::running() const {
  return bake_ && bake_->running();
}

bool ViewerRebake::pending() {
  if (bake_ && (bake_->running() || bake_->hasFinished())) return true;
  if (bake_ && !bake_->stopped().empty())
    std::fprintf(stderr, "bounce-view: re-bake %s\n", bake_->stopped().c_str());
  return false;
}

std::string ViewerRebake::status() const {
  return bake_ ? bake_->status() : "";
}

double ViewerRebake::fraction() const {
  return bake_ ? bake_->fraction() : 0.0;
}

std::optional<RebakedPass> ViewerRebake::take() {
  if (!bake_) return std::nullopt;
  std::optional<BakePass> pass = bake_->takeFinished();
  if (!pass) return std::nullopt;
  RebakedPass taken{pass->name, std::move(pass->bake), pass->writtenTo, {}, {}};
  taken.factLines = bakeFactLines(bakeFacts(taken.bake, taken.writtenTo));
  const bool inMemory = taken.writtenTo.empty();
  if (inMemory)
    taken.factLines.front() =
        taken.name == "preview"
            ? "preview (in memory; the final bake follows)"
            : "final bake (in memory only: the scene has edits the file has not)";
  taken.note = "re-baked in the viewer: " + taken.name +
               (taken.name == "final" && inMemory ? " (in memory only)" : "");
  std::fprintf(stderr, "bounce-view: drawing the re-bake's %s%s%s\n", taken.name.c_str(),
               inMemory ? "" : ", written to ", taken.writtenTo.c_str());
  return taken;
}

}  // namespace bounce
