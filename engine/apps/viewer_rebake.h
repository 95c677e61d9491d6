// bounce-view's re-bake (the panel's button, the script's rebake): one BackgroundBake
// (background_bake.h) at a time, written to the scene's bake folder <scene>.bake, or kept in
// memory when the scene has edits its file has not (a light changed in the panel or a script:
// the folder would not match the file). Each finished pass comes with the panel's lines for it.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bake_folder/bake_folder.h"
#include "scene/scene.h"

namespace bounce {

class BackgroundBake;

struct RebakedPass {
  std::string name;  // "preview" or "final"
  Bake bake;
  std::filesystem::path writtenTo;     // empty: in memory only
  std::vector<std::string> factLines;  // bake_folder/bake_facts.h's, for the panel
  std::string note;                    // where the baked light came from
};

class ViewerRebake {
 public:
  ViewerRebake();
  ~ViewerRebake();  // cancels a running bake and waits for it

  // Starts a re-bake of `scene` unless one runs; `edited`: the scene differs from `sceneFile`.
  void start(const Scene& scene, const std::filesystem::path& sceneFile, bool edited);
  void cancel();
  bool running() const;
  // A bake runs or a finished pass waits to be taken; when neither, says on stderr why the
  // last one stopped early, if it did.
  bool pending();
  std::string status() const;         // its progress, or how it ended; empty: none started
  double fraction() const;            // of the running pass, 0..1
  std::optional<RebakedPass> take();  // a pass that finished since the last call

 private:
  std::unique_ptr<BackgroundBake> bake_;
};

}  // namespace bounce
